"""Engine figures of `make bench` (issue 10): the compiled loops as users call them.

  entry points  rk4_run / dop853_run of model 'derived', chosen once from Python
                (tethersim.engine.integrators.select.specialised), as simulate() does
  [2b] simulate(sat, periods=50, steps=10_000, method="rk4") with default arguments
       against the C RK4 port writing the same output rows
  [3b] simulate(sat, periods=50) (adaptive default) per accepted step against the
       C DOP853 port on the same output grid
"""
from __future__ import annotations

import math

import numpy as np
from timing import cpu_clock as clock
from timing import interleave, median

from tethersim.engine.events import N_EV
from tethersim.model.air.vector import uniform_air

MODEL = 0  # 'derived' (generated.dispatch.MODEL_NAMES), the model of the C port
PERIODS = 50
RK4_STEPS = 10_000
SAMPLES_PER_PERIOD = 200  # simulate()'s adaptive output grid


def rk4_entry(S):
    """rk4_run(model, air, k0, y, h, n_steps, stride, p, pw, ev, locate, out_t, out_y, row0)."""
    from tethersim.engine.integrators.rk4 import rk4_run
    from tethersim.engine.integrators.select import specialised
    y, p = S["y0"].copy(), S["p"]
    args = (uniform_air(), 0, y, 1.0, 1, 1, p, p.copy(), np.empty(N_EV), False, np.empty(1),
            np.empty((1, y.size)), 0)
    return specialised(rk4_run, MODEL, args)


def dop853_entry(S):
    """dop853_run(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y,
    i_out, max_steps, counters, t_pause)."""
    from tethersim.engine.integrators.dop853 import dop853_run
    from tethersim.engine.integrators.select import specialised
    y, p = S["y0"].copy(), S["p"]
    args = (uniform_air(), 0.0, 1.0, y, 0.0, p, p.copy(), np.empty(N_EV), 1e-10, 1e-12, True,
            np.empty(1),
            np.empty((1, y.size)), 0, 1, np.zeros(5, np.int64), math.inf)
    return specialised(dop853_run, MODEL, args)


def derivative_entry(S):
    """dynamics.derivative(model, air, t, y, p, pw, dydt) of model 'derived'."""
    from tethersim.engine.dynamics import derivative
    from tethersim.engine.integrators.select import specialised
    y, p = S["y0"].copy(), S["p"]
    return specialised(derivative, MODEL, (uniform_air(), 0.0, y, p, p.copy(), np.empty(y.size)))


def bench_simulate(rep, S, q, log):
    """simulate() with default arguments vs the C ports (same steps, same output)."""
    from tethersim import simulate
    sat, p, y0 = S["sat"], S["p"], S["y0"]
    log(f"\n[2b] simulate(sat, periods={PERIODS}, steps={RK4_STEPS}, method='rk4'), default "
        f"arguments, vs C RK4 writing the same {RK4_STEPS + 1} rows; thread CPU time")
    h = PERIODS * sat.period / RK4_STEPS
    out_t, out_y = np.empty(RK4_STEPS + 1), np.empty((RK4_STEPS + 1, y0.size))
    runs = {}

    def t_sim():
        t0 = clock()
        runs["rk4"] = simulate(sat, periods=PERIODS, steps=RK4_STEPS, method="rk4")
        return clock() - t0

    def t_c():
        t0 = clock()
        y = y0.copy()
        out_t[0], out_y[0] = 0.0, y
        S["c"].rk4_run(0.0, y, h, RK4_STEPS, 1, p, out_t, out_y, 1)
        return clock() - t0

    res = interleave({"simulate": t_sim, "c": t_c}, q["fast_repeats"])
    r = runs["rk4"]
    dev = float(np.max(np.abs(r.states - out_y) / (np.abs(out_y).max(axis=0) + 1e-300)))
    rep.check("simulate(rk4) default and C RK4: one integration, same trajectory",
              r.error_estimate is None and r.n_accepted == RK4_STEPS and dev < 1e-9,
              f"max diff / range {dev:.1e}")
    sim = rep.fig("simulate.rk4", "simulate(rk4, 50 periods, 10,000 steps), default args",
                  median(res["simulate"]), "s", res["simulate"])
    c = rep.fig("simulate.c_rk4", "C RK4 (gcc -O3), same output rows", median(res["c"]), "s",
                res["c"])
    ratio = rep.fig("simulate.ratio_rk4_c", "ratio simulate(rk4) / C RK4", sim / c, "x")
    rep.target("T2b", "2b. simulate(rk4) default args <= 1.3x C RK4", ratio, "<=", 1.3)

    log(f"\n[3b] simulate(sat, periods={PERIODS}) (adaptive, default arguments) per accepted "
        f"step, vs C DOP853 on the same output grid; thread CPU time")
    n_out = SAMPLES_PER_PERIOD * PERIODS
    T = PERIODS * sat.period
    grid = np.linspace(0.0, T, n_out + 1)[1:]
    c_out = np.empty((n_out, y0.size))
    counts = {}

    def t_sim_a():
        t0 = clock()
        runs["adaptive"] = simulate(sat, periods=PERIODS)
        return clock() - t0

    def t_c_a():
        cnt = np.zeros(5, np.int64)
        y = y0.copy()
        t0 = clock()
        S["c"].dop853_run(0.0, T, y, 0.0, p, 1e-10, 1e-12, True, grid, c_out, 0, 10**9, cnt)
        dt = clock() - t0
        counts["c"] = cnt
        return dt

    res = interleave({"simulate": t_sim_a, "c": t_c_a}, q["dop_repeats"])
    r = runs["adaptive"]
    acc_c = int(counts["c"][1])
    rep.check("simulate(adaptive) default and C DOP853: one integration, same accepted steps",
              r.error_estimate is None and r.n_accepted == acc_c,
              f"accepted {r.n_accepted} vs {acc_c}")
    sim = rep.fig("simulate.adaptive_per_step", "simulate(50 periods) default, per accepted step",
                  median(res["simulate"]) / r.n_accepted, "s", res["simulate"])
    c = rep.fig("simulate.c_dop853_per_step", "C DOP853 (gcc -O3), per accepted step",
                median(res["c"]) / acc_c, "s", res["c"])
    ratio = rep.fig("simulate.ratio_adaptive_c", "ratio simulate(adaptive) / C DOP853, per step",
                    sim / c, "x")
    rep.target("T3c", "3c. simulate(adaptive) default per accepted step <= 1.3x C DOP853",
               ratio, "<=", 1.3)
