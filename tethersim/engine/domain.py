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
                 far is no longer tethered in any physical sense;
``diverged``     a non-finite state (the integrators report it themselves).

:func:`first_violation` scans the output samples (the integrators' dense output,
or every RK4 step) and returns the first one outside, with the reason;
``simulate`` truncates the run there.  The re-entry time is interpolated
linearly between the last sample above and the first below the threshold.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tethersim.engine.evaluate import tether_margin_series
from tethersim.engine.integrators.select import call

REENTRY_ALTITUDE = 120e3  # m: default re-entry threshold (issue 12; Vallado's table holds to 0)
# λ / l0: the thesis's own presets trail the balloon ~28 m on 6 m tethers (λ/l0 ≈ 5,
# moduli ~0.01 N/mm² on 1 mm²: rubber-like tethers); twenty times the rest length is
# beyond any elastic tether, and a run there has lost the balloon
MAX_STRETCH = 20.0
BALLOON_REACH = 10.0  # × max(l10 + b, l20 + a): as the plausibility limit on the start


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
    finite = np.all(np.isfinite(res.states), axis=1)
    last = int(np.argmin(finite)) if not finite.all() else n  # before the first NaN sample
    candidates = []
    h_min = getattr(sat, "reentry_altitude", REENTRY_ALTITUDE)
    # a circular orbit is held at its altitude (checked at load time): only a free orbit falls
    if lay.orbit == "free" or altitude is not None:
        h = res.altitude if altitude is None else altitude
        below = np.nonzero(h[:last] < h_min)[0]
    else:
        below = np.array([], dtype=int)
    if below.size:
        i = int(below[0])
        t = float(res.t[i])
        if i > 0:  # linear interpolation to the crossing
            h0, h1 = h[i - 1], h[i]
            t = float(res.t[i - 1] + (res.t[i] - res.t[i - 1]) * (h0 - h_min) / (h0 - h1))
        candidates.append(Violation(i, t, "re-entered",
                                    f"re-entered: altitude {h[i] / 1e3:.1f} km fell below "
                                    f"{h_min / 1e3:g} km at t = {t:.6g} s ({t / 3600:.3g} h)"))
    names = lay.state
    dist2 = res.x[:last] ** 2 + res.y[:last] ** 2
    if "delta_z" in names:
        dist2 = dist2 + res.series("delta_z")[:last] ** 2
    far = np.nonzero(dist2 > reach(sat) ** 2)[0]
    if far.size:
        i = int(far[0])
        candidates.append(Violation(i, float(res.t[i]), "left-domain",
                                    f"left the model's domain: balloon {np.sqrt(dist2[i]):.4g} m "
                                    f"from the COM at t = {res.t[i]:.6g} s (allowed <= "
                                    f"{reach(sat):.4g} m, {BALLOON_REACH:g} x the longest "
                                    f"tether path)"))
    if last:
        g = call(tether_margin_series, lay.index, np.ascontiguousarray(res.states[:last]),
                 res.parameters)
        strain = np.column_stack([g[:, 0] / sat.l10, g[:, 1] / sat.l20]) + 1.0
        over = np.nonzero(np.any(strain > MAX_STRETCH, axis=1))[0]
        if over.size:
            i = int(over[0])
            j = int(np.argmax(strain[i]))
            candidates.append(Violation(i, float(res.t[i]), "left-domain",
                                        f"left the model's domain: tether {j + 1} stretched to "
                                        f"{strain[i, j]:.3g} x its rest length at t = "
                                        f"{res.t[i]:.6g} s (allowed <= {MAX_STRETCH:g} x)"))
    return min(candidates, key=lambda v: v.index) if candidates else None


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
