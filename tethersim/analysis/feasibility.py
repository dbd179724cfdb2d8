"""The verdict of one feasibility point: does the thesis's design work in a real orbit?

A point (an altitude, a balloon area) has three kinds of runs
(tethersim.experiments.feasibility):

* a **free** orbit from that altitude, run until re-entry (capped): its end is the
  end of the satellite's life;
* a **nominal** circular run (the thesis: orbit held, Vallado's air): its outcome
  gives the settling time;
* **trim** runs: circular, the density scaled to NRLMSISE-00's solar minimum, mean
  and maximum at that altitude.

:func:`verdict` turns them into one of :data:`VERDICTS`, in this priority:

1. ``unstable`` -- the nominal run failed, tumbled, ended upside down or did not
   settle within the run (no settling time);
2. ``re-enters before settling`` -- the free orbit ended before the nominal
   settling time;
3. ``trim lost as the air varies`` -- a trim run (or the nominal one) failed,
   tumbled, or settled with |θ_ss| > ``tol`` (thesis ±0.05 rad, p. 5-18);
4. ``feasible`` -- none of these.
"""
from __future__ import annotations

import math

from tethersim.analysis.classify import FAILED, TUMBLING, UPSIDE_DOWN
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.analysis.outcome import Outcome

VERDICTS = ("feasible", "re-enters before settling", "trim lost as the air varies", "unstable")
FEASIBLE, REENTERS, TRIM_LOST, UNSTABLE = VERDICTS
VERDICT_COLORS = {FEASIBLE: "#2e7d32", REENTERS: "#c62828", TRIM_LOST: "#fbc02d",
                  UNSTABLE: "#6a1b9a"}
_LOST = (FAILED, TUMBLING, UPSIDE_DOWN)


def settling_time(out: Outcome) -> float:
    """Settling time [s] of a run's outcome; NaN if it did not settle or has no metrics."""
    return out.metrics.settling_time if out.metrics is not None else math.nan


def trim_held(out: Outcome, tol: float = SETTLING_TOL) -> bool:
    """True when a run counts, did not tumble or turn over, and |θ_ss| <= ``tol``."""
    if not out.counts or out.stability_class in _LOST or out.metrics is None:
        return False
    return abs(out.metrics.steady_state_pitch) <= tol


def verdict(lifetime_s: float, nominal: Outcome, trims, tol: float = SETTLING_TOL) -> str:
    """The verdict of one point.

    Parameters
    ----------
    lifetime_s : float
        When the free orbit ended [s] (``math.inf`` if it outlived the cap).
    nominal : Outcome
        Outcome of the nominal circular run.
    trims : iterable of Outcome
        Outcomes of the circular runs across the solar-cycle density range.
    tol : float, optional
        Trim band [rad].

    Returns
    -------
    str
        One of :data:`VERDICTS`.
    """
    settle = settling_time(nominal)
    if not nominal.counts or nominal.stability_class in _LOST or not math.isfinite(settle):
        return UNSTABLE
    if lifetime_s < settle:
        return REENTERS
    if not all(trim_held(o, tol) for o in (nominal, *trims)):
        return TRIM_LOST
    return FEASIBLE
