"""How loose a tolerance may be for a question that needs only classes.

A point's class (docs/metrics.md) depends on its run through thresholds far above
the integration error (the settling band is 0.05 rad), so it converges long before
the steady-state pitch does.  :func:`class_convergence` measures that on a grid:
the same points at each tolerance against the tightest, the classes that change,
the largest change of θ_ss and settling time, and the work saved.  The study that
chose :data:`tethersim.experiments.sweep.plan.CLASS_RTOL` is docs/tolerances.md.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from tethersim.analysis.classify import CLASSES
from tethersim.experiments.sweep.runner import run_plan
from tethersim.experiments.sweep.spec import SweepSpec


def class_convergence(spec: SweepSpec, rtols, workers: int | None = None) -> list:
    """The grid of ``spec`` at each tolerance against the tightest of ``rtols``.

    Parameters
    ----------
    spec : SweepSpec
        The grid (its own rtol is not used).
    rtols : sequence of float
        Tolerances; the smallest is the reference.
    workers : int, optional
        Threads.

    Returns
    -------
    list of dict
        One row per tolerance, loosest last: ``rtol``, ``class_changes`` (points whose
        class differs from the reference's), ``max_dtheta_ss`` [rad] and
        ``max_dsettling`` [s] (largest change where both runs have the value; the
        settling time only of points whose reference class is stable: a tumbling
        point's last pass through the band is not a settling time), and
        ``work`` (right-hand-side evaluations relative to the reference).
    """
    sats = [spec.satellite_at(k) for k in range(spec.size)]
    runs = {}
    for rtol in sorted(rtols):
        recs = run_plan(replace(spec.plan, rtol=float(rtol)), sats, workers=workers,
                        progress=False)
        runs[rtol] = {key: np.array([r[key] for r in recs], dtype=float)
                      for key in ("stability_class", "steady_state_pitch", "settling_time",
                                  "nfev")}
    ref = runs[min(runs)]
    stable = ref["stability_class"] == CLASSES.index("stable")
    rows = []
    for rtol, run in runs.items():
        rows.append({"rtol": rtol,
                     "class_changes": int(np.sum(run["stability_class"] != ref["stability_class"])),
                     "max_dtheta_ss": _largest_change(run["steady_state_pitch"],
                                                      ref["steady_state_pitch"]),
                     "max_dsettling": _largest_change(run["settling_time"][stable],
                                                      ref["settling_time"][stable]),
                     "work": float(run["nfev"].sum() / ref["nfev"].sum())})
    return rows


def _largest_change(a: np.ndarray, b: np.ndarray) -> float:
    both = np.isfinite(a) & np.isfinite(b)
    return float(np.max(np.abs(a[both] - b[both]))) if both.any() else 0.0
