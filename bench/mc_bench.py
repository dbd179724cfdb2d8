"""Cost of ``tethersim mc`` (issue 23): `.venv/bin/python bench/mc_bench.py [N] [--dask-workers K]`.

Runs the same N SatI samples (seed 2026, the command's defaults: 50-orbit settling run,
free run capped at 240 h in stages) twice, after a warm-up of 4 samples (compiled
kernels, the space-weather table):

* bare: ``run_plan`` of the samples' circular satellites, then of their free ones
  (first stage, and the second stage for those still flying): the runs alone;
* mc: ``run_mc`` into a fresh store (draws, rows, the JSONL store, its final rewrite);

and prints both, their ratio (mc's per-run overhead) and mc's time per sample with
the extrapolation to N = 2000.  Each free run's MSIS grid is built for the UTC days of its
stage (0.1 s a day in pymsis, which holds the GIL: threads do not share that part out,
worker processes do).  Figures depend on the machine and on what else runs on it.
"""
from __future__ import annotations

import argparse
import tempfile
import time
from collections import Counter

import tethersim as ts
from tethersim.experiments.mc import MCSpec, run_mc
from tethersim.experiments.mc.inputs import sample_satellites
from tethersim.experiments.sweep.point import STATUS
from tethersim.experiments.sweep.runner import run_plan


def bare(spec: MCSpec, kw: dict) -> float:
    samples = sample_satellites(spec.satellite, spec.inputs, spec.units("sample"))
    t = time.perf_counter()
    run_plan(spec.circular_plan, [s[1] for s in samples], progress=False, **kw)
    free = run_plan(spec.free_plans[0], [s[2] for s in samples], progress=False, **kw)
    for plan in spec.free_plans[1:]:
        again = [s[2] for s, r in zip(samples, free) if r["status"] == STATUS["ok"]]
        if again:
            run_plan(plan, again, progress=False, **kw)
    return time.perf_counter() - t


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("n", type=int, nargs="?", default=64)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--dask-workers", type=int, default=None)
    a = ap.parse_args()
    kw = {"dask_workers": a.dask_workers} if a.dask_workers else {"workers": a.workers}
    sat = ts.load_preset("satI")
    run_mc(MCSpec(sat, n=4, seed=1), tempfile.mkdtemp(), progress=False, **kw)  # warm-up
    spec = MCSpec(sat, n=a.n, seed=2026)
    t_bare = bare(spec, kw)
    t = time.perf_counter()
    rows = run_mc(spec, tempfile.mkdtemp(), progress=False, **kw)
    t_mc = time.perf_counter() - t
    where = f"{a.dask_workers} Dask worker processes" if a.dask_workers else f"{a.workers} threads"
    print(f"mc bench: n = {a.n} SatI samples on {where}: bare run_plan {t_bare:.2f} s, "
          f"mc {t_mc:.2f} s, mc / bare {t_mc / t_bare:.2f}; {1e3 * t_mc / a.n:.0f} ms a sample "
          f"-> n = 2000 in about {t_mc / a.n * 2000 / 60:.1f} min")
    print("  life ends:", dict(Counter(r["life_end"] for r in rows)),
          " classes:", dict(Counter(r["class"] for r in rows)))


if __name__ == "__main__":
    main()
