"""The sweep benches' grid, and the report's wall time.

The grid is SatI's E1 x E2 around the stable band, so it mixes settling, offset and
tumbling points as a real sweep does (bench/csweep.py times its sweeps on 1 thread and
on every core, against a C+OpenMP driver).
"""
from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
from timing import wall

COMPILE_NOTICE = "tethersim: compiling numerical kernels"  # engine/integrators/select.py

GRID = (np.linspace(0.0036, 0.0044, 12), np.linspace(0.039, 0.047, 12))  # N/mm^2, 144 runs


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
