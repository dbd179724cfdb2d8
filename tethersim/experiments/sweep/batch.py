"""A block of sweep points: Python builds the inputs, one compiled call runs them all.

Per point, Python only builds the satellite, its parameter vector, initial
state, output grid and event limits, and (one LAPACK call for the block) the
RK4 amplification; ``kernel.sweep_block`` then integrates (the loops stop at the
domain's limits themselves) and measures every point without the GIL, and Python
writes the records.  Every model and air runs here: there is no fallback path.  The
records are those of simulate() then outcome() (point.run_point, the tests' truth)
bit for bit (tests/experiments/test_sweep_batch.py): the same compiled loops, called
as simulate calls them, and the same compiled metrics (analysis.metrics_kernel).
They do not depend on the block a point is in, so a resumed or distributed sweep is
still identical to an uninterrupted one.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.classify import classify
from tethersim.analysis.metrics import SS_FRACTION, PitchMetrics
from tethersim.engine.arguments import check_scheme
from tethersim.engine.events import event_parameters
from tethersim.engine.guards import API_SUBJECT, check_simulation
from tethersim.engine.integrators.lanes import has_lanes, lane_count
from tethersim.engine.integrators.select import specialised
from tethersim.engine.linearise import rk4_amplifications
from tethersim.engine.simulate import (
    FAITHFUL_STEPS_PER_PERIOD,
    METRIC_SAMPLES_PER_PERIOD,
    refined_grid,
    step_budget,
)
from tethersim.engine.start import start_satellite
from tethersim.experiments.sweep.kernel import (
    COL_FIELDS,
    F_FIELDS,
    I_FIELDS,
    sweep_block,
    sweep_block_implicit,
)
from tethersim.experiments.sweep.lanes import sweep_block_lanes
from tethersim.experiments.sweep.lanes853 import sweep_block_lanes853
from tethersim.experiments.sweep.plan import SCHEMES, Plan
from tethersim.experiments.sweep.point import record
from tethersim.experiments.sweep.spec import SweepSpec
from tethersim.model.air.vector import UNIFORM
from tethersim.model.inputs import air_vector, initial_model_state, parameter_vector
from tethersim.model.registry import get_model, model_for_orbit, model_index

# faithful and adaptive blocks of one lane model in uniform air run K points per step on
# SIMD lanes (sweep/lanes.py, RK4; sweep/lanes853.py, DOP853), the same records; False runs
# every block point by point (the benchmark's and the tests' comparison:
# bench/lanes_bench.py)
USE_LANES = True


def _lanes_for(method: str, m: int) -> bool:
    """Whether scheme ``method`` runs model index ``m`` on SIMD lanes (in uniform air)."""
    return USE_LANES and method in ("faithful", "adaptive") and has_lanes(m)


def lane_width(plan: Plan) -> int:
    """Points one compiled step of ``plan``'s blocks advances together: the SIMD lanes
    (lane_count) for the faithful and adaptive schemes of a model with a lane rhs, else
    1 (runner.block_size gives a block at least this many points)."""
    return lane_count() if _lanes_for(plan.method, model_index(plan.model)) else 1


_F = {name: i for i, name in enumerate(F_FIELDS)}
_I = {name: i for i, name in enumerate(I_FIELDS)}


def run_block(spec: SweepSpec, ks: list) -> list:
    """[(k, record)] of flat points ks of ``spec``, in the order of ks (run_satellites)."""
    return list(zip(ks, run_satellites(spec.plan, [spec.satellite_at(k) for k in ks])))


def run_satellites(plan: Plan, sats: list) -> list:
    """The record of each satellite's run under ``plan``, in order.

    Every point runs in a compiled block, whatever its model (planar or 3-D,
    circular or free orbit) and air (uniform, per-body, NRLMSISE-00): the points are
    grouped by the model their orbit runs and by their air vector (equal for points
    that differ only in the satellite's other parameters), one compiled call per group.
    A record does not depend on the other satellites of the call.

    Parameters
    ----------
    plan : Plan
        How every run integrates.
    sats : list of Satellite
        The runs' satellites.

    Returns
    -------
    list of dict
        One record per satellite, as point.run_point returns it (point.VARIABLES).
    """
    periods = float(plan.periods)
    groups = {}  # (model, air vector bytes) -> (air vector, indices into sats)
    sats = list(sats)
    for i, s in enumerate(sats):
        model = model_for_orbit(plan.model, s.orbit)  # a free orbit runs the free twin
        # where simulate() starts it: as given, or a real line's equilibrium (engine/start.py)
        sats[i] = s = start_satellite(s, model, plan.start)[0]
        air = air_vector(s, periods * s.period)  # as simulate() builds it
        groups.setdefault((model, air.tobytes()), (air, []))[1].append(i)
    records = {}
    for (model, _), (air, idx) in groups.items():
        records.update(zip(idx, _compiled([sats[i] for i in idx], plan, model, air)))
    return [records[i] for i in range(len(sats))]


def _sizes(spec) -> tuple:
    """(RK4 steps, adaptive output samples) of one point of a plan (or spec)."""
    return (max(1, round(spec.steps_per_period * spec.periods)),
            max(2, round(spec.samples_per_period * spec.periods)))


def check_point_size(spec, subject: str = API_SUBJECT) -> None:
    """Refuse a sweep whose every point's arrays would exceed the output limit
    (engine/guards.py: the output and the 200-per-orbit metrics grid), before any store
    or run.

    Parameters
    ----------
    spec : SweepSpec or object
        Anything with the spec's ``periods``, ``method``, ``steps_per_period`` and
        ``samples_per_period`` (the command checks before building the spec, whose
        points' validation takes a while on a large grid).
    subject : str, optional
        What the message blames (a command: ``"--periods"``).
    """
    n_steps, n_out = _sizes(spec)
    faithful = spec.method == "faithful"
    check_simulation(float(spec.periods), n_steps if faithful else None,
                     "rk4" if faithful else "adaptive", None if faithful else n_out, False,
                     subject=subject)


def _grid(t_end: float, n_out: int, refine: int, cache: dict) -> np.ndarray:
    key = (t_end, n_out, refine)
    if key not in cache:  # one grid for every point of the same orbit
        cache[key] = refined_grid(t_end, n_out, refine)
    return cache[key]


def _compiled(sats: list, plan: Plan, model: str, air: np.ndarray) -> list:
    """The records of points whose satellites are ``sats``, all running ``model`` in the
    air vector ``air``, in one compiled call."""
    m = model_index(model)
    lay = get_model(model)
    periods = float(plan.periods)  # as simulate() takes it
    faithful = plan.method == "faithful"
    for s in sats:  # what simulate() refuses, each point's run refuses here too
        check_scheme(s, SCHEMES[plan.method])
    n = len(sats)
    P = np.stack([parameter_vector(s, model) for s in sats])
    Y0 = np.stack([initial_model_state(s, model) for s in sats])
    n_steps, n_out = _sizes(plan)
    check_point_size(plan)  # the output-size guard simulate() applies to each point
    if faithful:  # simulate._run_rk4: every step is a sample
        span = np.array([periods * s.period / n_steps for s in sats])
        T = np.empty((1, n_steps + 1))  # the RK4 loop writes its own times
    else:  # simulate._run_adaptive: the metrics grid, refined from the output grid
        refine = max(1, math.ceil(METRIC_SAMPLES_PER_PERIOD * periods / n_out))
        span = np.array([periods * s.period for s in sats])
        grids = {}
        T = np.stack([_grid(t_end, n_out, refine, grids) for t_end in span])
    EV = np.stack([event_parameters(s, model) for s in sats])  # as simulate() builds it
    cols = np.array([lay.state.index(c) for c in COL_FIELDS], dtype=np.int64)
    rec_f = np.empty((n, len(F_FIELDS)))
    rec_i = np.empty((n, len(I_FIELDS)), dtype=np.int64)
    tolerances = (plan.rtol, plan.absolute_tolerance,
                  step_budget(SCHEMES[plan.method], periods))
    measure = (EV, cols, float(plan.tol), SS_FRACTION, rec_f, rec_i)
    if plan.method == "implicit":  # its own entry: the explicit blocks do not carry Radau
        args = (air, T, Y0, P, span, *tolerances, *measure)
        specialised(sweep_block_implicit, m, args)(m, *args)  # releases the GIL
    elif faithful and n >= 2 and air[0] == UNIFORM and _lanes_for(plan.method, m):
        # K points per step on SIMD lanes, the same records bit for bit (sweep/lanes.py)
        args = (air, Y0, P, span, n_steps, *measure, lane_count())
        specialised(sweep_block_lanes, m, args)(m, *args)  # releases the GIL
    elif n >= 2 and air[0] == UNIFORM and _lanes_for(plan.method, m):
        # DOP853 with K points per step on SIMD lanes, the same records (sweep/lanes853.py)
        args = (air, T, Y0, P, span, *tolerances, *measure, lane_count())
        specialised(sweep_block_lanes853, m, args)(m, *args)  # releases the GIL
    else:
        args = (air, faithful, T, Y0, P, span, n_steps, *tolerances, *measure)
        specialised(sweep_block, m, args)(m, *args)  # releases the GIL
    amps = rk4_amplifications(sats, [s.period / FAITHFUL_STEPS_PER_PERIOD for s in sats],
                              model)
    # the run length outcome.run_orbits gives the per-point path: the orbits asked for
    return [_record(rec_f[j], rec_i[j], amps[j], plan.tol, periods) for j in range(n)]


def _record(f: np.ndarray, i: np.ndarray, amplification: float, tol: float,
            run_orbits: float) -> dict:
    status, nfev = int(i[_I["status"]]), int(i[_I["nfev"]])
    end_time = float(f[_F["end_time"]])
    if not i[_I["counts"]]:
        return record(status, nfev, amplification, classify(None), None, end_time)
    m = PitchMetrics(mean_pitch=float(f[_F["mean_pitch"]]),
                     steady_state_pitch=float(f[_F["steady_state_pitch"]]),
                     settling_time=float(f[_F["settling_time"]]),
                     tumbled=bool(i[_I["tumbled"]]), upside_down=bool(i[_I["upside_down"]]))
    measured = {name: float(f[_F[name]]) for name in F_FIELDS if name != "end_time"}
    measured.update(tumbled=int(m.tumbled), upside_down=int(m.upside_down))
    return record(status, nfev, amplification, classify(m, tol=tol, run_orbits=run_orbits),
                  measured, end_time)
