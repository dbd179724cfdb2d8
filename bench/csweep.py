"""C+OpenMP sweep driver vs tethersim's sweep (`make bench`, issue 10 item 6).

The C side is the DOP853 port of bench/cref.py (same derivation, tableau, step
control, switch location and dense output) driven by one ``#pragma omp
parallel for`` over the grid points: integration only, the floor a sweep can
reach.  The tethersim side is ``run_sweep`` as users call it (integration plus
the metrics, force peaks, classification and the Zarr store), whose tasks are
compiled blocks of points (tethersim.experiments.sweep.batch); for comparison,
the same sweep through the per-point path (point.run_point: simulate() and
outcome() in Python per point) on 2 threads.  All sweep SatI's E1 x E2 grid of
bench/sweep_bench.py at the sweep's defaults (rtol 1e-9, atol 1e-11, 100
output samples per orbit, switches located), timed interleaved.
"""
from __future__ import annotations

import ctypes
import os
import shutil
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

import cref
import numpy as np
from timing import clock, interleave, median

DRIVER = r"""
#include <stdlib.h>
#include <omp.h>

/* n points: parameters P[k*np_ ...], initial states Y0[k*NS ...]; final states and
   accepted step counts out.  Each point writes its own dense output (like a sweep). */
int c_sweep_dop853(long n, const double *P, long np_, const double *Y0, double t_end,
                   double rtol, double atol, int locate, long n_out, double *final_y,
                   long *accepted, int threads)
{
    long failed = 0;
    omp_set_num_threads(threads);
    #pragma omp parallel for schedule(dynamic, 1) reduction(+:failed)
    for (long k = 0; k < n; k++) {
        double y[NS], res[3];
        int64_t cnt[5] = {0, 0, 0, 0, 0};
        double *out_t = malloc(n_out * sizeof(double));
        double *out_y = malloc(n_out * NS * sizeof(double));
        for (long i = 0; i < n_out; i++) out_t[i] = t_end * (double)(i + 1) / (double)n_out;
        memcpy(y, Y0 + k * NS, sizeof y);
        int st = c_dop853_run(0.0, t_end, y, 0.0, P + k * np_, rtol, atol, locate, out_t, n_out,
                              out_y, 0, 1000000000L, cnt, res);
        failed += st != 0;
        memcpy(final_y + k * NS, y, sizeof y);
        accepted[k] = (long)cnt[1];
        free(out_t);
        free(out_y);
    }
    return (int)failed;
}
"""

_D = ctypes.POINTER(ctypes.c_double)
_L = ctypes.POINTER(ctypes.c_long)


def build():
    """The OpenMP library (gcc -O3 -fopenmp) of the derived model's C port, or None when
    gcc cannot build it."""
    src, _ = cref.derived_source()
    try:
        path = cref.build(src + DRIVER, ("-O3", "-fopenmp"), "omp")
    except Exception as exc:  # noqa: BLE001 - no OpenMP toolchain: the figure is skipped
        return None, str(exc)
    lib = ctypes.CDLL(str(path))
    lib.c_sweep_dop853.argtypes = [ctypes.c_long, _D, ctypes.c_long, _D, ctypes.c_double,
                                   ctypes.c_double, ctypes.c_double, ctypes.c_int, ctypes.c_long,
                                   _D, _L, ctypes.c_int]
    lib.c_sweep_dop853.restype = ctypes.c_int
    return lib, ""


def _cpu() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "an unnamed CPU"


@contextmanager
def per_point_path():
    """run_sweep with every point through point.run_point (the path before the blocks)."""
    from tethersim.experiments.sweep import runner
    from tethersim.experiments.sweep.point import _spec, run_point
    saved = runner.run_points
    runner.run_points = lambda spec_json, ks: [(k, run_point(_spec(spec_json), k)) for k in ks]
    try:
        yield
    finally:
        runner.run_points = saved


def _points(spec):
    from tethersim.model.inputs import initial_model_state, parameter_vector
    sats = [spec.satellite_at(k) for k in range(spec.size)]
    P = np.ascontiguousarray([parameter_vector(s, "derived") for s in sats])
    Y0 = np.ascontiguousarray([initial_model_state(s, "derived") for s in sats])
    return P, Y0, sats[0].period


