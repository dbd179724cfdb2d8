"""SIMD lanes across sweep points (sweep/lanes.py) vs the point-by-point block.

A faithful (fixed-step RK4, the thesis's scheme) SatI sweep of 5 orbits, E1 x E2 on
the 64-point grid of bench/peers.py and the 144-point grid of bench/sweep_bench.py;
trajectories per second with the lanes (batch.USE_LANES) and without, the records
checked equal.  One thread: ``batch.run_satellites`` in this thread, timed in thread
CPU time; two threads: ``run_plan(workers=2)``, process CPU time and wall time.
Best of interleaved repeats.  The adaptive (DOP853) case: the 64-point grid on lanes
(sweep/lanes853.py) vs point by point, one thread.  ``python bench/lanes_bench.py
[repeats]`` runs it alone and prints the CPU and the load averages beside every figure
(``python bench/lanes_bench.py 3 adaptive``: the adaptive case alone).
"""
from __future__ import annotations

import os
import platform
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
for _p in (str(HERE), str(HERE.parent)):
    if _p not in sys.path:
        sys.path.insert(0, _p)

import numpy as np  # noqa: E402
from timing import cpu_clock, interleave  # noqa: E402

PERIODS = 5
GRIDS = {64: (np.linspace(0.002, 0.006, 8), np.linspace(0.03, 0.055, 8)),  # bench/peers.py
         144: (np.linspace(0.0036, 0.0044, 12), np.linspace(0.039, 0.047, 12))}  # sweep_bench


def _sats(n):
    from tethersim import load_preset
    sat = load_preset("satI")
    e1, e2 = GRIDS[n]
    return [sat.replace(E1=float(a), E2=float(b)) for b in e2 for a in e1]


def _load() -> str:
    return "load {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def bench_lanes(rep, q, log) -> None:
    """Lanes vs scalar block trajectories/s, 64 and 144 points, 1 and 2 threads."""
    from tethersim.engine.integrators.lanes import lane_count
    from tethersim.experiments.sweep import Plan, batch, run_plan

    plan = Plan(periods=float(PERIODS), method="faithful")
    repeats = q.get("sweep_repeats", 3)
    for n in GRIDS:
        sats = _sats(n)
        recs = {}

        def one(lanes, sats=sats, recs=recs):
            def t():
                batch.USE_LANES = lanes
                try:
                    t0 = cpu_clock()
                    recs[lanes] = batch.run_satellites(plan, sats)
                    return cpu_clock() - t0
                finally:
                    batch.USE_LANES = True
            return t

        def two(lanes, sats=sats):
            def t():
                batch.USE_LANES = lanes
                try:
                    c0, w0 = time.process_time(), time.perf_counter()
                    run_plan(plan, sats, workers=2, progress=False)
                    return time.process_time() - c0, time.perf_counter() - w0
                finally:
                    batch.USE_LANES = True
            return t

        s1 = interleave({"lanes": one(True), "scalar": one(False)}, repeats)
        same = [repr(sorted(r.items())) for r in recs[True]] == \
               [repr(sorted(r.items())) for r in recs[False]]
        rep.check(f"lanes: the {n}-point records equal the scalar block's", same)
        best = {k: n / min(v) for k, v in s1.items()}
        log(f"  lanes {n} points x {PERIODS} orbits, 1 thread (K = {lane_count()}): "
            f"{best['lanes']:.0f} vs scalar {best['scalar']:.0f} trajectories/s (thread CPU), "
            f"{best['lanes'] / best['scalar']:.2f}x; {_load()}")
        rep.fig(f"lanes.{n}.one", f"faithful sweep {n} points, 1 thread: lanes / scalar block",
                best["lanes"] / best["scalar"], "x", note=_load())
        s2 = interleave({"lanes": two(True), "scalar": two(False)}, repeats)
        cpu = {k: n / min(c for c, _ in v) for k, v in s2.items()}
        wall = {k: n / min(w for _, w in v) for k, v in s2.items()}
        log(f"  lanes {n} points, 2 threads: {cpu['lanes']:.0f} vs {cpu['scalar']:.0f} "
            f"trajectories per CPU second ({cpu['lanes'] / cpu['scalar']:.2f}x), wall "
            f"{wall['lanes']:.0f} vs {wall['scalar']:.0f}/s ({wall['lanes'] / wall['scalar']:.2f}x); "
            f"{_load()}")
        rep.fig(f"lanes.{n}.two", f"faithful sweep {n} points, 2 threads: lanes / scalar "
                f"block (process CPU)", cpu["lanes"] / cpu["scalar"], "x", note=_load())


