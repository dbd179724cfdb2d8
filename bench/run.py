"""Speed figures of tethersim (`make bench`): `.venv/bin/python bench/run.py [--quick]`.

Every figure is the median of repeats taken after a warm-up (compilation,
caches); ratios are computed from figures measured in this same run, with the
two sides of a ratio interleaved (A B A B ...).  The C reference is generated
from the same derivation at run time (bench/cref.py -> bench/_build/) and built
with gcc -O3.  Results go to stdout (table at the end) and bench/results.json.

  1. one call of the generated 6-state RHS: numba (in an @njit loop) vs C (in a
     C loop) vs sympy.lambdify + numpy and PyDy (called from Python)
  2. RK4, 50 periods in 10,000 steps, 6-state: numba rk4_run vs C
     (2b: simulate() with default arguments vs C, bench/engine_bench.py)
  3. DOP853 rtol 1e-10 atol 1e-12, 50 periods: numba dop853_run vs C port vs
     scipy solve_ivp(DOP853) driving the compiled RHS through a Python wrapper
     (3b: simulate() adaptive default per accepted step vs C, bench/engine_bench.py);
     `--only core` runs 2, 2b, 3 and 3b alone
  4. sympy.lambdify + solve_ivp and PyDy + solve_ivp, same model and tolerance
  5. `python -m derive <tmpdir>` wall time
  6. second `tethersim run satI --periods 50` wall time (numba caches warm), and a
     cold first `tethersim run satI --periods 1 --no-plots` with an empty cache folder
     (TETHERSIM_CACHE_DIR); `--only cli` runs this section alone
  7. sweeps: a C+OpenMP sweep driver vs run_sweep at 5 and 50 orbits, 1 and 2 threads
     (the thread scaling, with the store and without it), and run_sweep through the
     per-point path (bench/csweep.py); `--only sweep` runs this section alone
  8. `tethersim report` wall time (not with --quick)
  9. against heyoka.py (bench/peers.py, when heyoka is installed: the [bench] extra):
     single runs at equal accuracy (work-precision, three cases) and sweep throughput
     against its SIMD batches; `--only peers` runs this section alone
 10. faithful sweeps on SIMD lanes vs the point-by-point block, 64 and 144 points, 1 and
     2 threads (bench/lanes_bench.py); `--only lanes` runs this section alone
 11. real tethers (bench/stiff.py): SatI on 1 mm Dyneema lines, tethersim's Radau IIA
     against the explicit C DOP853 port at equal accuracy, and against the
     thesis-tether run of the same length; `--only stiff` runs this section alone
 12. plans of many of the 3-D, free-orbit and NRLMSISE-00-air models against bare
     compiled runs of the same points, and their 1 -> 2 thread scaling
     (bench/models_sweep.py, issue 20); `--only models` runs this section alone
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
for path in (str(HERE), str(REPO)):
    if path not in sys.path:
        sys.path.insert(0, path)

import numpy as np  # noqa: E402
from speedpage import fmt as _fmt  # noqa: E402
from timing import clock, cpu_clock, interleave, median, spread, wall  # noqa: E402

from tethersim.engine.events import event_parameters  # noqa: E402

RTOL, ATOL = 1e-10, 1e-12
PERIODS = 50
RK4_STEPS = 10_000
SAMPLES_PER_PERIOD = 200  # the CLI's adaptive output grid


def _uniform_air():
    from tethersim.model.air.vector import uniform_air
    return uniform_air()


def log(msg=""):
    print(msg, flush=True)


class Report:
    """Figures, targets and sanity checks, printed as a table and saved as JSON."""

    def __init__(self):
        self.figures = {}
        self.targets = []
        self.checks = []
        self.notes = []

    def fig(self, key, label, value, unit, samples=None, note=""):
        d = {"label": label, "value": value, "unit": unit}
        if samples is not None:
            d["n"] = len(samples)
            d["spread"] = spread(samples)
            d["samples"] = [float(s) for s in samples]
        if note:
            d["note"] = note
        self.figures[key] = d
        shown = _fmt(value, unit)
        extra = f"  (n={len(samples)}, ±{100 * d['spread']:.0f}%)" if samples is not None and \
            len(samples) >= 4 else (f"  (n={len(samples)})" if samples is not None else "")
        log(f"    {label:<62} {shown:>14}{extra}")
        return value

    def target(self, key, label, value, op, limit, unit="x", note=""):
        if op == "info":
            ok = None
        elif value is None or (isinstance(value, float) and not math.isfinite(value)):
            ok = None
        else:
            ok = value <= limit if op == "<=" else value >= limit if op == ">=" else value < limit
        self.targets.append({"key": key, "label": label, "value": value, "op": op,
                             "limit": limit, "unit": unit,
                             "status": "info" if op == "info" else
                             "SKIP" if ok is None else ("PASS" if ok else "MISS"),
                             "note": note})
        return ok

    def check(self, label, ok, detail=""):
        self.checks.append({"label": label, "ok": bool(ok), "detail": detail})
        log(f"    check: {label}: {'ok' if ok else 'FAILED'}{'  ' + detail if detail else ''}")


# --------------------------------------------------------------------------- setup
def load_satellite():
    """The SatI preset; the /tmp/t1.py satellite if presets are not available."""
    try:
        from tethersim.model.presets import load_preset
        return load_preset("satI"), "preset satI"
    except Exception as exc:  # noqa: BLE001
        from tethersim.model.satellite import Satellite
        sat = Satellite("t", m1=10, m2=105, m3=1, A1=0.25, A2=1.0, A3=11.4, a=1.0, b=10.5,
                        l10=6, l20=6, E1=0.004, E2=0.042, c1=0.01, c2=0.01, altitude=200e3,
                        initial=(28.0, 0, math.pi / 6, 0, 0, 0))
        return sat, f"fallback satellite (presets unavailable: {exc})"


def setup(rep: Report):
    import cref

    from tethersim.model.inputs import initial_model_state, parameter_vector

    sat, what = load_satellite()
    log(f"satellite: {sat.name} ({what}); period {sat.period:.1f} s")
    t0 = clock()
    model, length_defs = cref.derived_model()
    t_derive = clock() - t0
    t0 = clock()
    _, info = cref.derived_source()
    t_src = clock() - t0
    current = cref.generated_is_current(model, length_defs, REPO / "generated" / "derived.py")
    t0 = clock()
    lib_o3, lib_nat = cref.port("O3"), cref.port("native")
    t_gcc = clock() - t0
    log(f"derivation of 'derived' {t_derive:.1f} s, C source {t_src:.1f} s "
        f"({info['cse_temporaries']} cse temporaries, same cse as derive.codegen), "
        f"gcc {t_gcc:.1f} s -> {lib_o3.path.relative_to(REPO)}")
    rep.check("generated/derived.py rhs is what derive/codegen.py prints now", current,
              "" if current else "generated/ is stale: numba and C kernels differ; run make derive")
    p = parameter_vector(sat, "derived")
    y0 = initial_model_state(sat, "derived")
    S = dict(sat=sat, model=model, length_defs=length_defs, c=lib_o3, c_native=lib_nat,
             p=p, y0=y0, setup_s={"derive": t_derive, "c_source": t_src, "gcc": t_gcc})
    # model 'derived', uniform density: its compiled loops, chosen once as simulate() does
    import engine_bench
    S.update(rk4=engine_bench.rk4_entry(S), dop853=engine_bench.dop853_entry(S),
             derivative=engine_bench.derivative_entry(S))
    return S


def validate_rhs(rep: Report, S, lamb, pydy_f):
    """The kernels being compared compute the same numbers (incl. slack tethers)."""
    from tethersim.generated.derived import rhs
    rng = np.random.default_rng(1)
    p, y0 = S["p"], S["y0"]
    err_c, err_l, err_py, slack = 0.0, 0.0, 0.0, 0
    for _ in range(40):
        y = y0 + rng.normal(size=6) * np.array([8.0, 3.0, 0.6, 0.05, 0.05, 1e-3])
        d = np.empty(6)
        rhs(0.0, y, p, d)
        scale = np.abs(d[3:]).max()
        err_c = max(err_c, np.abs(S["c"].rhs6(y, p)[3:] - d[3:]).max() / scale)
        err_l = max(err_l, np.abs(np.array(lamb(*y.tolist(), *p.tolist()), float)[3:]
                                  - d[3:]).max() / scale)
        g = _tether_margins(y, p)
        if pydy_f is None:
            pass
        elif (g > 0).all():
            err_py = max(err_py, np.abs(pydy_f(y, 0.0, p)[3:] - d[3:]).max() / scale)
        else:
            slack += 1
    rep.check("C rhs == numba rhs (40 random states)", err_c < 1e-12, f"max rel diff {err_c:.1e}")
    rep.check("lambdify rhs == numba rhs (40 random states)", err_l < 1e-12,
              f"max rel diff {err_l:.1e}")
    if pydy_f is not None:
        rep.check("PyDy rhs == numba rhs (taut states)", err_py < 1e-12,
                  f"max rel diff {err_py:.1e}; {slack} of 40 states had a slack tether")


def _tether_margins(y, p):
    from tethersim.generated.derived import tether_margins  # the model of the C port
    g = np.empty(2)
    tether_margins(np.ascontiguousarray(y, dtype=float), p, g)
    return g


# --------------------------------------------------------------------------- 1
def bench_rhs(rep: Report, S, q, lamb, pydy_f, pydy_gen):
    import nbloops

    from tethersim.generated.derived import rhs
    log("\n[1] one call of the generated 6-state RHS (generated.derived.rhs)")
    p, y6 = S["p"], S["y0"].copy()
    n, eps = q["rhs_calls"], 1e-6
    pw = S["p"].copy()
    accs = {}

    def loop(name, fn, y):
        def timer():
            yy = y.copy()
            t0 = clock()
            accs[name] = fn(yy)
            return (clock() - t0) / n
        return timer

    res = interleave({
        "numba": loop("numba", lambda yy: nbloops.rhs6_loop(yy, p, n, eps), y6),
        "c": loop("c", lambda yy: S["c"].rhs6_loop(yy, p, n, eps), y6),
        "c_native": loop("c_native", lambda yy: S["c_native"].rhs6_loop(yy, p, n, eps), y6),
        "numba_deriv": loop("numba_deriv",
                            lambda yy: nbloops.derivative_loop(yy, p, pw, n, eps), y6),
        "c_deriv": loop("c_deriv", lambda yy: S["c"].derivative_loop(yy, p, n, eps), y6),
    }, q["fast_repeats"])
    rel = abs(accs["numba"] - accs["c"]) / abs(accs["c"])
    rep.check("numba and C loops compute the same trajectory", rel < 1e-9,
              f"checksum rel diff {rel:.1e}")
    nb = rep.fig("rhs.numba", f"numba rhs, per call in an @njit loop ({n} calls)",
                 median(res["numba"]), "s", res["numba"])
    c = rep.fig("rhs.c", "C rhs (gcc -O3), per call in a C loop", median(res["c"]), "s", res["c"])
    cn = rep.fig("rhs.c_native", "C rhs (gcc -O3 -march=native), per call",
                 median(res["c_native"]), "s", res["c_native"])
    nbd = rep.fig("rhs.numba_deriv", "numba tethersim.engine.dynamics.derivative (6-state, "
                  "model literal)", median(res["numba_deriv"]), "s", res["numba_deriv"])
    cd = rep.fig("rhs.c_deriv", "C derivative (6-state), gcc -O3",
                 median(res["c_deriv"]), "s", res["c_deriv"])

    # called from Python, one call at a time
    yl, pl = y6.tolist(), p.tolist()
    d = np.empty(6)
    n_l, n_py, n_nb = q["lambdify_calls"], q["pydy_calls"], q["pycall_calls"]

    def per_call(fn, m):
        def timer():
            t0 = clock()
            for _ in range(m):
                fn()
            return (clock() - t0) / m
        return timer

    timers = {"lambdify": per_call(lambda: lamb(*yl, *pl), n_l),
              "numba_py": per_call(lambda: rhs(0.0, y6, p, d), n_nb)}
    if pydy_f is not None:
        timers["pydy"] = per_call(lambda: pydy_f(y6, 0.0, p), n_py)
    res2 = interleave(timers, q["fast_repeats"])
    lam = rep.fig("rhs.lambdify", "sympy.lambdify(numpy) rhs, per call from Python",
                  median(res2["lambdify"]), "s", res2["lambdify"])
    nbp = rep.fig("rhs.numba_pycall", "numba rhs called from Python (dispatch overhead incl.)",
                  median(res2["numba_py"]), "s", res2["numba_py"])
    r1 = rep.fig("rhs.ratio_numba_c", "ratio numba / C -O3", nb / c, "x")
    rep.fig("rhs.ratio_numba_c_native", "ratio numba / C -O3 -march=native", nb / cn, "x")
    rep.fig("rhs.ratio_deriv_numba_c", "ratio numba / C, 6-state derivative", nbd / cd, "x")
    rep.fig("rhs.ratio_lambdify_numba", "ratio lambdify / numba (in-loop)", lam / nb, "x")
    rep.target("T1", "1. RHS call: numba <= 2x C (gcc -O3)", r1, "<=", 2.0)
    if pydy_f is None:
        return
    py = rep.fig("rhs.pydy", f"PyDy generate_ode_function ({pydy_gen}), per call from Python",
                 median(res2["pydy"]), "s", res2["pydy"])
    rp = rep.fig("rhs.ratio_pydy_numba", "ratio PyDy / numba (in-loop)", py / nb, "x")
    rp2 = rep.fig("rhs.ratio_pydy_numba_pycall", "ratio PyDy / numba (both called from Python)",
                  py / nbp, "x")
    rep.target("T4c", "4. RHS call: PyDy / numba (report only)", rp, "info", 0,
               note=f"{rp2:.1f}x when both are called from Python")
    return {"numba_in_loop": nb}


# --------------------------------------------------------------------------- 2
def bench_rk4(rep: Report, S, q):
    rk4_run, AIR = S["rk4"], _uniform_air()
    log(f"\n[2] RK4, {PERIODS} periods in {RK4_STEPS} steps, 6-state (the model's own); "
        "thread CPU time")
    sat, p, y0 = S["sat"], S["p"], S["y0"]
    pw = p.copy()
    ev = event_parameters(sat, "derived")
    N = RK4_STEPS
    h = PERIODS * sat.period / N
    bufs = {k: (np.empty(N), np.empty((N, y0.size))) for k in ("numba", "c", "c_native")}
    finals = {}

    def timer(name, fn):
        out_t, out_y = bufs[name]

        def t():
            y = y0.copy()
            t0 = cpu_clock()
            r = fn(y, out_t, out_y)
            dt = cpu_clock() - t0
            finals[name] = (y, r)
            return dt
        return t

    res = interleave({
        "numba": timer("numba", lambda y, ot, oy: rk4_run(0, AIR, 0, y, h, N, 1, p, pw, ev,
                                                           False, ot, oy, 0)),
        "c": timer("c", lambda y, ot, oy: S["c"].rk4_run(0.0, y, h, N, 1, p, ot, oy, 0)),
        "c_native": timer("c_native", lambda y, ot, oy: S["c_native"].rk4_run(
            0.0, y, h, N, 1, p, ot, oy, 0)),
    }, q["fast_repeats"])
    yn, rn = finals["numba"]
    yc, rc = finals["c"]
    rel = float(np.max(np.abs(yn - yc) / (np.abs(yc) + 1e-300)))
    same_out = float(np.max(np.abs(bufs["numba"][1] - bufs["c"][1])
                            / (np.abs(bufs["c"][1]).max(axis=0) + 1e-300)))
    rep.check("RK4 numba and C: same status/rows and same trajectory",
              rn[0] == rc[0] and rn[2] == rc[2] == 0 and same_out < 1e-9,
              f"rows {rn[0]}/{rc[0]}, final state max rel diff {rel:.1e}, "
              f"output max diff / range {same_out:.1e}")
    nb = rep.fig("rk4.numba", "numba rk4_run (whole loop compiled)", median(res["numba"]), "s",
                 res["numba"])
    c = rep.fig("rk4.c", "C RK4 (gcc -O3), same cse'd RHS", median(res["c"]), "s", res["c"])
    cn = rep.fig("rk4.c_native", "C RK4 (gcc -O3 -march=native)", median(res["c_native"]), "s",
                 res["c_native"])
    rep.fig("rk4.numba_per_eval", "numba: time per RHS evaluation (4 per step)", nb / (4 * N), "s")
    rep.fig("rk4.c_per_eval", "C: time per RHS evaluation", c / (4 * N), "s")
    r = rep.fig("rk4.ratio_numba_c", "ratio numba / C -O3", nb / c, "x")
    rep.fig("rk4.ratio_numba_c_native", "ratio numba / C -O3 -march=native", nb / cn, "x")
    rep.target("T2", "2. RK4 50 periods: numba <= 1.2x C (gcc -O3)", r, "<=", 1.2)


# --------------------------------------------------------------------------- 3, 4
def dop853_numba(S, periods, locate=True):
    """One numba dop853_run from t=0 over `periods`; returns (seconds, counters, y, out_y)."""
    dop853_run, AIR = S["dop853"], _uniform_air()
    sat, p, y0 = S["sat"], S["p"], S["y0"]
    T = periods * sat.period
    n_out = max(2, round(SAMPLES_PER_PERIOD * periods))
    out_t = np.linspace(0.0, T, n_out + 1)[1:]
    out_y = np.empty((n_out, y0.size))
    y = y0.copy()
    cnt = np.zeros(5, dtype=np.int64)
    pw = p.copy()
    t0 = cpu_clock()
    r = dop853_run(0, AIR, 0.0, T, y, 0.0, p, pw, event_parameters(sat, "derived"), RTOL, ATOL,
                   locate, out_t, out_y, 0, 10**9, cnt, math.inf)
    dt = cpu_clock() - t0
    assert r[3] == 0, r
    return dt, cnt, y, out_y


def dop853_c(S, lib, periods, locate=True):
    """The C port's dop853_run over the span and grid of dop853_numba."""
    import cref
    return cref.timed_dop853(lib, S["y0"], S["p"], periods * S["sat"].period,
                             max(2, round(SAMPLES_PER_PERIOD * periods)), RTOL, ATOL, locate)


