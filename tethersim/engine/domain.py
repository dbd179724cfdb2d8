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

:func:`first_violation` scans the output samples (the integrators' dense output,
or every RK4 step) and returns the first one outside, with the reason;
``simulate`` truncates the run there.  The re-entry time and the time the roll
passes its limit are interpolated linearly between the last sample inside and
the first outside.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tethersim.engine.evaluate import domain_scan
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
# The samples (>= 200 per orbit) are checked, and so is every interval between two of
# them that a fast roll could have crossed into the band unseen (_roll_violation).
# The same limit bounds the start (Satellite.initial_3d).
ROLL_LIMIT = np.radians(ROLL_LIMIT_DEG)
ROLL_PATH_MARGIN = 2.0  # × the sampled change of the boom's turn rate (_roll_violation)


@dataclass(frozen=True)
class Violation:
    """The first sample outside the domain.

    Attributes
    ----------
    index : int
        First sample outside (the run keeps the samples before it and this one).
    time : float
        When it left [s]; for a re-entry, interpolated to the threshold crossing.
    status : str
        ``"re-entered"`` or ``"left-domain"``.
    message : str
        One line saying what left the domain, with the limit.
    """

    index: int
    time: float
    status: str
    message: str


def reach(sat) -> float:
    """Largest balloon distance from the COM inside the domain [m]."""
    return BALLOON_REACH * max(sat.l10 + sat.b, sat.l20 + sat.a)


def first_violation(res, altitude=None) -> Violation | None:
    """The first sample of ``res`` outside the model's domain, or None.

    Parameters
    ----------
    res : SimResult
        A run (its samples are checked, not the steps between them).
    altitude : numpy.ndarray, optional
        The reference point's altitude per sample [m] (default ``res.altitude``).

    Returns
    -------
    Violation or None
    """
    sat, lay = res.satellite, res.layout
    n = res.t.size
    if n == 0:
        return None
    names = lay.state
    # one compiled pass: the first non-finite sample, balloon too far, tether over-stretched
    last, i_far, d_far, i_over, j_over, s_over = domain_scan(
        lay.index, np.ascontiguousarray(res.states), res.parameters,
        names.index("delta_x"), names.index("delta_y"),
        names.index("delta_z") if "delta_z" in names else -1, sat.l10, sat.l20, sat.a, sat.b,
        reach(sat) ** 2, MAX_STRETCH)
    candidates = []
    reentry = reentry_violation(res, last, altitude)
    if reentry is not None:
        candidates.append(reentry)
    if i_far >= 0:
        i = i_far
        candidates.append(Violation(i, float(res.t[i]), "left-domain",
                                    f"left the model's domain: balloon {np.sqrt(d_far):.4g} m "
                                    f"from the COM at t = {res.t[i]:.6g} s (allowed <= "
                                    f"{reach(sat):.4g} m, {BALLOON_REACH:g} x the longest "
                                    f"tether path)"))
    if "phi" in names:
        candidates += _roll_violation(res, last)
    if i_over >= 0:
        i = i_over
        candidates.append(Violation(i, float(res.t[i]), "left-domain",
                                    f"left the model's domain: tether {j_over + 1} stretched to "
                                    f"{s_over:.3g} x its rest length at t = "
                                    f"{res.t[i]:.6g} s (allowed <= {MAX_STRETCH:g} x)"))
    return min(candidates, key=lambda v: v.index) if candidates else None


def reentry_violation(res, last: int | None = None, altitude=None) -> Violation | None:
    """The first sample of ``res`` below the re-entry altitude, or None.

    Parameters
    ----------
    res : SimResult
        A run; a circular orbit is held at its altitude (checked at load time), so
        only a free orbit's (or a given ``altitude``) can fall below.
    last : int, optional
        Samples to look at (default all).
    altitude : numpy.ndarray, optional
        The reference point's altitude per sample [m] (default ``res.altitude``).

    Returns
    -------
    Violation or None
        Status ``"re-entered"``, the time interpolated linearly to the crossing.
    """
    if res.layout.orbit != "free" and altitude is None:
        return None
    h_min = getattr(res.satellite, "reentry_altitude", REENTRY_ALTITUDE)
    h = res.altitude if altitude is None else altitude
    below = np.nonzero(h[:last] < h_min)[0]
    if not below.size:
        return None
    i = int(below[0])
    t = float(res.t[i])
    if i > 0:  # linear interpolation to the crossing
        h0, h1 = h[i - 1], h[i]
        t = float(res.t[i - 1] + (res.t[i] - res.t[i - 1]) * (h0 - h_min) / (h0 - h1))
    return Violation(i, t, "re-entered", f"re-entered: altitude {h[i] / 1e3:.1f} km fell below "
                                         f"{h_min / 1e3:g} km at t = {t:.6g} s ({t / 3600:.3g} h)")


