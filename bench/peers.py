"""tethersim against heyoka.py (Taylor integrator, LLVM, events, SIMD batches), at equal accuracy.

The same model: the "derived" planar circular-orbit equations, rebuilt from the
derivation (derive/: the sympy q̈ and force families) and handed to heyoka with
``heyoka.from_sympy``; each tether's springs and dampers are gated by a runtime
parameter (taut 1, slack 0) that a heyoka event g = λ_j − l_j0 flips, as tethersim's
loops switch at the located crossing.  Both integrate the six model states from the
same start with the same parameters.

Work-precision: each tool runs at several tolerances; the error of a run is its final
state against a reference (tethersim DOP853 at rtol 1e-13, checked against heyoka at
tol 1e-15), as max_i |Δy_i| / max(1, |y_i|).  The ratio at equal accuracy is heyoka's
CPU time interpolated (log-log) to tethersim's error at its default tolerance, over
tethersim's time there: above 1, tethersim is faster.  Times are thread CPU time, best of
interleaved repeats, in this one process; both sides write the same output grid (200
samples per orbit: the metrics grid every simulate() run computes).

The scheme's floor: the bench's C port of the same model and DOP853 driver
(bench/cref.py, gcc -O3 -march=native; the same steps as tethersim's loop) timed on
each single-run case beside them, heyoka's time at its error over its time: where
this ratio is below 1 as well, no speed-up of tethersim's loop short of another
scheme reaches heyoka on that case.

Sweeps: 64 points (an 8 × 8 grid of E1 and E2 around SatI's band), 5 orbits:
tethersim's plan of many (compiled blocks on 1 thread and every core, full records:
metrics, class, force peaks) against heyoka's batch integrator (``taylor_adaptive_batch``,
per-lane events) writing each point's states on the same grid, at the tolerance whose
error matches tethersim's, in its fastest batch size on this CPU (:func:`fastest_batch`:
``heyoka.recommended_simd_size()`` or twice it, timed; on an AVX-512 Xeon twice the
recommendation ran faster, docs/speed-log.md);
once at the sweeps' default tolerance (numbers that are reported) and once at
``CLASS_RTOL`` (maps and searches that need a class or a verdict, docs/tolerances.md).
"""
from __future__ import annotations

import math
import os
import time
from concurrent.futures import ThreadPoolExecutor
from functools import cache

import numpy as np
from timing import cpu_clock, interleave