def solve_ivp_run(S, fun, periods):
    from scipy.integrate import solve_ivp
    T = periods * S["sat"].period
    t0 = cpu_clock()
    sol = solve_ivp(fun, (0.0, T), S["y0"].copy(), method="DOP853", rtol=RTOL, atol=ATOL)
    dt = cpu_clock() - t0
    assert sol.status == 0, sol.message
    return dt, sol


def bench_dop853(rep: Report, S, q):
    import baselines
    log(f"\n[3] adaptive DOP853 rtol {RTOL:g} atol {ATOL:g}, {PERIODS} periods, 6-state, "
        f"switch location on, dense output on {SAMPLES_PER_PERIOD} samples/period")
    finals = {}

    def t(name, fn):
        def timer():
            dt, cnt, y, oy = fn()
            finals[name] = (cnt, y, oy)
            return dt
        return timer

    res = interleave({
        "numba": t("numba", lambda: dop853_numba(S, PERIODS)),
        "c": t("c", lambda: dop853_c(S, S["c"], PERIODS)),
        "c_native": t("c_native", lambda: dop853_c(S, S["c_native"], PERIODS)),
    }, q["dop_repeats"])
    cn_, yn, oyn = finals["numba"]
    cc_, yc, oyc = finals["c"]
    same_counts = bool(np.array_equal(cn_, cc_))
    dev = float(np.max(np.abs(oyn - oyc) / (np.abs(oyc).max(axis=0) + 1e-300)))
    rep.check("DOP853 numba and C: identical nfev/accepted/rejected/switches/steps",
              same_counts, f"numba {cn_.tolist()}, C {cc_.tolist()}")
    rep.check("DOP853 numba and C: same dense output", dev < 1e-8,
              f"max diff / range {dev:.1e}")
    nb = rep.fig("dop853.numba", "numba dop853_run (whole loop compiled)", median(res["numba"]),
                 "s", res["numba"])
    c = rep.fig("dop853.c", "C DOP853 port (gcc -O3), same tableau/control/dense output",
                median(res["c"]), "s", res["c"])
    cnat = rep.fig("dop853.c_native", "C DOP853 port (gcc -O3 -march=native)",
                   median(res["c_native"]), "s", res["c_native"])
    rep.fig("dop853.nfev", "nfev (numba counter; C identical)", int(cn_[0]), "count")
    rep.fig("dop853.accepted", "accepted steps", int(cn_[1]), "count")
    rep.fig("dop853.rejected", "rejected steps", int(cn_[2]), "count")
    rep.fig("dop853.switches", "tether switches located", int(cn_[3]), "count")
    rep.fig("dop853.numba_per_eval", "numba: time per RHS evaluation (incl. stepper)",
            nb / cn_[0], "s")
    rep.fig("dop853.c_per_eval", "C: time per RHS evaluation (incl. stepper)", c / cc_[0], "s")
    r = rep.fig("dop853.ratio_numba_c", "ratio numba / C -O3", nb / c, "x")
    rep.fig("dop853.ratio_numba_c_native", "ratio numba / C -O3 -march=native", nb / cnat, "x")
    rep.target("T3a", "3. DOP853 50 periods: numba <= 1.2x C port (gcc -O3)", r, "<=", 1.2)
    S["dop_counts_full"] = cn_
    S["dop_numba_full"] = nb
    # all tethers taut throughout? (validates PyDy's taut-branch forcing below)
    taut = all((_tether_margins(row, S["p"]) > 0).all() for row in oyn[:: max(1, len(oyn) // 500)])
    S["always_taut"] = taut and cn_[3] == 0

    # scipy solve_ivp driving the compiled RHS
    k = q["scipy_numba_periods"]
    fun = baselines.ivp_fun_numba(S["derivative"], S["p"])
    solve_ivp_run(S, fun, 0.05)  # warm-up (dispatcher type resolution)
    sols = {}

    def t_ivp():
        dt, sol = solve_ivp_run(S, fun, k)
        sols["s"] = sol
        return dt

    if k == PERIODS:
        res_s = interleave({"scipy": t_ivp}, q["slow_repeats"], warmup=0)
        ref_nb, ref_cnt = nb, cn_
    else:
        res_s = interleave({"scipy": t_ivp, "numba": lambda: dop853_numba(S, k)[0]},
                           q["slow_repeats"], warmup=0)
        ref_nb = median(res_s["numba"])
        ref_cnt = dop853_numba(S, k)[1]
    sol = sols["s"]
    n_acc = len(sol.t) - 1
    rep.check(f"solve_ivp(DOP853) takes the same steps as dop853_run ({k:g} periods)",
              abs(n_acc - ref_cnt[1]) <= 2 + 0.002 * ref_cnt[1],
              f"accepted {n_acc} vs {int(ref_cnt[1])}; scipy nfev {sol.nfev} (no dense-output "
              f"stages) vs {int(ref_cnt[0])}")
    sc = median(res_s["scipy"])
    label = f"scipy solve_ivp(DOP853) + numba derivative via Python wrapper, {k:g} periods"
    rep.fig("dop853.scipy_numba_rhs", label, sc, "s", res_s["scipy"])
    if k != PERIODS:
        rep.fig("dop853.numba_same_run", f"numba dop853_run, same {k:g} periods", ref_nb, "s",
                res_s["numba"])
        est = sc * (S["dop_counts_full"][4] + S["dop_counts_full"][2]) / (ref_cnt[4] + ref_cnt[2])
        rep.fig("dop853.scipy_numba_rhs_est50", f"  scaled to {PERIODS} periods by step count "
                "(estimate)", est, "s")
    rs = rep.fig("dop853.ratio_scipy_numba", "ratio solve_ivp / numba dop853_run (same run)",
                 sc / ref_nb, "x")
    rep.target("T3b", "3. DOP853: numba >= 50x faster than solve_ivp (same RHS)", rs, ">=", 50.0,
               note="" if k == PERIODS else f"measured on {k:g} periods")


def bench_tools(rep: Report, S, q, lamb, pydy_f, pydy_gen):
    import baselines
    k = q["slow_periods"]
    log(f"\n[4] the tools people use instead: same model, DOP853 rtol {RTOL:g}, "
        f"{k:g} period(s) (too slow for {PERIODS}; scaled by step count)")
    if not S.get("always_taut"):
        rep.notes.append("a tether went slack in the 50-period run: the PyDy run (taut-branch "
                         "forcing) is not the same dynamics")
    fl = baselines.ivp_fun_lambdify(lamb, S["p"])
    sols = {}

    def t(name, fun):
        def timer():
            dt, sol = solve_ivp_run(S, fun, k)
            sols[name] = sol
            return dt
        return timer

    timers = {"lambdify": t("lambdify", fl), "numba": lambda: dop853_numba(S, k)[0]}
    if pydy_f is not None:
        timers["pydy"] = t("pydy", baselines.ivp_fun_pydy(pydy_f, S["p"]))
    res = interleave(timers, q["slow_repeats"], warmup=1)
    _, cnt, y_nb, _ = dop853_numba(S, k)
    for name in sols:
        yk = sols[name].y[:, -1]
        rel = float(np.max(np.abs(yk[:6] - y_nb[:6]) / (np.abs(y_nb[:6]) + 1e-3)))
        rep.check(f"{name} + solve_ivp end state == numba dop853_run end state", rel < 1e-6,
                  f"max rel diff {rel:.1e}; accepted {len(sols[name].t) - 1} vs {int(cnt[1])}")
    nb = rep.fig("tools.numba", f"numba dop853_run, {k:g} period(s)", median(res["numba"]), "s",
                 res["numba"])
    lam = rep.fig("tools.lambdify", f"sympy.lambdify + solve_ivp(DOP853), {k:g} period(s)",
                  median(res["lambdify"]), "s", res["lambdify"])
    full = S["dop_counts_full"]
    scale = (full[4] + full[2]) / (cnt[4] + cnt[2])
    rep.fig("tools.lambdify_est50", f"  lambdify run scaled to {PERIODS} periods (estimate)",
            lam * scale, "s")
    rl = rep.fig("tools.ratio_lambdify_numba", "ratio lambdify+solve_ivp / numba (same run)",
                 lam / nb, "x")
    rep.target("T4a", "4. numba >= 100x faster than lambdify + solve_ivp", rl, ">=", 100.0,
               note=f"measured on {k:g} period(s)")
    if pydy_f is None:
        rep.target("T4b", "4. integrated run: PyDy+solve_ivp / numba (report only)", None,
                   "info", 0, note="skipped: PyDy not installed")
        return
    py = rep.fig("tools.pydy", f"PyDy ({pydy_gen}) + solve_ivp(DOP853), {k:g} period(s)",
                 median(res["pydy"]), "s", res["pydy"])
    rep.fig("tools.pydy_est50", f"  PyDy run scaled to {PERIODS} periods (estimate)",
            py * scale, "s")
    rp = rep.fig("tools.ratio_pydy_numba", "ratio PyDy+solve_ivp / numba (same run)", py / nb, "x")
    rep.target("T4b", "4. integrated run: PyDy+solve_ivp / numba (report only)", rp, "info", 0,
               note=f"measured on {k:g} period(s), PyDy generator {pydy_gen}, "
                    "taut-branch forcing")


# --------------------------------------------------------------------------- 5, 6
def bench_derive(rep: Report, q):
    log("\n[5] make derive: python -m derive <tmpdir> (subprocess, all 4 models)")
    times = []
    for _ in range(q["derive_repeats"]):
        with tempfile.TemporaryDirectory() as tmp:
            dt, rc, tail = wall([sys.executable, "-m", "derive", tmp], cwd=REPO)
        if rc != 0:
            rep.check("python -m derive succeeded", False, tail[-300:])
            rep.target("T5", "5. make derive < 60 s", None, "<", 60.0, "s")
            return
        times.append(dt)
    v = rep.fig("derive.wall", "python -m derive <tmpdir> wall time", median(times), "s", times)
    rep.target("T5", "5. make derive < 60 s", v, "<", 60.0, "s",
               note=f"median of {len(times)}")


WARM_LABEL = "6. second CLI run <= 2.5 s (issue 10)"


def bench_cli(rep: Report, q):
    log("\n[6] CLI: tethersim run satI --periods 50 (second run, numba caches warm)")
    exe = Path(sys.executable).parent / "tethersim"
    if not exe.exists():
        exe = shutil.which("tethersim")
    try:
        from tethersim.model.presets import load_preset
        load_preset("satI")
        have = exe is not None
    except Exception:  # noqa: BLE001
        have = False
    if not have:
        log("    skipped: CLI not available")
        rep.target("T6", WARM_LABEL, None, "<=", 2.5, "s",
                   note="skipped: CLI not available")
        return
    with tempfile.TemporaryDirectory() as tmp:
        # issue 10: the first run after install compiles every kernel it calls
        dt, rc, tail = wall([str(exe), "run", "satI", "--periods", "1", "--no-plots", "--out",
                             tmp + "/cold"], cwd=tmp, env={"TETHERSIM_CACHE_DIR": tmp + "/cache"})
        log(f"    cold run (empty cache folder), --periods 1 --no-plots: {dt:.1f} s")
        rep.check("cold tethersim run succeeded", rc == 0, tail[-300:] if rc else "")
        cold = rep.fig("cli.cold", "cold first run --periods 1 --no-plots (empty cache)", dt, "s")
        rep.target("T6c", "6. cold first CLI run <= 20 s (issue 10)", cold if rc == 0 else None,
                   "<=", 20.0, "s", note="" if rc == 0 else "cold run failed")
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [str(exe), "run", "satI", "--periods", "50", "--out", tmp + "/out"]
        for i in range(1 + q["cli_repeats"]):
            dt, rc, tail = wall(cmd, cwd=tmp)
            if rc != 0:
                rep.check("tethersim run succeeded", False, tail[-300:])
                rep.target("T6", WARM_LABEL, None, "<=", 2.5, "s",
                           note="CLI run failed")
                return
            times.append(dt)
            log(f"    run {i + 1}: {dt:.2f} s")
        phases = None
        if q["cli_phases"]:
            dt, rc, tail = wall([sys.executable, str(HERE / "cli_phases.py"), tmp + "/ph"],
                                cwd=REPO)
            if rc == 0:
                phases = json.loads(tail.strip().splitlines()[-1])
                phases["process wall time (incl. interpreter start)"] = dt
    rep.fig("cli.first", "first run (may load or build numba caches)", times[0], "s")
    second = rep.fig("cli.second", "second run", times[1], "s")
    if len(times) > 2:
        rep.fig("cli.warm_median", "median of the warm runs (2nd onwards)", median(times[1:]), "s",
                times[1:])
    rep.target("T6", WARM_LABEL, second, "<=", 2.5, "s",
               note=f"warm-run median {median(times[1:]):.2f} s over {len(times) - 1}")
    if phases:
        log("    where a warm run spends its time (bench/cli_phases.py, one fresh process):")
        for k, v in phases.items():
            log(f"      {k:<62} {v:7.3f} s")
        rep.figures["cli.phases"] = {"label": "phases of a warm run (diagnostic)",
                                     "value": phases, "unit": "s"}


# --------------------------------------------------------------------------- main
def bench_peers(rep: Report, q) -> None:
    """heyoka.py at equal accuracy (bench/peers.py), if it is installed."""
    try:
        import heyoka  # noqa: F401
    except ImportError as exc:
        rep.notes.append(f"heyoka figures skipped: {exc} (make bench installs the [bench] extra)")
        return
    import peers
    log("heyoka.py: single runs at equal accuracy, then sweeps against its SIMD batches")
    peers.bench_single(rep, q, log)
    peers.bench_sweep(rep, q, log)


def machine_info():
    cpu = ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import numba
    import scipy
    import sympy
    gcc = subprocess.run(["gcc", "--version"], capture_output=True, text=True).stdout
    try:
        import pydy
        pydy_v = pydy.__version__
    except ImportError:
        pydy_v = None
    return {"cpu": cpu, "cores": os.cpu_count(), "python": platform.python_version(),
            "numpy": np.__version__, "numba": numba.__version__, "scipy": scipy.__version__,
            "sympy": sympy.__version__, "pydy": pydy_v,
            "gcc": gcc.splitlines()[0] if gcc else None,
            "loadavg_start": os.getloadavg()}


def print_table(rep: Report, total_s, out_json):
    log("\n" + "=" * 100)
    log("SUMMARY (medians; ratios from this run)")
    log("=" * 100)
    keys = [
        ("rhs.numba", "rhs.c", "rhs.ratio_numba_c"),
        ("rk4.numba", "rk4.c", "rk4.ratio_numba_c"),
        ("dop853.numba", "dop853.c", "dop853.ratio_numba_c"),
    ]
    log(f"{'':34}{'numba':>14}{'C gcc -O3':>14}{'ratio':>10}{'C -march=native':>18}")
    names = {"rhs": "6-state RHS, per call", "rk4": "RK4 50 periods, 10k steps",
             "dop853": "DOP853 50 periods, rtol 1e-10"}
    for a, b, r in keys:
        sec = a.split(".")[0]
        f = rep.figures
        if a in f:
            log(f"{names[sec]:<34}{_fmt(f[a]['value'], 's'):>14}{_fmt(f[b]['value'], 's'):>14}"
                f"{_fmt(f[r]['value'], 'x'):>10}{_fmt(f[sec + '.c_native']['value'], 's'):>18}")
    f = rep.figures
    log("")
    other = [("rhs.lambdify", "sympy.lambdify RHS call (Python)"),
             ("rhs.pydy", "PyDy RHS call (Python)"),
             ("rhs.numba_pycall", "numba RHS called from Python"),
             ("dop853.scipy_numba_rhs", "solve_ivp + numba RHS"),
             ("tools.lambdify", "lambdify + solve_ivp"), ("tools.pydy", "PyDy + solve_ivp"),
             ("tools.numba", "numba dop853_run (same short run)"),
             ("derive.wall", "python -m derive"), ("cli.second", "tethersim run, 2nd")]
    for k, label in other:
        if k in f:
            lab = f[k]["label"]
            extra = ""
            for tag in (" periods", " period(s)"):
                if tag in lab:
                    extra = " [" + lab.rsplit(",", 1)[-1].strip() + "]"
            log(f"  {label + extra:<60}{_fmt(f[k]['value'], f[k]['unit']):>14}")
    log("")
    log(f"{'target':<62}{'measured':>12}{'limit':>12}  status")
    for t in rep.targets:
        lim = ("" if t["op"] == "info" else f"{t['op']} {_fmt(t['limit'], t['unit'])}")
        val = _fmt(t["value"], t["unit"])
        status = "info" if t["op"] == "info" else t["status"]
        note = f"  ({t['note']})" if t["note"] else ""
        log(f"{t['label']:<62}{val:>12}{lim:>12}  {status}{note}")
    bad = [c for c in rep.checks if not c["ok"]]
    log(f"\nsanity checks: {len(rep.checks) - len(bad)}/{len(rep.checks)} ok"
        + "".join(f"\n  FAILED: {c['label']}: {c['detail']}" for c in bad))
    for n in rep.notes:
        log(f"note: {n}")
    la = os.getloadavg()
    log(f"bench wall time {total_s:.0f} s (load average now {la[0]:.2f}: other work on the "
        f"machine inflates the absolute times, less so the interleaved ratios); "
        f"results in {out_json}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="fewer repeats and shorter baseline runs (about a third of the time)")
    ap.add_argument("--json", default=str(HERE / "results.json"), help="where to write results")
    ap.add_argument("--skip-slow", action="store_true",
                    help="skip the subprocess figures (make derive, CLI, report)")
    ap.add_argument("--only", choices=("core", "sweep", "report", "3d", "cli", "peers",
                                       "lanes", "stiff", "models"),
                    default=None,
                    help="run one section only (the planar loops and simulate() against the "
                         "C port, sweep throughput, the report's wall time, "
                         "the 3-D model against its C port, the CLI's cold and warm runs, "
                         "heyoka, the sweep's SIMD lanes against its scalar block, or "
                         "plans of 3-D, free-orbit and MSIS-air models against bare runs)")
    args = ap.parse_args(argv)
    q = dict(fast_repeats=15, dop_repeats=9, slow_repeats=5, rhs_calls=200_000,
             lambdify_calls=1000, pydy_calls=4000, pycall_calls=20_000,
             scipy_numba_periods=PERIODS, slow_periods=1.0, derive_repeats=5, cli_repeats=5,
             cli_phases=True, sweep_repeats=3)
    if args.quick:
        q.update(fast_repeats=5, dop_repeats=5, slow_repeats=5, rhs_calls=100_000,
                 lambdify_calls=300, pydy_calls=1000, pycall_calls=5000,
                 scipy_numba_periods=5.0, slow_periods=0.5, derive_repeats=1, cli_repeats=1,
                 cli_phases=False, sweep_repeats=1)
    t_start = clock()
    rep = Report()
    info = machine_info()
    log(f"tethersim bench{' --quick' if args.quick else ''}: {info['cpu']}, {info['cores']} cores, "
        f"python {info['python']}, numba {info['numba']}, {info['gcc']}; "
        f"load average {info['loadavg_start'][0]:.2f}")
    if args.quick:
        log("quick mode: 5 repeats; make derive and the CLI timed once/twice; shorter "
            "solve_ivp runs (scaled)")
    import sweep_bench
    if args.only:
        if args.only == "core":
            import engine_bench
            S = setup(rep)
            bench_rk4(rep, S, q)
            engine_bench.bench_simulate(rep, S, q, log)
            bench_dop853(rep, S, q)
        elif args.only == "sweep":
            import csweep
            csweep.bench_csweep(rep, q, log)
        elif args.only == "3d":
            import bench3d
            bench3d.bench_3d(rep, q, log)
        elif args.only == "cli":
            bench_cli(rep, q)
        elif args.only == "peers":
            bench_peers(rep, q)
        elif args.only == "stiff":
            import stiff
            stiff.bench_stiff(rep, q, log)
        elif args.only == "lanes":
            import lanes_bench
            lanes_bench.bench_lanes(rep, q, log)
            lanes_bench.bench_lanes_adaptive(rep, q, log)
        elif args.only == "models":
            import models_sweep
            models_sweep.bench_models_sweep(rep, q, log)
        else:
            sweep_bench.bench_report(rep, q, REPO)
        print_table(rep, clock() - t_start, "(not written with --only)")
        return 0 if all(c["ok"] for c in rep.checks) else 1
    S = setup(rep)
    import baselines
    t0 = clock()
    lamb = baselines.make_lambdify(S["model"], S["length_defs"])
    t_lamb = clock() - t0
    t0 = clock()
    try:
        pydy_f, pydy_gen = baselines.make_pydy(S["model"], S["length_defs"])
    except ImportError as exc:
        pydy_f, pydy_gen = None, "unavailable"
        rep.notes.append(f"PyDy figures skipped: {exc} (make bench installs the [bench] extra)")
    t_pydy = clock() - t0
    log(f"sympy.lambdify build {t_lamb:.2f} s; PyDy generate_ode_function ({pydy_gen}) "
        f"{t_pydy:.2f} s")
    validate_rhs(rep, S, lamb, pydy_f)

    bench_rhs(rep, S, q, lamb, pydy_f, pydy_gen)
    bench_rk4(rep, S, q)
    import engine_bench
    engine_bench.bench_simulate(rep, S, q, log)
    bench_dop853(rep, S, q)
    import bench3d
    bench3d.bench_3d(rep, q, log)
    bench_tools(rep, S, q, lamb, pydy_f, pydy_gen)
    import csweep
    csweep.bench_csweep(rep, q, log)
    bench_peers(rep, q)
    import stiff
    stiff.bench_stiff(rep, q, log)
    import lanes_bench
    lanes_bench.bench_lanes(rep, q, log)
    lanes_bench.bench_lanes_adaptive(rep, q, log)
    import models_sweep
    models_sweep.bench_models_sweep(rep, q, log)
    if not args.skip_slow:
        bench_derive(rep, q)
        bench_cli(rep, q)
        if not args.quick:
            sweep_bench.bench_report(rep, q, REPO)

    total = clock() - t_start
    info["loadavg_end"] = os.getloadavg()
    doc = {
        "meta": {**info, "quick": args.quick, "settings": q,
                 "satellite": S["sat"].name, "model": "derived", "rtol": RTOL, "atol": ATOL,
                 "periods": PERIODS, "rk4_steps": RK4_STEPS, "pydy_generator": pydy_gen,
                 "c_flags": ["-O3", "-O3 -march=native (info)"],
                 "setup_s": {**S["setup_s"], "lambdify_build": t_lamb, "pydy_build": t_pydy},
                 "bench_wall_s": total,
                 "timestamp": time.strftime("%Y-%m-%dT%H:%M:%S%z")},
        "figures": rep.figures, "targets": rep.targets, "checks": rep.checks, "notes": rep.notes,
    }
    Path(args.json).write_text(json.dumps(doc, indent=2, default=_json_default) + "\n")
    import speedpage
    page = speedpage.write(Path(args.json))
    print_table(rep, total, f"{args.json} and {page}")
    return 0 if all(c["ok"] for c in rep.checks) else 1


def _json_default(o):
    if isinstance(o, (np.integer,)):
        return int(o)
    if isinstance(o, (np.floating,)):
        return float(o)
    if isinstance(o, np.ndarray):
        return o.tolist()
    raise TypeError(type(o))


if __name__ == "__main__":
    raise SystemExit(main())
