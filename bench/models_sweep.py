"""Plans of many for models beyond the planar circular one (`make bench`, issue 20 targets).

Issue 20 asks that sweeps of 3-D, free-orbit and NRLMSISE-00-air models run in the
compiled path: a point of a plan costs at most 1.2x a bare compiled run of the same
model (no Python per point), and 1 -> 2 threads give at least 1.8x.  For each case,
N satellites (SatI, E2 spread by 1 % a point) run ``PERIODS`` orbits:

* **bare**: the engine's DOP853 loop called directly for each point, with the
  arguments a plan's compiled block passes it (same air vector, event limits,
  metrics grid, tolerances, step budget), prepared beforehand: integration only;
* **plan, 1 and 2 threads**: ``run_plan`` as users call it (starts, air vectors,
  the compiled blocks with their metrics and force peaks, the records).

Wall time, best of interleaved repeats.  The bare loop runs on the calling thread,
the plan on a pool: both timed by the wall clock.
"""
from __future__ import annotations

import math
import os

import numpy as np
from timing import clock, interleave

N = 16
PERIODS = 5.0


def _cases():
    from tethersim.model.air.model import SOLAR_CYCLE, SOLAR_CYCLE_EPOCH
    from tethersim.model.presets import load_preset

    sat = load_preset("satI")
    free = sat.replace(orbit="free", density_mode="per-body", atmosphere="vallado")
    f107, f107a, ap = SOLAR_CYCLE["mean"]
    return {  # figure key -> (label, satellite, plan model)
        "3d": ("3-D (circular, uniform air)",
               sat.replace(initial_3d={"phi": math.radians(5.0), "psi": math.radians(3.0)}),
               "3d"),
        "free": ("free orbit (per-body Vallado air)", free, "derived"),
        "free_msis": ("free orbit (NRLMSISE-00 air)",
                      free.replace(atmosphere="nrlmsise00", epoch=SOLAR_CYCLE_EPOCH, f107=f107,
                                   f107a=f107a, ap=ap), "derived"),
    }


def _bare_runs(plan, sats):
    """Zero-argument function running every point's DOP853 loop as a plan's block calls
    it (experiments/sweep/kernel.py _block_loop), the inputs built beforehand."""
    from tethersim.engine.events import event_parameters
    from tethersim.engine.guards import step_budget
    from tethersim.engine.integrators.dop853 import dop853_run
    from tethersim.engine.integrators.select import specialised
    from tethersim.engine.simulate import METRIC_SAMPLES_PER_PERIOD, refined_grid
    from tethersim.engine.start import start_satellite
    from tethersim.experiments.sweep.batch import _sizes
    from tethersim.experiments.sweep.plan import ATOL_PER_RTOL
    from tethersim.model.inputs import air_vector, initial_model_state, parameter_vector
    from tethersim.model.registry import model_for_orbit, model_index

    n_out = _sizes(plan)[1]  # the block's output samples and metrics grid (batch._compiled)
    refine = max(1, math.ceil(METRIC_SAMPLES_PER_PERIOD * plan.periods / n_out))
    runs = []
    for s in sats:
        model = model_for_orbit(plan.model, s.orbit)
        s = start_satellite(s, model, plan.start)[0]
        m, t_end = model_index(model), plan.periods * s.period
        p, y0 = parameter_vector(s, model), initial_model_state(s, model)
        T = refined_grid(t_end, n_out, refine)
        args = (air_vector(s, t_end), 0.0, t_end, y0, 0.0, p, p.copy(),
                event_parameters(s, model), plan.rtol, plan.rtol * ATOL_PER_RTOL, True, T,
                np.empty((T.size, y0.size)), np.int64(1),
                step_budget("adaptive", plan.periods), np.zeros(5, np.int64), math.inf)
        runs.append((specialised(dop853_run, m, args), m, args, y0.copy()))

    def run_all():
        for fn, m, args, y0 in runs:
            args[3][:] = y0  # the loop integrates the state in place
            fn(m, *args)
    return run_all


def bench_models_sweep(rep, q, log) -> None:
    from tethersim.experiments.sweep import Plan, run_plan

    cores = os.cpu_count() or 1
    log(f"\n[models] plans of many beyond the planar circular model: {N} SatI points x "
        f"{PERIODS:g} orbits, DOP853 at the plan's default rtol; wall time")
    for key, (label, sat, model) in _cases().items():
        sats = [sat.replace(E2=sat.E2 * (1 + 0.01 * i)) for i in range(N)]
        plan = Plan(periods=PERIODS, model=model)
        bare = _bare_runs(plan, sats)

        def timer(fn):
            def t():
                t0 = clock()
                fn()
                return clock() - t0
            return t

        def planned(workers, plan=plan, sats=sats):
            return lambda: run_plan(plan, sats, workers=workers, progress=False)

        res = interleave({"bare": timer(bare), "plan1": timer(planned(1)),
                          f"plan{cores}": timer(planned(cores))}, q["slow_repeats"], warmup=1)
        b, p1, pn = (min(res[k]) for k in ("bare", "plan1", f"plan{cores}"))
        key = f"models.{key}"
        log(f"  {label}: bare {1e3 * b / N:.2f} ms a point, plan {1e3 * p1 / N:.2f} ms "
            f"(1 thread), {1e3 * pn / N:.2f} ms ({cores} threads)")
        rep.fig(f"{key}.bare", f"{label}: bare DOP853 loop, per point (best)", b / N, "s",
                [x / N for x in res["bare"]])
        rep.fig(f"{key}.plan1", f"{label}: run_plan, 1 thread, per point (best)", p1 / N, "s",
                [x / N for x in res["plan1"]])
        rep.target(f"{key}.cost", f"issue 20: {label}, a plan's point <= 1.2x a bare run",
                   p1 / b, "<=", 1.2)
        rep.target(f"{key}.scale", f"issue 20: {label}, run_plan 1 -> {cores} threads",
                   p1 / pn, ">=", 1.8 if cores >= 2 else 1.0)