def bench_lanes_adaptive(rep, q, log) -> None:
    """The adaptive (DOP853) 64-point sweep: lanes (sweep/lanes853.py) vs the point-by-point
    block, 1 thread, thread CPU time, the records checked equal."""
    from tethersim.engine.integrators.lanes import lane_count
    from tethersim.experiments.sweep import Plan, batch

    plan = Plan(periods=float(PERIODS))
    sats = _sats(64)
    recs = {}

    def one(lanes):
        def t():
            batch.USE_LANES = lanes
            try:
                t0 = cpu_clock()
                recs[lanes] = batch.run_satellites(plan, sats)
                return cpu_clock() - t0
            finally:
                batch.USE_LANES = True
        return t

    s1 = interleave({"lanes": one(True), "scalar": one(False)}, q.get("sweep_repeats", 3))
    same = [repr(sorted(r.items())) for r in recs[True]] == \
           [repr(sorted(r.items())) for r in recs[False]]
    rep.check("lanes: the adaptive 64-point records equal the scalar block's", same)
    best = {k: len(sats) / min(v) for k, v in s1.items()}
    log(f"  adaptive lanes 64 points x {PERIODS} orbits, 1 thread (K = {lane_count()}): "
        f"{best['lanes']:.0f} vs scalar {best['scalar']:.0f} trajectories/s (thread CPU), "
        f"{best['lanes'] / best['scalar']:.2f}x; {_load()}")
    rep.fig("lanes.adaptive.64.one", "adaptive sweep 64 points, 1 thread: lanes / scalar "
            "block", best["lanes"] / best["scalar"], "x", note=_load())


def bench_lanes_heyoka(rep, q, log) -> None:
    """The 64-point faithful sweep on lanes vs heyoka's SIMD batches at the faithful run's
    final-state error (first point, against tethersim DOP853 at rtol 1e-13), one thread.

    heyoka's loosest tolerance whose error is at most the faithful RK4 run's; its batch
    size is its fastest on this CPU (peers.fastest_batch); CPU time of the process
    (heyoka) and of the thread (tethersim).  tethersim's trajectories include the records
    (metrics, class, force peaks), heyoka's only the states on the same 200-per-orbit
    grid.
    """
    from peers import _error, _taut, fastest_batch, heyoka_batches, heyoka_integrator

    import tethersim as ts
    from tethersim.experiments.sweep import Plan, batch
    from tethersim.model.inputs import initial_model_state
    sats = _sats(64)
    sat0 = sats[0]
    plan = Plan(periods=float(PERIODS), method="faithful")
    n_steps = round(plan.steps_per_period * PERIODS)
    ref = ts.simulate(sat0, PERIODS, rtol=1e-13, atol=1e-15, progress=False,
                      samples=2).states[-1][:6]
    rk_err = _error(ts.simulate(sat0, PERIODS, n_steps, method="rk4", locate_switches=False,
                                progress=False).states[-1][:6], ref)
    y0 = initial_model_state(sat0, "derived")
    pars = _taut(sat0, y0)
    T = PERIODS * sat0.period
    grid1 = np.linspace(0.0, T, n_steps + 1)
    tol, hy_err = None, None
    for t in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10):
        ta = heyoka_integrator(sat0, t)[0]
        ta.time = 0.0
        ta.state[:] = y0
        ta.pars[:] = pars
        err = _error(ta.propagate_grid(grid1)[-1][-1], ref)
        if err <= rk_err:
            tol, hy_err = t, err
            break
    if tol is None:
        rep.check("lanes vs heyoka: a heyoka tolerance reaches the faithful run's error", False)
        return
    E = np.array([[s.E1 for s in sats], [s.E2 for s in sats]])
    bs, ta = fastest_batch(sat0, tol, y0, pars, E, grid1, log)

    def heyoka_all():
        t0 = time.process_time()
        heyoka_batches(ta, bs, range(0, len(sats), bs), y0, pars, E, grid1)
        return time.process_time() - t0

    def lanes():
        t0 = cpu_clock()
        batch.run_satellites(plan, sats)
        return cpu_clock() - t0

    best = {k: len(sats) / min(v) for k, v in
            interleave({"lanes": lanes, "heyoka": heyoka_all}, q.get("sweep_repeats", 3)).items()}
    log(f"  lanes vs heyoka, 64 points x {PERIODS} orbits, 1 thread: faithful RK4 error "
        f"{rk_err:.2g}, heyoka tol {tol:g} (error {hy_err:.2g}), batch {bs}: lanes "
        f"{best['lanes']:.0f} vs heyoka {best['heyoka']:.0f} trajectories/s "
        f"({best['lanes'] / best['heyoka']:.2f}x); {_load()}")
    rep.fig("lanes.heyoka", "faithful sweep on lanes / heyoka batches at the faithful run's "
            "error, 64 points, 1 thread", best["lanes"] / best["heyoka"], "x",
            note=f">1: tethersim faster; {_load()}")


class _Print:
    def fig(self, key, label, value, unit, samples=None, note=""):
        print(f"{key}: {label}: {value:.3g} {unit} ({note})")

    def check(self, label, ok, detail=""):
        print(f"{'ok' if ok else 'FAILED'}: {label} {detail}")


if __name__ == "__main__":
    cpu = next((ln.split(":", 1)[1].strip() for ln in
                Path("/proc/cpuinfo").read_text().splitlines() if ln.startswith("model name")),
               platform.processor())
    print(f"CPU: {cpu}; {os.cpu_count()} cores; {_load()}")
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    if "adaptive" in sys.argv[2:]:  # the adaptive case alone
        bench_lanes_adaptive(_Print(), {"sweep_repeats": reps}, print)
        sys.exit(0)
    bench_lanes(_Print(), {"sweep_repeats": reps}, print)
    bench_lanes_adaptive(_Print(), {"sweep_repeats": reps}, print)
    try:
        import heyoka  # noqa: F401
    except ImportError:
        print("heyoka not installed (the [bench] extra): no comparison with its batches")
    else:
        bench_lanes_heyoka(_Print(), {"sweep_repeats": reps}, print)
