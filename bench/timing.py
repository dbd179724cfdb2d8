"""Timing helpers: interleaved repeats, medians, subprocess wall times."""
from __future__ import annotations

import gc
import os
import statistics
import subprocess
import time

clock = time.perf_counter
# CPU time of the calling thread: for single-threaded compiled loops and the C
# ports, it leaves out the time the thread waited for a core, which on a
# shared, loaded machine (load average above the core count) dominates the
# spread of wall-clock repeats; both sides of a ratio are timed with it
cpu_clock = time.thread_time


def interleave(fns: dict, repeats: int, warmup: int = 1) -> dict:
    """Run each zero-argument timer fn (returning seconds) in turn, repeats times.

    Interleaving A B A B ... rather than A A ... B B ... makes the ratio of the
    medians robust to slow drifts of machine load.  The first ``warmup`` rounds
    (compilation, caches, page faults) are discarded.
    """
    out = {name: [] for name in fns}
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for r in range(warmup + repeats):
            for name, fn in fns.items():
                dt = fn()
                if r >= warmup:
                    out[name].append(dt)
    finally:
        if gc_was:
            gc.enable()
    return out


def median(xs) -> float:
    return float(statistics.median(xs))


def spread(xs) -> float:
    """Half the interquartile range relative to the median (a noise indicator)."""
    if len(xs) < 4:
        return float("nan")
    q = statistics.quantiles(xs, n=4)
    m = statistics.median(xs)
    return (q[2] - q[0]) / 2 / m if m else float("nan")


def wall(cmd, cwd=None, env=None, timeout=600, keep=2000):
    """Wall time [s] of a subprocess, its return code and the last ``keep`` characters of
    its output."""
    e = dict(os.environ)
    if env:
        e.update(env)
    t0 = clock()
    proc = subprocess.run(cmd, cwd=cwd, env=e, capture_output=True, text=True, timeout=timeout)
    dt = clock() - t0
    tail = (proc.stdout + proc.stderr)[-keep:]
    return dt, proc.returncode, tail
