"""Real tethers: tethersim's implicit scheme against the explicit C DOP853 port, equal accuracy.

The case (issue 21's target, docs/real-tethers.md's nonlinear runs): SatI on 1 mm
Dyneema SK75 lines cut to the thesis's stretched geometry (rest lengths 30.83 and
28.92 m; EA ≈ 9e4 N, the loss factor's damping, the breaking load, from
``tether_parameters``), model ``objective-damper``, starting at rest at its equilibrium
for nominal air and flying at ×0.5 density: the step in drag sets the lines bouncing
(their axial mode near 77 rad/s) and the pitch moving to its new trim.

tethersim: ``simulate(method="implicit")`` (Radau IIA) at several rtol, atol 1e-10 (a
real line's floor, docs/tethers.md).  C: the DOP853 port of the same generated model
(bench/cref.py, printed from generated/objective_damper.py by bench/pyc.py; switches
located) at several rtol, on the same output grid.  The reference is C DOP853 at rtol
1e-13, checked against tethersim's implicit run at rtol 1e-11.  Error of a run: its
final state against the reference, max_i |Δy_i| / max(1, |y_i|) (bench/peers.py).  The
ratio is C's CPU time interpolated (log-log) to tethersim's error at rtol 1e-8 (the
tolerance of docs/real-tethers.md), over tethersim's time there; and tethersim's time
over the thesis-tether run of the same length (``simulate(satI)``, defaults).
"""
from __future__ import annotations

import numpy as np
from peers import _at_equal_error, _error
from timing import cpu_clock, interleave

MODEL = "objective-damper"
LENGTHS = (30.83, 28.92)  # m: the thesis's stretched equilibrium geometry
DENSITY = 0.5  # x nominal: the solar cycle's step from rest
TS_RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10)
TS_ATOL = 1e-10
TS_RTOL = 1e-8  # docs/real-tethers.md's runs
C_RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
SAMPLES = 200  # per orbit: the metrics grid


def start_satellite():
    """SatI on 1 mm Dyneema lines at LENGTHS, at rest at its nominal-air equilibrium,
    flying at DENSITY x nominal air."""
    from tethersim.engine.start import equilibrium_satellite
    from tethersim.model.materials import tether_parameters
    from tethersim.model.presets import load_preset
    sat = load_preset("satI")
    ch = {}
    for j, l0 in zip((1, 2), LENGTHS):
        t = tether_parameters("dyneema-sk75", 1e-3, l0, sat.m3)
        ch.update({f"l{j}0": l0, f"E{j}": t["EA"], f"c{j}": t["c"], f"Fb{j}": t["breaking_load"]})
    return equilibrium_satellite(sat.replace(**ch), MODEL).replace(density_scale=DENSITY)


def bench_stiff(rep, q, log, periods: float | None = None) -> None:
    """Work-precision of the real-tether case (module docstring)."""
    import cref

    from tethersim import load_preset, simulate
    from tethersim.model.inputs import initial_model_state, parameter_vector
    periods = periods or q.get("stiff_periods", 5)
    repeats = q.get("slow_repeats", 5)
    sat = start_satellite()
    c = cref.CRef(cref.build(cref.c_source_of_generated(MODEL), ("-O3",), "od"))
    p = parameter_vector(sat, MODEL)
    y0 = initial_model_state(sat, MODEL)
    T = periods * sat.period
    grid = np.linspace(0.0, T, int(SAMPLES * periods) + 1)[1:]
    log(f"\n[stiff] SatI, Dyneema 1 mm lines {LENGTHS[0]}/{LENGTHS[1]} m (EA {sat.E1:.3g} N), "
        f"{MODEL}, from rest at x{DENSITY} air, {periods:g} orbits: tethersim Radau IIA vs "
        f"C DOP853; thread CPU time, best of {repeats}")

    def c_run(rtol, atol=None):
        y, out = y0.copy(), np.empty((grid.size, y0.size))
        cnt = np.zeros(5, np.int64)
        t0 = cpu_clock()
        _, _, _, st = c.dop853_run(0.0, T, y, 0.0, p, rtol, atol or rtol * 1e-2, True, grid,
                                   out, 0, 10**10, cnt)
        dt = cpu_clock() - t0
        assert st == 0, f"C DOP853 status {st} at rtol {rtol:g}"
        return dt, out[-1].copy(), int(cnt[1])

    def ts_run(rtol):
        t0 = cpu_clock()
        res = simulate(sat, periods, model=MODEL, method="implicit", start="given", rtol=rtol,
                       atol=TS_ATOL, progress=False, check=False)
        dt = cpu_clock() - t0
        assert res.status == "ok", res.message
        return dt, res.states[-1][:y0.size], res.n_accepted

    thesis = load_preset("satI")

    def thesis_run():
        t0 = cpu_clock()
        simulate(thesis, periods, progress=False, check=False)
        return cpu_clock() - t0

    ref = c_run(1e-13, 1e-15)[1]
    ts_ref = ts_run(1e-11)[1]
    rep.check("real tethers: C DOP853 reference and tethersim Radau at rtol 1e-11 agree",
              _error(ts_ref, ref) < 1e-7, f"difference {_error(ts_ref, ref):.2g}")
    fns = {f"ts {r:g}": (lambda r=r: ts_run(r)[0]) for r in TS_RTOLS}
    fns.update({f"c {r:g}": (lambda r=r: c_run(r)[0]) for r in C_RTOLS})
    fns["thesis"] = thesis_run
    times = {k: min(v) for k, v in interleave(fns, repeats).items()}
    ts_res = {r: ts_run(r) for r in TS_RTOLS}
    c_res = {r: c_run(r) for r in C_RTOLS}
    for r, (_, y, n) in ts_res.items():
        log(f"  tethersim Radau rtol {r:g}: error {_error(y, ref):.2g}, {n} steps, "
            f"{times[f'ts {r:g}'] * 1e3:.1f} ms")
    for r, (_, y, n) in c_res.items():
        log(f"  C DOP853 rtol {r:g}: error {_error(y, ref):.2g}, {n} steps, "
            f"{times[f'c {r:g}'] * 1e3:.1f} ms")
    target = _error(ts_res[TS_RTOL][1], ref)
    c_t = _at_equal_error([_error(y, ref) for _, y, _ in c_res.values()],
                          [times[f"c {r:g}"] for r in C_RTOLS], target)
    ts_t = times[f"ts {TS_RTOL:g}"]
    ratio = rep.fig("stiff.c_dop853_over_radau",
                    f"C DOP853 / tethersim Radau CPU time at equal accuracy, Dyneema SatI, "
                    f"{periods:g} orbits (error {target:.1g})", c_t / ts_t, "x",
                    note=">1: tethersim faster")
    rep.target("T21a", "issue 21: real tethers >= 30x faster than C DOP853 at equal accuracy",
               ratio, ">=", 30.0)
    over = rep.fig("stiff.radau_over_thesis",
                   f"tethersim Radau (rtol {TS_RTOL:g}) / thesis-tether simulate(satI), "
                   f"{periods:g} orbits", ts_t / times["thesis"], "x")
    rep.target("T21b", "issue 21: real-tether run <= 5x the thesis-tether run", over, "<=", 5.0)
