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

1. ``unstable`` -- the nominal run failed, tumbled or ended upside down, or did not
   settle although the run could have seen a settling at any time up to the cap;
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
   (1 − SS_FRACTION) T ≥ the usable life (or the cap), :func:`periods_to_decide`.

A point is decided at two integrator tolerances (experiments/feasibility.py); a
verdict that differs between them is reported as :data:`SENSITIVE`
(:func:`combine`), not as a fact.
"""
from __future__ import annotations

import math

from tethersim.analysis.classify import FAILED, TUMBLING, UPSIDE_DOWN
from tethersim.analysis.metrics import SETTLING_TOL, SS_FRACTION
from tethersim.analysis.outcome import Outcome

VERDICTS = ("feasible", "balloon lost before settling", "re-enters before settling",
            "trim lost as the air varies", "unstable", "undecided: run longer", "sensitive")
FEASIBLE, LOST, REENTERS, TRIM_LOST, UNSTABLE, UNDECIDED, SENSITIVE = VERDICTS
VERDICT_COLORS = {FEASIBLE: "#2e7d32", LOST: "#ef6c00", REENTERS: "#c62828",
                  TRIM_LOST: "#fbc02d", UNSTABLE: "#6a1b9a", UNDECIDED: "#ffffff",
                  SENSITIVE: "#9e9e9e"}
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
    a run of T [s] sees a settling up to (1 − SS_FRACTION) T.
    """
    return math.ceil(horizon_s / ((1 - SS_FRACTION) * period_s) - 1e-9)


def verdict(lifetime_s: float, nominal: Outcome, trims, tol: float = SETTLING_TOL, *,
            run_s: float = math.inf, cap_s: float = math.inf, lost: bool = False) -> str:
    """The verdict of one point at one integrator tolerance.

    Parameters
    ----------
    lifetime_s : float
        When the free orbit's usable life ended [s] (``math.inf`` if it outlived
        the cap).
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
    horizon = lifetime_s if math.isfinite(lifetime_s) else cap_s
    ended = LOST if lost else REENTERS
    settle = settling_time(nominal)
    if not nominal.counts or nominal.stability_class in _LOST:
        return UNSTABLE
    if not math.isfinite(settle):
        if seen < horizon:
            return UNDECIDED
        return ended if math.isfinite(lifetime_s) else UNSTABLE
    if lifetime_s < settle:
        return ended
    for o in (nominal, *trims):
        if not trim_held(o, tol):
            return TRIM_LOST
    for o in trims:  # a held trim that has not settled yet: does it settle in time?
        if not math.isfinite(settling_time(o)):
            return UNDECIDED if seen < horizon else TRIM_LOST
    return FEASIBLE


def combine(verdicts) -> str:
    """One verdict from a point's verdicts at several tolerances: theirs if they agree,
    else :data:`SENSITIVE`."""
    verdicts = set(verdicts)
    return verdicts.pop() if len(verdicts) == 1 else SENSITIVE
