"""Stability classes of one run, as the thesis sorted its sweep points (p. 5-6, 5-18).

Codes (stored in sweep data sets as CF flag_values / flag_meanings):

  0 stable       settled to within ±tol of θ_ss, |θ_ss| <= tol, within the requirement
  1 unsettled    |θ_ss| <= tol but not settled within the run / the requirement
                 (too little damping, thesis p. 5-11)
  2 offset       |θ_ss| > tol, not upside down (e.g. the π/2 offset of Fig 5.5)
  3 upside_down  |θ_ss| > 3π/4 (Fig 5.14)
  4 tumbling     θ passed ±π and did not end upside down (Fig 5.4)
  5 failed       the integration failed (non-finite state, step too small)

The order of the tests is the priority: a run that tumbled and ended upside
down is "upside_down".  Definitions of the metrics: docs/metrics.md.
"""
from __future__ import annotations

import math

from tethersim.analysis.metrics import SETTLING_TOL, PitchMetrics

CLASSES = ("stable", "unsettled", "offset", "upside_down", "tumbling", "failed")
STABLE, UNSETTLED, OFFSET, UPSIDE_DOWN, TUMBLING, FAILED = range(len(CLASSES))
CLASS_COLORS = ("#2e7d32", "#9ccc65", "#fbc02d", "#c62828", "#6a1b9a", "#616161")
SETTLING_REQUIREMENT = 3 * 86400.0  # s: three days, thesis p. 5-6


def classify(m: PitchMetrics | None, tol: float = SETTLING_TOL,
             requirement: float = SETTLING_REQUIREMENT) -> int:
    """Class code of a run from its metrics (None: the integration failed)."""
    if m is None:
        return FAILED
    if m.upside_down:
        return UPSIDE_DOWN
    if m.tumbled:
        return TUMBLING
    if abs(m.steady_state_pitch) > tol:
        return OFFSET
    if not math.isfinite(m.settling_time) or m.settling_time > requirement:
        return UNSETTLED
    return STABLE


def flag_attrs() -> dict:
    """CF attributes that label the class codes in a data set."""
    return {"flag_values": list(range(len(CLASSES))), "flag_meanings": " ".join(CLASSES),
            "long_name": "stability class (docs/metrics.md)"}