def bench_csweep(rep, q, log):
    """Trajectories/s of the C+OpenMP driver and of run_sweep, 5 and 50 orbits, 1 and 2 threads."""
    from sweep_bench import GRID

    from tethersim import load_preset
    from tethersim.experiments.sweep import SweepSpec, run_sweep
    from tethersim.experiments.sweep.plan import ATOL_PER_RTOL
    from tethersim.experiments.sweep.runner import map_points

    lib, why = build()
    if lib is None:
        rep.notes.append(f"C+OpenMP sweep skipped: {why[:200]}")
        return
    sat = load_preset("satI")
    cores = min(2, os.cpu_count() or 1)
    tmp = Path(tempfile.mkdtemp(prefix="tethersim-bench-csweep-"))
    try:
        for periods in (5.0, 50.0):
            spec = SweepSpec(sat, (("E1", GRID[0].tolist()), ("E2", GRID[1].tolist())),
                             periods=periods)
            P, Y0, period = _points(spec)
            n_out = max(2, round(spec.samples_per_period * periods))
            fin = np.empty_like(Y0)
            acc = np.zeros(spec.size, dtype=np.int64)
            log(f"  sweep {spec.size} points x {periods:g} orbits on {_cpu()}: C+OpenMP vs "
                f"run_sweep, 1 and {cores} threads, and the per-point path; load average "
                f"{os.getloadavg()[0]:.2f}")

            def c_timer(threads):
                def t():
                    t0 = clock()
                    lib.c_sweep_dop853(spec.size, P.ctypes.data_as(_D), P.shape[1],
                                       Y0.ctypes.data_as(_D), periods * period, spec.rtol,
                                       spec.rtol * ATOL_PER_RTOL, 1, n_out,
                                       fin.ctypes.data_as(_D), acc.ctypes.data_as(_L), threads)
                    return clock() - t0
                return t

            def ts_timer(threads, per_point=False):
                def t():
                    out = tmp / f"p{periods:g}w{threads}{'pp' if per_point else ''}.zarr"
                    shutil.rmtree(out, ignore_errors=True)  # a fresh store, as a first run writes
                    t0 = clock()
                    if per_point:
                        with per_point_path():
                            run_sweep(spec, out, workers=threads, progress=False)
                    else:
                        run_sweep(spec, out, workers=threads, progress=False)
                    return clock() - t0
                return t

            def map_timer(threads):  # the same points without a store (runner.map_points)
                def t():
                    t0 = clock()
                    map_points(spec, workers=threads)
                    return clock() - t0
                return t

            load = os.getloadavg()[0]
            res = interleave({"c1": c_timer(1), f"c{cores}": c_timer(cores),
                              "ts1": ts_timer(1), f"ts{cores}": ts_timer(cores),
                              f"pp{cores}": ts_timer(cores, per_point=True),
                              "mp1": map_timer(1), f"mp{cores}": map_timer(cores)},
                             # three times the repeats for the short sweep (its ~0.4 s
                             # runs move by 10 % between repeats on a shared machine),
                             # twice for the long one: its thread scaling is a target
                             q["sweep_repeats"] * (3 if periods < 10 else 2), warmup=1)
            load = (load + os.getloadavg()[0]) / 2
            tp = {k: spec.size / median(v) for k, v in res.items()}
            tag = f"{periods:g}"
            for k, label in (("c1", "C+OpenMP, 1 thread"), (f"c{cores}", f"C+OpenMP, {cores} threads"),
                             ("ts1", "tethersim run_sweep, 1 thread"),
                             (f"ts{cores}", f"tethersim run_sweep, {cores} threads"),
                             (f"pp{cores}", f"  per-point path (run_point), {cores} threads")):
                rep.fig(f"csweep.{tag}.{k}", f"{periods:g} orbits: {label}", tp[k], "run/s",
                        [spec.size / x for x in res[k]])
            ratio = tp[f"ts{cores}"] / tp[f"c{cores}"]
            rep.fig(f"csweep.{tag}.ratio", f"{periods:g} orbits: tethersim / C+OpenMP "
                    f"({cores} threads)", ratio, "x")
            rep.fig(f"csweep.{tag}.ratio1", f"{periods:g} orbits: tethersim / C (1 thread)",
                    tp["ts1"] / tp["c1"], "x")
            rep.fig(f"csweep.{tag}.blocks", f"{periods:g} orbits: compiled blocks / per-point "
                    f"path ({cores} threads)", tp[f"ts{cores}"] / tp[f"pp{cores}"], "x")
            rep.target(f"csweep.{tag}", f"issue 22: sweep {periods:g} orbits, tethersim >= 1x "
                       "C+OpenMP", ratio, ">=", 1.0,
                       note=f"load average {load:.1f} on {os.cpu_count()} cores")
            for who, name in (("c", "C+OpenMP"), ("ts", "run_sweep"),
                              ("mp", "map_points (no store)")):
                sc = tp[f"{who}{cores}"] / tp[f"{who}1"]
                rep.fig(f"csweep.{tag}.scale_{who}", f"{periods:g} orbits: {name} scaling 1 -> "
                        f"{cores} threads", sc, "x")
            # issue 4's target is the 50-orbit sweep's; the 5-orbit one is held to the same
            rep.target(f"csweep.{tag}.scale", f"{'issue 4: ' if periods >= 50 else ''}sweep "
                       f"{periods:g} orbits, run_sweep 1 -> {cores} threads",
                       tp[f"ts{cores}"] / tp["ts1"], ">=", 1.8 if cores >= 2 else 1.0,
                       note=f"C itself {tp[f'c{cores}'] / tp['c1']:.2f}x, tethersim without its "
                            f"store {tp[f'mp{cores}'] / tp['mp1']:.2f}x; load average "
                            f"{load:.1f} on {os.cpu_count()} cores")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    sys.stdout.flush()
