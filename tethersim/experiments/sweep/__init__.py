"""Stability-region sweeps (thesis Figures 5.13, 5.21-5.23, 5.27-5.28).

``sweep(sat, {"E1": values, "E2": values}, out="results/sweep.zarr")`` runs
every grid point (a converged DOP853 run by default, or the thesis's fixed RK4
step), classifies it (tethersim.analysis.classify) and writes the labelled results to a
resumable Zarr store; it returns the xarray Dataset.
"""
from __future__ import annotations

from tethersim.experiments.sweep.lock import StoreLocked
from tethersim.experiments.sweep.plan import Plan
from tethersim.experiments.sweep.point import VARIABLES, run_point
from tethersim.experiments.sweep.runner import SweepInterrupted, run_plan, run_sweep
from tethersim.experiments.sweep.spec import SweepSpec
from tethersim.experiments.sweep.store import StoreMismatch, StoreRepaired, open_dataset, status_names
from tethersim.experiments.sweep.verify import StoreDamaged


def sweep(sat, axes: dict, out, **options):
    """Run (or resume) a sweep and return its data set.

    axes: {name: values in edge units} with one or two entries (first = x).
    options: SweepSpec fields (periods, method, model, rtol, ...) and run_sweep
      options (workers, scheduler, dask_workers, restart, progress).
    """
    run_opts = {k: options.pop(k) for k in ("workers", "scheduler", "dask_workers", "restart",
                                             "progress", "block") if k in options}
    spec = SweepSpec(sat, tuple(axes.items()), **options)
    return run_sweep(spec, out, **run_opts).dataset()


__all__ = ["Plan", "SweepSpec", "SweepInterrupted", "StoreMismatch", "StoreLocked", "StoreDamaged",
           "StoreRepaired", "VARIABLES", "open_dataset", "status_names",
           "run_plan", "run_point", "run_sweep", "sweep"]
