"""The 3-D model against a C port of it (`make bench`, issue 13 item 5).

The C port is printed from generated/three_d.py itself (bench/pyc.py: the same
straight-line code, in C) inside the C drivers of bench/cref.py (the RK4 and
DOP853 ports of the engine); the numba side is the engine's own compiled loops
for model '3d', chosen once as simulate() does.  SatI with a 5° roll and 3°
yaw start, so the out-of-plane terms work; 12-state (the model's own: the COM orbit is
a closed form, integrated by neither side).
"""
from __future__ import annotations

import math

import numpy as np
from timing import cpu_clock, interleave, median

MODEL = "3d"
PERIODS = 10
RK4_STEPS = 2000
RTOL, ATOL = 1e-10, 1e-12
SAMPLES_PER_PERIOD = 200


def setup(log):
    import cref

    from tethersim.engine.events import event_parameters
    from tethersim.engine.integrators.dop853 import dop853_run
    from tethersim.engine.integrators.rk4 import rk4_run
    from tethersim.engine.integrators.select import specialised
    from tethersim.model.air.vector import uniform_air
    from tethersim.model.inputs import initial_model_state, parameter_vector
    from tethersim.model.presets import load_preset
    from tethersim.model.registry import get_model

    m = get_model(MODEL)
    sat = load_preset("satI").replace(initial_3d={"phi": math.radians(5.0),
                                                  "psi": math.radians(3.0)})
    src = cref.c_source_of_generated(MODEL)
    lib = cref.CRef(cref.build(src, ("-O3",), "3d"), na=m.n_state)
    p = parameter_vector(sat, MODEL)
    y0 = initial_model_state(sat, MODEL)
    air = uniform_air()
    ev = event_parameters(sat, MODEL)
    rk4 = specialised(rk4_run, m.index, (air, 0, y0.copy(), 1.0, 1, 1, p, p.copy(), ev, False,
                                         np.empty(1), np.empty((1, y0.size)), 0))
    dop = specialised(dop853_run, m.index, (air, 0.0, 1.0, y0.copy(), 0.0, p, p.copy(), ev, RTOL,
                                            ATOL, True, np.empty(1), np.empty((1, y0.size)), 0,
                                            1, np.zeros(5, np.int64), math.inf))
    log(f"model {MODEL!r}: {m.n_state} states; C port printed from "
        f"generated/three_d.py ({len(src.splitlines())} lines of C)")
    return dict(sat=sat, m=m, p=p, y0=y0, air=air, c=lib, rk4=rk4, dop=dop, ev=ev)


def bench_3d(rep, q, log):
    """RK4 and DOP853 loops of the 3-D model: numba vs its C port, interleaved."""
    log("\n[3d] model '3d' (roll, pitch, yaw, out-of-plane balloon): numba loops vs C port; "
        "thread CPU time")
    S = setup(log)
    sat, p, y0, m = S["sat"], S["p"], S["y0"], S["m"]
    ns = y0.size
    h = PERIODS * sat.period / RK4_STEPS
    T = PERIODS * sat.period
    n_out = round(SAMPLES_PER_PERIOD * PERIODS)
    grid = np.linspace(0.0, T, n_out + 1)[1:]
    runs = {}

    def rk4_numba():
        y, ot, oy = y0.copy(), np.empty(RK4_STEPS), np.empty((RK4_STEPS, ns))
        t0 = cpu_clock()
        S["rk4"](m.index, S["air"], 0.0, y, h, RK4_STEPS, 1, p, p.copy(), S["ev"], False, ot, oy,
                 0)
        runs["rk4_numba"] = oy
        return cpu_clock() - t0

    def rk4_c():
        y, ot, oy = y0.copy(), np.empty(RK4_STEPS), np.empty((RK4_STEPS, ns))
        t0 = cpu_clock()
        S["c"].rk4_run(0.0, y, h, RK4_STEPS, 1, p, ot, oy, 0)
        runs["rk4_c"] = oy
        return cpu_clock() - t0

    def dop_numba():
        y, oy, cnt = y0.copy(), np.empty((n_out, ns)), np.zeros(5, np.int64)
        t0 = cpu_clock()
        r = S["dop"](m.index, S["air"], 0.0, T, y, 0.0, p, p.copy(), S["ev"], RTOL, ATOL, True,
                     grid, oy,
                     0, 10**9, cnt, math.inf)
        dt = cpu_clock() - t0
        runs["dop_numba"] = (oy, cnt.copy(), r[3])
        return dt

    def dop_c():
        y, oy, cnt = y0.copy(), np.empty((n_out, ns)), np.zeros(5, np.int64)
        t0 = cpu_clock()
        r = S["c"].dop853_run(0.0, T, y, 0.0, p, RTOL, ATOL, True, grid, oy, 0, 10**9, cnt)
        dt = cpu_clock() - t0
        runs["dop_c"] = (oy, cnt.copy(), r[3])
        return dt

    res = interleave({"rk4_numba": rk4_numba, "rk4_c": rk4_c, "dop_numba": dop_numba,
                      "dop_c": dop_c}, q["dop_repeats"])
    a, b = runs["rk4_numba"], runs["rk4_c"]
    diff = float(np.max(np.abs(a - b) / (np.abs(b).max(axis=0) + 1e-300)))
    roll = float(np.max(np.abs(a[:, m.state.index("phi")])))
    rep.check("3-D RK4: numba and the C port give the same trajectory", diff < 1e-9,
              f"output max diff / range {diff:.1e}; max |roll| {math.degrees(roll):.2f} deg")
    (oa, ca, sa), (ob, cb, sb) = runs["dop_numba"], runs["dop_c"]
    dense = float(np.max(np.abs(oa - ob) / (np.abs(ob).max(axis=0) + 1e-300)))
    same_steps = sa == sb == 0 and np.array_equal(ca, cb) and dense < 1e-9
    rep.check("3-D DOP853: same status, steps, switches and output as the C port", same_steps,
              f"numba {ca.tolist()}, C {cb.tolist()}; output max diff / range {dense:.1e}")
    nb = rep.fig("3d.rk4.numba", f"3-D numba rk4_run, {PERIODS} periods in {RK4_STEPS} steps",
                 median(res["rk4_numba"]), "s", res["rk4_numba"])
    c = rep.fig("3d.rk4.c", "3-D C RK4 (gcc -O3), printed from the generated kernel",
                median(res["rk4_c"]), "s", res["rk4_c"])
    r = rep.fig("3d.rk4.ratio", "3-D ratio numba / C RK4", nb / c, "x")
    rep.target("3d.rk4", "3-D RK4 loop: numba <= 1.2x its C port", r, "<=", 1.2,
               note="issue 13 item 5")
    nbd = rep.fig("3d.dop853.numba", f"3-D numba dop853_run, {PERIODS} periods",
                  median(res["dop_numba"]), "s", res["dop_numba"])
    cd = rep.fig("3d.dop853.c", "3-D C DOP853 (gcc -O3)", median(res["dop_c"]), "s", res["dop_c"])
    rd = rep.fig("3d.dop853.ratio", "3-D ratio numba / C DOP853 (same steps)", nbd / cd, "x")
    rep.target("3d.dop853", "3-D DOP853 loop: numba <= 1.2x its C port", rd, "<=", 1.2,
               note="issue 13 item 5")
