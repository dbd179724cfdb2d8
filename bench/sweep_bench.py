"""Sweep throughput (trajectories per second) on 1 thread vs every core, and the report's wall time.

The grid is SatI's E1 x E2 around the stable band, 50-orbit converged runs, so
it mixes settling, offset and tumbling points as a real sweep does.  Each
repeat writes a fresh store (the store's cost is part of the figure; removing
the previous one, which a user's first run does not do, is not).
"""
from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
from timing import clock, interleave, median, wall

COMPILE_NOTICE = "tethersim: compiling numerical kernels"  # engine/integrators/select.py

GRID = (np.linspace(0.0036, 0.0044, 12), np.linspace(0.039, 0.047, 12))  # N/mm^2, 144 runs


def bench_sweep(rep, q):
    from tethersim import load_preset
    from tethersim.experiments.sweep import SweepSpec, run_sweep

    sat = load_preset("satI")
    spec = SweepSpec(sat, (("E1", GRID[0].tolist()), ("E2", GRID[1].tolist())), periods=50.0)
    cores = os.cpu_count() or 1
    tmp = Path(tempfile.mkdtemp(prefix="tethersim-bench-sweep-"))
    sys.stdout.write(f"  sweep: {spec.size} SatI runs of 50 orbits, 1 thread vs {cores}\n")

    def timer(workers):
        def t():
            out = tmp / f"w{workers}.zarr"
            shutil.rmtree(out, ignore_errors=True)
            t0 = clock()
            run_sweep(spec, out, workers=workers, progress=False)
            return clock() - t0
        return t

    try:
        s = interleave({"one": timer(1), "all": timer(cores)}, q["sweep_repeats"], warmup=1)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    tp1 = [spec.size / x for x in s["one"]]
    tpn = [spec.size / x for x in s["all"]]
    rep.fig("sweep.one", "sweep throughput, 1 thread", median(tp1), "run/s", tp1)
    rep.fig("sweep.all", f"sweep throughput, {cores} threads", median(tpn), "run/s", tpn)
    ratio = median(tpn) / median(tp1)
    rep.fig("sweep.ratio", f"sweep throughput ratio {cores} threads / 1", ratio, "x")
    rep.target("sweep.ratio", f"sweep throughput, {cores} cores vs 1", ratio, ">=",
               1.8 if cores >= 2 else 1.0, note="issue 4")


def bench_report(rep, q, repo):
    def run():
        out = Path(tempfile.mkdtemp(prefix="tethersim-bench-report-"))
        try:
            return wall([sys.executable, "-m", "tethersim", "report", "--out", str(out)],
                        cwd=repo, timeout=3600, keep=10**7)
        finally:
            shutil.rmtree(out, ignore_errors=True)

    dt, rc, text = run()
    if rc == 0 and COMPILE_NOTICE in text:  # kernels compiled: time a warm run too
        rep.fig("report.cold", "tethersim report, compiling its kernels first (one run)",
                dt, "s", [dt])
        dt, rc, text = run()
    rep.check("tethersim report exits 0", rc == 0, "" if rc == 0 else text[-300:])
    rep.fig("report.wall", "tethersim report, whole chapter 5, kernels cached (one run)", dt,
            "s", [dt])
    rep.target("report.wall", "issue 22: tethersim report wall time", dt, "<=", 70.0, unit="s",
               note=f"{os.cpu_count()} cores")
