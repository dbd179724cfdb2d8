"""Where the model means something, and the first sample of a run outside it.

A run that leaves the model's domain ends with a status that says so, never
"ok" (docs/limits.md):

``re-entered``   the boom's COM fell below the re-entry altitude (default 120 km,
                 ``Satellite.reentry_altitude``) on a free orbit: below it the thin-air
                 drag law and the rigid-tether model no longer hold, and the satellite
                 is lost (a circular orbit is held at its altitude, checked at load);
``left-domain``  the balloon farther from the COM than ``BALLOON_REACH`` times the
                 longest tether path (end body + tether), or a tether stretched
                 beyond ``MAX_STRETCH`` times its rest length (the thesis presets
                 sit near 5x): no elastic tether survives that, and a balloon that
                 far is no longer tethered in any physical sense; or, in a 3-D
                 model, the roll |φ| beyond ``ROLL_LIMIT`` (80°): the roll-pitch-yaw
                 angles are singular at 90° (docs/three-d.md);
``diverged``     a non-finite state (the integrators report it themselves).

Each limit is a stopping event of engine/events.py, located by the integrators
inside the compiled loop (every step, RK4 and adaptive alike) to the accuracy of
a taut/slack switch; the run ends just past the crossing, its last sample the
located state at the located time.  This module holds the limits and words them:
:func:`event_message` for a run, :func:`state_violation` for a single state.
"""
from __future__ import annotations

import numpy as np

from tethersim.model.satellite import ROLL_LIMIT_DEG

REENTRY_ALTITUDE = 120e3  # m: default re-entry threshold (issue 12; Vallado's table holds to 0)
# λ / l0: the thesis's own presets trail the balloon ~28 m on 6 m tethers (λ/l0 ≈ 5,
# moduli ~0.01 N/mm² on 1 mm²: rubber-like tethers); twenty times the rest length is
# beyond any elastic tether, and a run there has lost the balloon
MAX_STRETCH = 20.0
BALLOON_REACH = 10.0  # × max(l10 + b, l20 + a): as the plausibility limit on the start
# |roll| of the 3-D models (body 3-1-2 angles: pitch θ, roll φ, yaw ψ; docs/three-d.md).
# The kinematic matrix that turns the angle rates into the body rates loses rank at
# cos φ = 0: its 2-norm condition number is (1 + sin|φ|)/cos φ = tan(45° + |φ|/2), and
# the mass matrix's determinant falls as cos²φ, so θ̇, ψ̇ and the accelerations grow as
# 1/cos φ and the integrator's steps shrink as cos φ.  At 80° the condition number is
# 11.4 (a digit of the error tolerance), at 85° 22.9, at 89° 115 and unbounded at 90°.
# A boom rolled 80° lies within 10° of the orbit normal: it has left the gravity-gradient
# attitude the model is for, so stopping there loses no behaviour anyone asks about.
# The limit is an event located at every step (engine/events.py), so a fast roll
# cannot cross it unseen between samples.  The same limit bounds the start
# (Satellite.initial_3d).
ROLL_LIMIT = np.radians(ROLL_LIMIT_DEG)


def reach(sat) -> float:
    """Largest balloon distance from the COM inside the domain [m]."""
    return BALLOON_REACH * max(sat.l10 + sat.b, sat.l20 + sat.a)


def _limit_phrase(sat, name: str) -> str:
    """What the stopping event ``name`` (engine/events.py EVENTS) allows, in words."""
    if name == "balloon reach":
        return (f"allowed <= {reach(sat):.4g} m, {BALLOON_REACH:g} x the longest tether "
                f"path")
    if name == "roll":
        return (f"allowed |phi| <= {ROLL_LIMIT_DEG:g} deg: the roll-pitch-yaw angles are "
                f"singular at 90 deg")
    return f"allowed <= {MAX_STRETCH:g} x"  # a tether stretch


def event_message(sat, name: str, t: float) -> str:
    """One line saying which stopping limit a run reached, and when.

    Parameters
    ----------
    sat : Satellite
        The satellite run.
    name : str
        The stopping event (a terminal name of engine/events.py's EVENTS).
    t : float
        The located time of the event [s].

    Returns
    -------
    str
        E.g. "re-entered: the boom's COM fell below 120 km at t = ... s (... h)".
    """
    if name == "re-entry":
        return (f"re-entered: the boom's COM fell below {sat.reentry_altitude / 1e3:g} km "
                f"at t = {t:.6g} s ({t / 3600:.3g} h)")
    if name in ("tether 1 break", "tether 2 break"):
        j = name[7]
        return (f"tether {j} broke: its tension reached the breaking load Fb{j} = "
                f"{getattr(sat, 'Fb' + j):.4g} N at t = {t:.6g} s ({t / 3600:.3g} h)")
    what = {"roll": f"roll |phi| passed {ROLL_LIMIT_DEG:g} deg",
            "balloon reach": f"balloon passed {reach(sat):.4g} m from the COM",
            "tether 1 stretch": f"tether 1 stretched past {MAX_STRETCH:g} x its rest length",
            "tether 2 stretch": f"tether 2 stretched past {MAX_STRETCH:g} x its rest "
                                f"length"}[name]
    return f"left the model's domain: {what} at t = {t:.6g} s ({_limit_phrase(sat, name)})"


def state_violation(sat, model: str, y) -> str:
    """Why one state of ``model`` lies outside the model's domain, or "" if inside.

    The stopping limits a run is held to (balloon reach, tether stretch, the 3-D
    roll; not the re-entry: a circular orbit's state has no altitude), evaluated
    by the same compiled event function (engine/events.py), for a state no run
    produced, e.g. an equilibrium.

    Parameters
    ----------
    sat : Satellite
        The satellite.
    model : str
        Model name (tethersim.model.registry).
    y : array_like
        The model's state (coordinates then rates).

    Returns
    -------
    str
        One line naming the limit passed (empty: inside the domain).
    """
    from tethersim.engine.events import EVENTS, SLOT, event_parameters, events_at
    from tethersim.model.inputs import parameter_vector
    from tethersim.model.registry import get_model

    lay = get_model(model)
    names = lay.state
    y = np.asarray(y, dtype=float)
    stops = [e.name for e in EVENTS if e.terminal and e.name != "re-entry"]
    p = parameter_vector(sat, model)
    g = events_at(lay.index, y, p, event_parameters(sat, model, stops))
    for j in (SLOT["tether 1 stretch"], SLOT["tether 2 stretch"]):
        if not g[j] > 0.0:
            k = j - SLOT["tether 1 stretch"]
            l0 = (sat.l10, sat.l20)[k]
            return (f"tether {k + 1} stretched to {(g[k] + l0) / l0:.3g} x its rest length "
                    f"({_limit_phrase(sat, EVENTS[j].name)})")
    if not g[SLOT["balloon reach"]] > 0.0:
        d = np.sqrt(reach(sat) ** 2 - g[SLOT["balloon reach"]])
        return f"balloon {d:.4g} m from the COM ({_limit_phrase(sat, 'balloon reach')})"
    if not g[SLOT["roll"]] > 0.0:
        return (f"roll |phi| = {np.degrees(abs(y[names.index('phi')])):.1f} deg (allowed "
                f"<= {ROLL_LIMIT_DEG:g} deg)")
    return ""
