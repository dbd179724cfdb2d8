"""Stability classes of one run, as the thesis sorted its sweep points (p. 5-6, 5-18).

Codes (stored in sweep data sets as CF flag_values / flag_meanings):

  0 stable       settled to within ±tol of θ_ss, |θ_ss| <= tol, within the requirement
  1 unsettled    |θ_ss| <= tol but not settled within the run / the requirement
                 (too little damping, thesis p. 5-11)
  2 offset       |θ_ss| > tol, not upside down (e.g. the π/2 offset of Fig 5.5)
  3 upside_down  |θ_ss| > 3π/4 (Fig 5.14)
  4 tumbling     θ passed ±π and did not end upside down (Fig 5.4)
  5 failed       the integration failed (non-finite state, step too small)
  6 undecided    the run is too short to decide (metrics.long_enough): run longer

The order of the tests is the priority: a run that tumbled and ended upside
down is "upside_down".  A run too short to decide is "tumbling" if θ passed ±π
(that happened, whatever follows), else "undecided".  "undecided" comes last so
that the stored codes of the other classes keep their numbers.  Definitions of the metrics: docs/metrics.md.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.metrics import SETTLING_TOL, PitchMetrics, long_enough, min_run_orbits

CLASSES = ("stable", "unsettled", "offset", "upside_down", "tumbling", "failed", "undecided")
STABLE, UNSETTLED, OFFSET, UPSIDE_DOWN, TUMBLING, FAILED, UNDECIDED = range(len(CLASSES))
CLASS_COLORS = ("#2e7d32", "#9ccc65", "#fbc02d", "#c62828", "#6a1b9a", "#616161", "#90caf9")
SETTLING_REQUIREMENT = 3 * 86400.0  # s: three days, thesis p. 5-6


def classify(m: PitchMetrics | None, tol: float = SETTLING_TOL,
             requirement: float = SETTLING_REQUIREMENT, run_orbits: float = math.inf) -> int:
    """Class code of a run from its metrics (None: the integration failed).

    Parameters
    ----------
    m : PitchMetrics or None
        The run's pitch metrics; None when the integration failed.
    tol : float, optional
        Settling band [rad].
    requirement : float, optional
        Longest settling time that counts as stable [s].
    run_orbits : float, optional
        Length of the run [orbits]; below
        :func:`tethersim.analysis.metrics.min_run_orbits` the class is
        ``tumbling`` if θ passed ±π, else ``undecided``.

    Returns
    -------
    int
        Code in :data:`CLASSES`.
    """
    if m is None:
        return FAILED
    if not long_enough(run_orbits):
        return TUMBLING if m.tumbled else UNDECIDED
    if m.upside_down:
        return UPSIDE_DOWN
    if m.tumbled:
        return TUMBLING
    if abs(m.steady_state_pitch) > tol:
        return OFFSET
    if not math.isfinite(m.settling_time) or m.settling_time > requirement:
        return UNSETTLED
    return STABLE


def describe(code: int) -> str:
    """The class name; for ``undecided``, with how long a run must be to decide."""
    if code == UNDECIDED:
        return f"undecided: run at least {min_run_orbits():.4g} orbits"
    return CLASSES[code]


def flag_attrs() -> dict:
    """CF attributes that label the class codes in a data set."""
    return {"flag_values": list(range(len(CLASSES))), "flag_meanings": " ".join(CLASSES),
            "long_name": "stability class (docs/metrics.md)"}


def _codes(a, variable: str) -> np.ndarray:
    if hasattr(a, "data_vars"):  # an xarray Dataset (xarray itself is not imported here)
        a = a[variable]
    return np.asarray(a)


def agreement(predicted, simulated) -> dict:
    """How often a predicted map matches a simulated one, point by point.

    predicted, simulated: integer class codes of tethersim.analysis.classify, arrays of the
    same shape (or a Dataset: its predicted_class / stability_class variable).
    Negative codes are the sweep store's fill for points not computed.  They are
    left out of the comparison and counted in n_missing.

    Returns {"same_class": fraction of points with the same code, "same_stability":
    fraction with the same stable / not-stable verdict (stable: code 0), "confusion":
    counts, int array [predicted code, simulated code] of shape (6, 6), "classes":
    CLASSES, "n": points compared, "n_missing": points left out}.
    The fractions are NaN when no point is compared.
    """
    p = _codes(predicted, "predicted_class")
    s = _codes(simulated, "stability_class")
    if p.shape != s.shape:
        raise ValueError(f"predicted has shape {p.shape}, simulated {s.shape}: must be equal")
    for name, a in (("predicted", p), ("simulated", s)):
        if a.size and not np.issubdtype(a.dtype, np.integer):
            raise ValueError(f"{name}: class codes must be integers, got dtype {a.dtype}")
        if a.size and a.max() >= len(CLASSES):
            raise ValueError(f"{name}: code {a.max()} is not a class (0..{len(CLASSES) - 1})")
    ok = (p >= 0) & (s >= 0)
    pv, sv = p[ok].astype(np.intp), s[ok].astype(np.intp)
    confusion = np.zeros((len(CLASSES), len(CLASSES)), dtype=np.int64)
    np.add.at(confusion, (pv, sv), 1)
    n = int(pv.size)
    return {
        "same_class": float(np.mean(pv == sv)) if n else math.nan,
        "same_stability": float(np.mean((pv == STABLE) == (sv == STABLE))) if n else math.nan,
        "confusion": confusion, "classes": CLASSES, "n": n, "n_missing": int(p.size - n),
    }