CASES = {  # name -> (preset, changes): the bench's three single-run cases
    "SatI preset start": ("satI", {}),
    "SatI on its trail": ("satI", {"initial": (28.9, 0.0, 0.0, 0.0, 0.0, 0.0)}),
    "SatII preset start": ("satII", {}),
}
PERIODS = 50
TS_RTOLS = (1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
HY_TOLS = (1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14)
HY_LOOSE = (1e-4, 1e-5, 1e-6, 1e-7)  # for the sweep at CLASS_RTOL
DEFAULT_RTOL = 1e-10  # simulate()'s default
SAMPLES = 200  # per orbit: the metrics grid
SWEEP_E1 = np.linspace(0.002, 0.006, 8)  # N (E x 1 mm^2)
SWEEP_E2 = np.linspace(0.03, 0.055, 8)
SWEEP_PERIODS = 5


@cache
def symbolic(model: str = "derived"):
    """(q̈ with the summed families gated by τ1, τ2, tether gaps λ_j − l_j0, symbols)."""
    import sympy as sp

    from derive.kinematics import planar_kinematics
    from derive.model import derive
    from derive.models import DEFINITIONS
    from derive.pipeline import Q_SYMBOLS
    from derive.symbols import TETHER_LENGTHS, P, state_substitution
    defn = next(d for d in DEFINITIONS if d.name == model)
    dm = derive(defn)
    kin = planar_kinematics()
    lengths = {lam: d.subs(state_substitution()) for lam, d in kin.tether_length_defs.items()}
    tau = sp.symbols("tau1 tau2")
    Q = [0, 0, 0]
    for fam in dm.families:
        gate = 1 if not fam.tether else tau[fam.tether - 1]
        for k in range(3):
            Q[k] += gate * fam.Q[k]
    qdd = [e.subs(dict(zip(Q_SYMBOLS, Q))).subs(lengths) for e in dm.qdd]
    gaps = [sp.sympify(TETHER_LENGTHS[j]).subs(lengths) - P[f"l{j + 1}0"] for j in range(2)]
    return qdd, gaps, tau, P


def from_sympy(expr, smap):
    """``heyoka.from_sympy`` of ``expr``, with sympy's Max (the Kelvin-Voigt clamp,
    derive/forces.py ``damper_pull``), which it does not take, as heyoka's relu:
    max(a, b) = b + relu(a − b)."""
    import heyoka as hy
    import sympy as sp

    maxes = sorted(expr.atoms(sp.Max), key=sp.default_sort_key)
    if not maxes:
        return hy.from_sympy(expr, s_dict=smap)
    marks = sp.symbols(f"max0:{len(maxes)}")
    outer = hy.from_sympy(expr.xreplace(dict(zip(maxes, marks))),
                          s_dict={**smap, **{m: hy.expression(m.name) for m in marks}})
    values = {}
    for m, e in zip(marks, maxes):
        a, b = (from_sympy(arg, smap) for arg in e.args)  # two arguments: damper, −spring
        values[m.name] = b + hy.relu(a - b)
    return hy.subs(outer, values)


def heyoka_integrator(sat, tol: float, batch: int | None = None, model: str = "derived"):
    """heyoka's integrator of ``sat`` (E1, E2 as parameters 2, 3 for batches) at ``tol``."""
    import heyoka as hy

    from derive.symbols import STATE_SYMBOLS
    from tethersim.model.inputs import initial_model_state, parameter_vector
    from tethersim.model.registry import BY_NAME
    qdd, gaps, tau, P = symbolic(model)
    names = BY_NAME[model].parameters
    num = {P[n]: float(v) for n, v in zip(names, parameter_vector(sat, model)) if n in P}
    free = {P["E1"]: None, P["E2"]: None} if batch else {}
    num = {k: v for k, v in num.items() if k not in free}
    xs = hy.make_vars(*[s.name for s in STATE_SYMBOLS])
    smap = dict(zip(STATE_SYMBOLS, xs))
    smap.update({tau[0]: hy.par[0], tau[1]: hy.par[1]})
    if batch:
        smap.update({P["E1"]: hy.par[2], P["E2"]: hy.par[3]})
    rhs = [from_sympy(e.subs(num), smap) for e in qdd]
    g = [from_sympy(e.subs(num), smap) for e in gaps]
    eqs = [(xs[i], xs[i + 3]) for i in range(3)] + [(xs[i + 3], rhs[i]) for i in range(3)]
    y0 = initial_model_state(sat, model)
    if batch is None:
        def flip(j):
            def cb(ta, d_sgn):
                ta.pars[j] = 1.0 if int(d_sgn) > 0 else 0.0
                return True
            return cb
        events = [hy.t_event(g[j], callback=flip(j)) for j in range(2)]
        return hy.taylor_adaptive(eqs, list(y0), tol=tol, pars=[1.0, 1.0], t_events=events), g

    def flip_lane(j):
        def cb(ta, d_sgn, lane):
            ta.pars[j, lane] = 1.0 if int(d_sgn) > 0 else 0.0
            return True
        return cb
    events = [hy.t_event_batch(g[j], callback=flip_lane(j)) for j in range(2)]
    state = np.repeat(np.asarray(y0, dtype=float)[:, None], batch, axis=1)
    pars = np.ones((4, batch))
    return hy.taylor_adaptive_batch(eqs, state, tol=tol, pars=pars, t_events=events), g


def heyoka_batches(ta, bs, starts, y0, pars, E, grid1) -> None:
    """heyoka's batch integrator ``ta`` (``bs`` lanes) over the points from each index of
    ``starts``: the same start y0 and switch flags ``pars``, E1 and E2 from the columns of
    E, each lane's states on grid1."""
    grid = np.repeat(grid1[:, None], bs, axis=1)
    for i in starts:
        ta.set_time(0.0)
        ta.state[:] = np.repeat(np.asarray(y0, float)[:, None], bs, axis=1)
        ta.pars[:2] = np.array(pars)[:, None]
        ta.pars[2:] = E[:, i:i + bs]
        ta.propagate_grid(grid)


def fastest_batch(sat, tol, y0, pars, E, grid1, log, repeats: int = 3) -> tuple:
    """(heyoka's fastest batch size for these points on this CPU, its integrator): its
    recommended SIMD size or twice it (the recommendation follows the vector width LLVM
    prefers, 256 bits on Intel's AVX-512 servers, where 8 lanes ran faster), each timed
    over all the points as the callers run them (process CPU time, best of interleaved
    repeats; both sizes divide the bench's 64 points)."""
    import heyoka as hy
    rec = hy.recommended_simd_size()
    n = E.shape[1]
    tas = {bs: heyoka_integrator(sat, tol, batch=bs)[0] for bs in (rec, 2 * rec)}

    def timer(bs):
        def t():
            t0 = time.process_time()
            heyoka_batches(tas[bs], bs, range(0, n, bs), y0, pars, E, grid1)
            return time.process_time() - t0
        return t
    times = {bs: min(v) for bs, v in interleave({b: timer(b) for b in tas}, repeats).items()}
    best = min(times, key=times.get)
    shown = ", ".join(f"{b}: {t * 1e3:.1f} ms" for b, t in times.items())
    log(f"  heyoka batch sizes (recommended {rec}): {shown}; using {best}")
    return best, tas[best]


def _taut(sat, y0, model="derived"):
    """τ1, τ2 at the start (the run's own rule: taut when λ_j > l_j0)."""
    import sympy as sp

    from derive.symbols import STATE_SYMBOLS
    from tethersim.model.inputs import parameter_vector
    from tethersim.model.registry import BY_NAME
    _, gaps, _, P = symbolic(model)
    num = {P[n]: float(v) for n, v in zip(BY_NAME[model].parameters,
                                            parameter_vector(sat, model)) if n in P}
    at = dict(zip(STATE_SYMBOLS, y0))
    return [1.0 if float(sp.sympify(gp).subs(num).subs(at)) > 0 else 0.0 for gp in gaps]


def _error(y, ref) -> float:
    return float(np.max(np.abs(np.asarray(y) - ref) / np.maximum(1.0, np.abs(ref))))


def _ts_run(sat, rtol):
    from tethersim import simulate
    t0 = cpu_clock()
    res = simulate(sat, PERIODS, rtol=rtol, atol=rtol * 1e-2, samples=SAMPLES * PERIODS,
                   progress=False, check=False)
    dt = cpu_clock() - t0
    assert res.status == "ok", res.message
    return dt, res.states[-1][:6]


def _c_run(sat, rtol, native=True):
    """The C port (bench/cref.py: gcc -O3 -march=native, the lean floor of tethersim's own
    scheme, or plain -O3, the same numbers as tethersim's loop) over the single run's span
    and output grid, at ``rtol``; (thread CPU seconds, final state)."""
    import cref

    from tethersim.model.inputs import initial_model_state, parameter_vector
    dt, _, y, _ = cref.timed_dop853(cref.port("native" if native else "O3"),
                                    initial_model_state(sat, "derived"),
                                    parameter_vector(sat, "derived"), PERIODS * sat.period,
                                    SAMPLES * PERIODS, rtol, rtol * 1e-2)
    return dt, y


def _hy_run(sat, ta, y0, pars, grid):
    ta.time = 0.0
    ta.state[:] = y0
    ta.pars[:] = pars
    t0 = cpu_clock()
    out = ta.propagate_grid(grid)
    dt = cpu_clock() - t0
    return dt, out[-1][-1]


def _at_equal_error(errors, times, target) -> float:
    """Time interpolated log-log at ``target`` error (NaN outside the measured range)."""
    e, t = np.log(np.asarray(errors)), np.log(np.asarray(times))
    order = np.argsort(e)
    e, t = e[order], t[order]
    lt = math.log(target)
    if not e[0] <= lt <= e[-1]:
        return math.nan
    return float(np.exp(np.interp(lt, e, t)))


def bench_single(rep, q, log) -> None:
    """Work-precision of single runs: tethersim simulate() vs heyoka propagate_grid."""
    for case, (preset, changes) in CASES.items():
        _single(rep, case, preset, changes, q.get("slow_repeats", 5), log)


def _single(rep, case, preset, changes, repeats, log) -> None:
    import tethersim as ts
    from tethersim.model.inputs import initial_model_state
    sat = ts.load_preset(preset).replace(**changes)
    ref = ts.simulate(sat, PERIODS, rtol=1e-13, atol=1e-15, progress=False,
                      samples=2).states[-1][:6]
    y0 = initial_model_state(sat, "derived")
    pars = _taut(sat, y0)
    grid = np.linspace(0.0, PERIODS * sat.period, SAMPLES * PERIODS + 1)
    tas = {tol: heyoka_integrator(sat, tol)[0] for tol in HY_TOLS + (1e-15,)}
    hy_ref = _hy_run(sat, tas[1e-15], y0, pars, grid)[1]
    rep.check(f"heyoka ({case}) reproduces tethersim's reference final state",
              _error(hy_ref, ref) < 1e-9, f"difference {_error(hy_ref, ref):.2g}")
    fns = {f"ts {r:g}": (lambda r=r: _ts_run(sat, r)[0]) for r in TS_RTOLS}
    fns.update({f"hy {t:g}": (lambda t=t: _hy_run(sat, tas[t], y0, pars, grid)[0])
                for t in HY_TOLS})
    fns["c"] = lambda: _c_run(sat, DEFAULT_RTOL)[0]
    times = {k: min(v) for k, v in interleave(fns, repeats).items()}
    ts_err = {r: _error(_ts_run(sat, r)[1], ref) for r in TS_RTOLS}
    c_err = _error(_c_run(sat, DEFAULT_RTOL)[1], ref)  # its own: -march=native fuses
    same = _error(_c_run(sat, DEFAULT_RTOL, native=False)[1], _ts_run(sat, DEFAULT_RTOL)[1])
    rep.check(f"the C port, -O3 ({case}), ends where tethersim does (the same steps)",
              same <= 1e-13, f"difference {same:.2g}")
    hy_err = {t: _error(_hy_run(sat, tas[t], y0, pars, grid)[1], ref) for t in HY_TOLS}
    for r in TS_RTOLS:
        log(f"  {case}: tethersim rtol {r:g}: error {ts_err[r]:.2g}, "
            f"{times[f'ts {r:g}'] * 1e3:.2f} ms")
    for t in HY_TOLS:
        log(f"  {case}: heyoka tol {t:g}: error {hy_err[t]:.2g}, "
            f"{times[f'hy {t:g}'] * 1e3:.2f} ms")
    target = ts_err[DEFAULT_RTOL]
    hy_t = _at_equal_error(list(hy_err.values()), [times[f"hy {t:g}"] for t in HY_TOLS],
                           target)
    key = "heyoka_single_" + case.split()[0].lower() + "_" + case.split()[-1]
    ratio = rep.fig(key, f"heyoka / tethersim CPU time at equal accuracy, {case}, {PERIODS} "
                         f"orbits (error {target:.1g})", hy_t / times[f"ts {DEFAULT_RTOL:g}"],
                    "x", note=">1: tethersim faster")
    rep.target(key, f"issue 22: ahead of heyoka, single run, {case}", ratio, ">=", 1.0)
    log(f"  {case}: C DOP853 port (-march=native) rtol {DEFAULT_RTOL:g}: error {c_err:.2g}, "
        f"{times['c'] * 1e3:.2f} ms")
    rep.fig(key + "_c", f"heyoka / C DOP853 port (gcc -O3 -march=native) CPU time at equal "
                        f"accuracy, {case}: the scheme's floor", hy_t / times["c"], "x",
            note=">1: the C port faster; <1: no faster DOP853 loop reaches heyoka here")


def _sweep_sats():
    import tethersim as ts
    sat = ts.load_preset("satI")
    return [sat.replace(E1=float(a), E2=float(b)) for b in SWEEP_E2 for a in SWEEP_E1]


def bench_sweep(rep, q, log) -> None:
    """Sweep throughput: tethersim run_plan vs heyoka's SIMD batches at equal accuracy, at
    the sweeps' default tolerance and at the class tolerance of maps and searches."""
    from tethersim.experiments.sweep.plan import CLASS_RTOL, DEFAULT_RTOL
    _sweep(rep, q, log, DEFAULT_RTOL, HY_TOLS, "")
    _sweep(rep, q, log, CLASS_RTOL, HY_LOOSE + HY_TOLS, "_class")


def _sweep(rep, q, log, rtol, hy_tols, tag) -> None:
    import tethersim as ts
    from tethersim.experiments.sweep import Plan, run_plan
    from tethersim.experiments.sweep.plan import ATOL_PER_RTOL
    from tethersim.model.inputs import initial_model_state
    sats = _sweep_sats()
    sat0 = sats[0]
    T = SWEEP_PERIODS * sat0.period
    plan = Plan(periods=float(SWEEP_PERIODS), rtol=rtol)
    # the accuracy to match: tethersim's sweep tolerance at the first point
    ref = ts.simulate(sat0, SWEEP_PERIODS, rtol=1e-13, atol=1e-15, progress=False,
                      samples=2).states[-1][:6]
    ts_err = _error(ts.simulate(sat0, SWEEP_PERIODS, rtol=rtol, atol=rtol * ATOL_PER_RTOL,
                                progress=False, samples=2).states[-1][:6], ref)
    y0 = initial_model_state(sat0, "derived")
    pars = _taut(sat0, y0)
    grid1 = np.linspace(0.0, T, SAMPLES * SWEEP_PERIODS + 1)
    # heyoka's loosest tolerance whose error is at most tethersim's
    tol = next((t for t in hy_tols if _error(_hy_run(
        sat0, heyoka_integrator(sat0, t)[0], y0, pars, grid1)[1], ref) <= ts_err), hy_tols[-1])
    E = np.array([[s.E1 for s in sats], [s.E2 for s in sats]])
    bs, ta = fastest_batch(sat0, tol, y0, pars, E, grid1, log)

    # one thread: process CPU time (the plan runs in a worker thread); every core: wall time
    def heyoka_all():
        t0 = time.process_time()
        heyoka_batches(ta, bs, range(0, len(sats), bs), y0, pars, E, grid1)
        return time.process_time() - t0

    def tethersim_all(workers):
        clock = time.process_time if workers == 1 else time.perf_counter

        def timer():
            t0 = clock()
            run_plan(plan, sats, workers=workers, progress=False)
            return clock() - t0
        return timer

    def heyoka_threads(workers):
        """heyoka batches on ``workers`` threads (its propagate releases the GIL)."""
        def timer():
            tas = [heyoka_integrator(sat0, tol, batch=bs)[0] for _ in range(workers)]
            chunks = [list(range(i, len(sats), bs * workers)) for i in range(0, bs * workers, bs)]

            def run(w):
                heyoka_batches(tas[w], bs, chunks[w], y0, pars, E, grid1)
            t0 = time.perf_counter()
            with ThreadPoolExecutor(workers) as ex:
                list(ex.map(run, range(workers)))
            return time.perf_counter() - t0
        return timer

    cores = os.cpu_count() or 1
    fns = {"ts 1": tethersim_all(1), f"ts {cores}": tethersim_all(cores), "hy 1": heyoka_all,
           f"hy {cores}": heyoka_threads(cores)}
    times = {k: min(v) for k, v in interleave(fns, q.get("sweep_repeats", 3)).items()}
    n = len(sats)
    log(f"  sweep {n} points x {SWEEP_PERIODS} orbits: heyoka tol {tol:g} (tethersim rtol "
        f"{rtol:g}: error {ts_err:.2g}), SIMD batch {bs}")
    for k, v in times.items():
        log(f"  {k} thread(s): {n / v:.0f} trajectories/s")
    log(f"  (one thread: process CPU time; {cores} threads: wall time, load average "
        f"{os.getloadavg()[0]:.1f})")
    for w in (1, cores):
        ratio = times[f"hy {w}"] / times[f"ts {w}"]
        if not tag:
            rep.target(f"heyoka_sweep_{w}", f"issue 22: sweeps >= 1.5x heyoka's batches, {w} "
                       f"thread(s)", ratio, ">=", 1.5)
        rep.fig(f"heyoka_sweep_{w}{tag}", f"tethersim / heyoka (batch {bs}) sweep "
                                          f"trajectories/s, {w} thread(s), equal accuracy "
                                          f"(rtol {rtol:g}, heyoka tol {tol:g})",
                ratio, "x", note=">1: tethersim faster; "
                "tethersim's records include metrics, class and force peaks")
