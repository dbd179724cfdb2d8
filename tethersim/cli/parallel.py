"""Where a command's runs go: threads here, or Dask workers (``--workers``,
``--dask-workers``, ``--scheduler``), declared once for sweep, mc and design.

A local Dask cluster (``--dask-workers N``: N worker processes) or a running scheduler
(``--scheduler ADDR``; `dask scheduler` on one machine, `dask worker ADDR` on each, or
`dask-jobqueue` on an HPC queue: docs/sweeps.md) runs the same compiled blocks as the
threads, so the stored results are the same.
"""
from __future__ import annotations

from tethersim.cli import options, preflight


def add_parallel(p) -> None:
    """``--workers``, ``--dask-workers``, ``--scheduler`` (alternatives)."""
    p.add_argument("--workers", type=options.positive_int, default=None, metavar="N",
                   help="threads on this machine (default: every core; at most 4 per core)")
    p.add_argument("--dask-workers", type=options.positive_int, default=None, metavar="N",
                   help="start a local Dask cluster of N worker processes (at most 4 per core)")
    p.add_argument("--scheduler", default=None, metavar="ADDR",
                   help="Dask scheduler address, e.g. tcp://10.0.0.5:8786 (docs/sweeps.md)")


def check_parallel(args) -> dict:
    """Refuse two of the three, or too many workers (one line); the runner's keywords."""
    if sum(x is not None for x in (args.workers, args.dask_workers, args.scheduler)) > 1:
        raise options.UsageError("--workers, --dask-workers and --scheduler are alternatives: "
                                 "give one")
    preflight.check_workers(args, "workers", "dask_workers")
    return {"workers": args.workers, "scheduler": args.scheduler,
            "dask_workers": args.dask_workers}
