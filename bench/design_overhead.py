"""Per-design overhead of ``tethersim design`` against bare plans of the same runs.

The search (NSGA-II, building each design's feasibility runs, the verdicts, the JSONL
store) against ``run_plan`` of exactly the satellites it ran (prebuilt, two calls), on
one thread, re-verification off; min of REPEATS.  Usage:
``python bench/design_overhead.py [PERIODS] [BUDGET]`` (default 50 orbits, 32 designs).
"""
from __future__ import annotations

import sys
import tempfile
import time

REPEATS = 3


def main(periods: float = 50.0, budget: int = 32) -> None:
    import tethersim as ts
    from tethersim.experiments.design import DesignSpec, build_runs
    from tethersim.experiments.design_search import search
    from tethersim.experiments.sweep.runner import run_plan

    spec = DesignSpec(ts.load_preset("satI"), variables=(("c1", 1e-3, 1e-1), ("c2", 1e-3, 1e-1),
                                                         ("altitude", 195.0, 230.0)),
                      budget=budget, population=min(16, budget), periods=periods,
                      max_lifetime_h=12, seed=1, verify=0)
    search(spec, tempfile.mkdtemp(), workers=1, progress=False)  # compile / load the kernels
    t_design, t_bare = [], []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        res = search(spec, tempfile.mkdtemp(), workers=1, progress=False)
        t_design.append(time.perf_counter() - t0)
        unique = {r["key"]: r["x"] for r in res["evaluations"]}  # each design ran once
        built = [build_runs(spec, x) for x in unique.values()]
        circ_plan, free_plan = spec.plans()
        t0 = time.perf_counter()
        run_plan(circ_plan, [c for b in built for c in b[0]], workers=1, progress=False)
        run_plan(free_plan, [b[1] for b in built], workers=1, progress=False)
        t_bare.append(time.perf_counter() - t0)
    n, d, b = len(built), min(t_design), min(t_bare)
    print(f"{n} designs x 5 runs ({periods:g}-orbit circular, free to 12 h), 1 thread: design "
          f"{d:.3f} s, bare run_plan {b:.3f} s, ratio {d / b:.3f}, overhead "
          f"{(d - b) / n * 1e3:.2f} ms per design")


if __name__ == "__main__":
    main(*(float(a) if i == 0 else int(a) for i, a in enumerate(sys.argv[1:])))
