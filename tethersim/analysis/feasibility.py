"""The verdict of one feasibility point: does the thesis's design work in a real orbit?

A point (an altitude, a balloon area) has three kinds of runs
(tethersim.experiments.feasibility):

* a **free** orbit from that altitude: its *usable life* ends when the balloon is
  lost (the tether passes its stretch limit, engine/domain.py) or the satellite
  re-enters, whichever comes first (capped);
* a **nominal** circular run (the thesis: orbit held, Vallado's air): its outcome
  gives the settling time;
* **trim** runs: circular, the density scaled to NRLMSISE-00's solar minimum, mean
  and maximum at that altitude.

:func:`verdict` turns them into one of :data:`VERDICTS`, in this priority:

1. ``unstable`` -- the nominal run failed, tumbled or ended upside down;
2. ``balloon lost before settling`` / ``re-enters before settling`` -- the usable
   life ended before the nominal settling time (or the run could have seen a
   settling before it ended and saw none);
3. ``trim lost as the air varies`` -- a trim run (or the nominal one) failed,
   tumbled, settled with |θ_ss| > ``tol`` (thesis ±0.05 rad, p. 5-18) or did not
   settle within the usable life;
4. ``feasible`` -- none of these;
5. ``undecided: run longer`` -- the answer turns on a settling the run was too short
   to see.  The settling criterion (docs/metrics.md) looks at the last
   ``SS_FRACTION`` of a run, so a run of T sees a settling only up to
   (1 − SS_FRACTION) T: deciding "did not settle in time" needs
   (1 − SS_FRACTION) T ≥ the usable life, :func:`periods_to_decide`; a run shorter
   than :func:`tethersim.analysis.metrics.min_run_orbits` has no class yet
   (``undecided``, tethersim.analysis.classify) and decides nothing but a tumble;
6. ``undecided: raise the lifetime cap`` -- the free orbit outlived the cap
   (``max_lifetime_h``), so its life is not known, and the answer turns on it:
   the runs did not settle (or a trim did not) within the cap.  A capped life is
   never used as if the life ended there.

A point is decided at two integrator tolerances (experiments/feasibility.py); a
verdict that differs between them is reported as :data:`SENSITIVE`
(:func:`combine`), not as a fact.
"""
from __future__ import annotations

import math

from tethersim.analysis.classify import FAILED, TUMBLING, UPSIDE_DOWN
from tethersim.analysis.classify import UNDECIDED as UNDECIDED_CLASS
from tethersim.analysis.metrics import SETTLING_TOL, SS_FRACTION, min_run_orbits
from tethersim.analysis.outcome import Outcome

VERDICTS = ("feasible", "balloon lost before settling", "re-enters before settling",
            "trim lost as the air varies", "unstable", "undecided: run longer", "sensitive",
            "undecided: raise the lifetime cap")
FEASIBLE, LOST, REENTERS, TRIM_LOST, UNSTABLE, UNDECIDED, SENSITIVE, CAPPED = VERDICTS
VERDICT_COLORS = {FEASIBLE: "#2e7d32", LOST: "#ef6c00", REENTERS: "#c62828",
                  TRIM_LOST: "#fbc02d", UNSTABLE: "#6a1b9a", UNDECIDED: "#ffffff",
                  SENSITIVE: "#9e9e9e", CAPPED: "#e0e0e0"}
_LOST = (FAILED, TUMBLING, UPSIDE_DOWN)


def settling_time(out: Outcome) -> float:
    """Settling time [s] of a run's outcome; NaN if it did not settle or has no metrics."""
    return out.metrics.settling_time if out.metrics is not None else math.nan


def trim_held(out: Outcome, tol: float = SETTLING_TOL) -> bool:
    """True when a run counts, did not tumble or turn over, and |θ_ss| <= ``tol``."""
    if not out.counts or out.stability_class in _LOST or out.metrics is None:
        return False
    return abs(out.metrics.steady_state_pitch) <= tol


def periods_to_decide(horizon_s: float, period_s: float) -> int:
    """Fewest orbits of a circular run that can see a settling up to ``horizon_s`` [s].

    The settling criterion needs the run's last ``SS_FRACTION`` inside the band, so
    a run of T [s] sees a settling up to (1 − SS_FRACTION) T; and no run shorter
    than :func:`~tethersim.analysis.metrics.min_run_orbits` has a class at all.
    """
    return max(math.ceil(horizon_s / ((1 - SS_FRACTION) * period_s) - 1e-9),
               math.ceil(min_run_orbits()))


def verdict(lifetime_s: float, nominal: Outcome, trims, tol: float = SETTLING_TOL, *,
            run_s: float = math.inf, cap_s: float = math.inf, lost: bool = False) -> str:
    """The verdict of one point at one integrator tolerance.

    Parameters
    ----------
    lifetime_s : float
        When the free orbit's usable life ended [s] (``math.inf`` if it outlived
        the cap: then a verdict that turns on the life is :data:`CAPPED`).
    nominal : Outcome
        Outcome of the nominal circular run.
    trims : iterable of Outcome
        Outcomes of the circular runs across the solar-cycle density range.
    tol : float, optional
        Trim band [rad].
    run_s : float, optional
        Length of the circular runs [s] (default: long enough for anything).
    cap_s : float, optional
        The free run's cap [s]: what is known of a life that outlived it.
    lost : bool, optional
        The life ended with the balloon lost (not a re-entry).

    Returns
    -------
    str
        One of :data:`VERDICTS` other than :data:`SENSITIVE`.
    """
    seen = (1 - SS_FRACTION) * run_s  # the latest settling the runs can show
    capped = not math.isfinite(lifetime_s)  # the life outlived the cap: its end is unknown
    horizon = cap_s if capped else lifetime_s
    ended = LOST if lost else REENTERS
    trims = tuple(trims)
    settle = settling_time(nominal)
    if not nominal.counts or nominal.stability_class in _LOST:
        return UNSTABLE
    if nominal.stability_class == UNDECIDED_CLASS:  # too short for any class
        return UNDECIDED
    if not math.isfinite(settle):
        if seen < horizon:
            return UNDECIDED
        return CAPPED if capped else ended
    if lifetime_s < settle:
        return ended
    for o in (nominal, *trims):
        if o.counts and o.stability_class == UNDECIDED_CLASS:
            return UNDECIDED
        if not trim_held(o, tol):
            return TRIM_LOST
    for o in trims:  # a held trim that has not settled yet: does it settle in time?
        if not math.isfinite(settling_time(o)):
            if seen < horizon:
                return UNDECIDED
            return CAPPED if capped else TRIM_LOST
    return FEASIBLE


def combine(verdicts) -> str:
    """One verdict from a point's verdicts at several tolerances: theirs if they agree,
    else :data:`SENSITIVE`."""
    verdicts = set(verdicts)
    return verdicts.pop() if len(verdicts) == 1 else SENSITIVE