def _roll_violation(res, last: int) -> list:
    """[Violation] where |φ| passes ROLL_LIMIT (3-D models), or [].

    Two tests, the first that fires wins: a sample with |φ| > ROLL_LIMIT (the
    crossing time interpolated linearly), or an interval between two samples
    during which the boom could have come within 90° − ROLL_LIMIT of the orbit
    normal ±z unseen (a fast roll: a sample near 90° would otherwise be missed and
    the run continue in the badly conditioned angles).  The boom ê = (cos φ sin θ,
    cos φ cos θ, sin φ) turns at |ê̇| = √(φ̇² + cos²φ θ̇²); over an interval Δt it
    travels about Δt (max|ê̇| + a Δt / 2), the faster end's rate plus what the
    rate can gain inside, a the rate's change per second estimated from this and
    the neighbouring intervals (at least the gravity-gradient 3n²) times
    ``ROLL_PATH_MARGIN``.  Within the band it would have been no farther than
    90° − ROLL_LIMIT from a pole, so it cannot have entered the band when the two
    samples' distances from that pole add up to more than the path plus twice the
    band.  An estimate from the samples, not a bound: a run that grazes the band
    for less than a sample may still pass.
    """
    n = min(last, res.t.size)
    if n == 0:
        return []
    phi = res.series("phi")[:n]
    band = np.pi / 2 - ROLL_LIMIT
    out = []
    beyond = np.nonzero(np.abs(phi) > ROLL_LIMIT)[0]
    if beyond.size:
        i = int(beyond[0])
        t = float(res.t[i])
        if i > 0:  # linear interpolation to the crossing
            p0, p1 = abs(phi[i - 1]), abs(phi[i])
            t = float(res.t[i - 1] + (res.t[i] - res.t[i - 1]) * (ROLL_LIMIT - p0) / (p1 - p0))
        out.append(Violation(i, t, "left-domain",
                             f"left the model's domain: roll |phi| = {np.degrees(abs(phi[i])):.1f} "
                             f"deg at t = {res.t[i]:.6g} s, beyond {ROLL_LIMIT_DEG:g} deg at "
                             f"t = {t:.6g} s (allowed |phi| <= {ROLL_LIMIT_DEG:g} deg: the "
                             f"roll-pitch-yaw angles are singular at 90 deg)"))
    if n > 1:
        speed = np.hypot(res.series("phi_dot")[:n], np.cos(phi) * res.series("theta_dot")[:n])
        dt = np.diff(res.t[:n])
        w = res.satellite.omega
        # the turn rate's change per second, each interval's and its neighbours' (or the
        # gravity-gradient 3n² where larger), as the acceleration within the interval
        with np.errstate(divide="ignore", invalid="ignore"):  # a repeated time: no interval
            rate = np.where(dt > 0, np.abs(np.diff(speed)) / dt, 0.0)
        acc = np.maximum(rate, 3 * w * w)
        acc = np.maximum(acc, np.maximum(np.append(acc[1:], 0.0), np.insert(acc[:-1], 0, 0.0)))
        path = dt * (np.maximum(speed[:-1], speed[1:]) + ROLL_PATH_MARGIN * acc * dt / 2)
        reach_pole = np.minimum(np.pi - phi[:-1] - phi[1:], np.pi + phi[:-1] + phi[1:])
        unseen = np.nonzero(reach_pole <= path + 2 * band)[0]
        if unseen.size:
            i = int(unseen[0])
            out.append(Violation(i + 1, float(res.t[i]), "left-domain",
                                 f"left the model's domain: roll may have passed "
                                 f"{ROLL_LIMIT_DEG:g} deg between t = {res.t[i]:.6g} s and "
                                 f"{res.t[i + 1]:.6g} s (the boom turns at up to "
                                 f"{np.degrees(max(speed[i], speed[i + 1])):.3g} deg/s; allowed "
                                 f"|phi| <= {ROLL_LIMIT_DEG:g} deg: the roll-pitch-yaw angles "
                                 f"are singular at 90 deg)"))
    return out


def below_reentry(sat, model: str, state) -> bool:
    """Whether the boom's COM at ``state`` (a free-orbit model's integrated state) is
    below the re-entry altitude: the loop's cue to stop and let simulate() truncate."""
    from tethersim.model.constants import R_EARTH
    from tethersim.model.registry import get_model
    lay = get_model(model)
    if "r" not in lay.state:
        return False
    return bool(state[lay.state.index("r")] - R_EARTH
                < getattr(sat, "reentry_altitude", REENTRY_ALTITUDE))
