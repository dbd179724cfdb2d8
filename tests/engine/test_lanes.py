"""SIMD lanes (engine/integrators/lanes.py): each lane is the scalar kernel, bit for bit
(the tether margins' lane form, a filter, to a few ulps).

The truth is the scalar generated rhs and steps.rk4_step, evaluated point by point;
the lanes get K different points (parameters and states, tethers taut and slack)
at once.  Equality is exact (repr of every float): the lane form reorders no
floating-point operation (derive/lanes.py).
"""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from tethersim import load_preset, simulate
from tethersim.engine.evaluate import family_force_peaks, family_forces_series
from tethersim.engine.integrators.lanes import (
    LANES,
    has_lanes,
    lane_count,
    rk4_lanes_step,
)
from tethersim.engine.integrators.select import call
from tethersim.engine.integrators.steps import rk4_step
from tethersim.model.air.vector import uniform_air
from tethersim.model.inputs import initial_model_state, parameter_vector
from tethersim.model.registry import KERNELS, MODELS, model_index

LANE_MODELS = [m.name for m in MODELS if has_lanes(model_index(m.name))]


def _points(model: str, k: int, seed: int):
    """k parameter vectors and states of SatI with scaled tethers and random offsets:
    the balloon near the tethers' rest lengths, so that about half the tethers are taut."""
    rng = np.random.default_rng(seed)
    sat = load_preset("satI")
    P, Y = [], []
    for _ in range(k):
        s = sat.replace(E1=sat.E1 * rng.uniform(0.5, 2.0), c2=sat.c2 * rng.uniform(0.0, 3.0))
        y = initial_model_state(s, model).copy()
        y[0] = rng.uniform(-0.3, 0.3) * s.l10
        y[1] = rng.uniform(0.7, 1.2) * s.l10
        y[2] = rng.uniform(-np.pi, np.pi)
        y[3:] = rng.normal(size=3) * np.array([0.1, 0.1, 1e-3])
        P.append(parameter_vector(s, model))
        Y.append(y)
    return np.array(P), np.array(Y)


def _flat(rows: np.ndarray) -> np.ndarray:
    """(K, n) points -> the lane layout, row i at [i*LANES, i*LANES + K)."""
    k, n = rows.shape
    out = np.zeros(n * LANES)
    for i in range(n):
        out[i * LANES:i * LANES + k] = rows[:, i]
    return out


def _unflat(flat: np.ndarray, k: int, n: int) -> np.ndarray:
    return np.array([[flat[i * LANES + j] for i in range(n)] for j in range(k)])


def _bits(a) -> list:
    return [repr(float(v)) for v in np.ravel(a)]


def test_planar_lane_models_are_the_circular_ones_whose_libm_calls_read_the_state():
    # the thesis model and its objective damper have lanes; exact gravity's expm1/log1p
    # read intermediates (derive/lanes.py refuses them): it runs the scalar loops
    assert {"derived", "objective-damper"} <= set(LANE_MODELS)
    assert "exact-gravity" not in LANE_MODELS
    assert all(MODELS[model_index(m)].orbit == "circular" for m in LANE_MODELS)
    # the adaptive lanes' event filter writes no re-entry or roll slot (lanes853._clear)
    from tethersim.model.registry import record
    assert not any({"r", "phi"} & set(record(model_index(m)).state) for m in LANE_MODELS)
    assert lane_count() in (4, 8) and lane_count() <= LANES


# the thesis model in the fast tier; the others compile their own rhs twice (~5 s each)
@pytest.mark.parametrize("model", [m if m == "derived" else pytest.param(m, marks=pytest.mark.slow)
                                   for m in LANE_MODELS])
def test_lane_rhs_equals_the_scalar_rhs_bit_for_bit(model):
    k = lane_count()
    kern = KERNELS[model_index(model)]
    rhs, rhs_lanes = kern.rhs, kern.rhs_lanes
    scalar = njit(lambda t, y, p, d: rhs(t, y, p, d))
    lanes = njit(lambda t, y, p, d, s: rhs_lanes(t, y, p, d, s))
    taut = set()
    for seed in range(4):
        P, Y = _points(model, k, seed)
        d = np.empty(Y.shape[1] * LANES)
        lanes(np.zeros(k), _flat(Y), _flat(P), d, np.empty(kern.N_TRANSCENDENTAL * LANES))
        for j in range(k):
            want = np.empty(Y.shape[1])
            scalar(0.0, Y[j], P[j], want)
            assert _bits(_unflat(d, k, Y.shape[1])[j]) == _bits(want), (model, seed, j)
            g = np.empty(2)
            kern.tether_margins(Y[j], P[j], g)
            taut.add(tuple(g > 0))
    assert len(taut) >= 3  # taut and slack tethers, in several combinations


# the thesis model in the fast tier, as the rhs above
@pytest.mark.parametrize("model", [m if m == "derived" else pytest.param(m, marks=pytest.mark.slow)
                                   for m in LANE_MODELS])
def test_lane_family_forces_equal_the_scalar_ones_bit_for_bit(model):
    kern = KERNELS[model_index(model)]
    forces, forces_lanes = kern.family_forces, kern.family_forces_lanes
    scalar = njit(lambda y, p, out: forces(y, p, out))
    lanes = njit(lambda k, y, p, out, s: forces_lanes(k, y, p, out, s))
    nf, nq = len(kern.FAMILIES), 3
    for seed, k in ((0, LANES), (1, LANES), (2, 3)):  # a last, partial batch of 3 lanes
        P, Y = _points(model, k, seed)
        out = np.full(nf * nq * LANES, np.nan)  # every entry written, zeros included
        lanes(k, _flat(Y), _flat(P), out, np.empty(kern.N_TRANSCENDENTAL * LANES))
        got = _unflat(out, k, nf * nq)
        for j in range(k):
            want = np.full((nf, nq), np.nan)
            scalar(Y[j], P[j], want)
            assert _bits(got[j]) == _bits(want), (model, seed, j)


def test_lane_tether_margins_are_the_scalar_ones_to_a_few_ulps_far_inside_the_clear_margin():
    # the lane margins take sqrt(x**2 + y**2) where the scalar kernel takes hypot (no
    # vector version): the adaptive lanes use them only to rule out a sign change, with a
    # margin of CLEAR times the lengths (sweep/lanes853.py _clear); lines slack, taut and
    # stretched far past their rest length (up to the stretch limit, 20x)
    from tethersim.experiments.sweep.lanes853 import CLEAR
    from tethersim.generated import layout
    worst = 0.0
    for model in LANE_MODELS:
        kern = KERNELS[model_index(model)]
        lanes = kern.tether_margins_lanes
        margins = njit(lambda k, y, p, g, s, f=lanes: f(k, y, p, g, s))
        for seed in range(6):
            P, Y = _points(model, LANES, seed)
            Y[:, :2] *= 1.0 + 4.0 * seed  # the balloon out to ~20 rest lengths
            got = np.full(2 * LANES, np.nan)
            margins(LANES, _flat(Y), _flat(P), got, np.empty(kern.N_TRANSCENDENTAL * LANES))
            for j in range(LANES):
                want = np.empty(2)
                kern.tether_margins(Y[j], P[j], want)
                l0 = P[j][[layout.P_L10, layout.P_L20]]
                for i in range(2):
                    worst = max(worst, abs(got[i * LANES + j] - want[i]) / (want[i] + l0[i]))
    assert 0.0 < worst <= 8 * np.finfo(float).eps  # not bit for bit, but a few ulps
    assert CLEAR >= 1000 * worst


def test_force_peaks_on_lanes_equal_the_largest_force_of_the_series():
    # the sweeps' force peaks take LANES samples at a time in uniform air; the truth is the
    # scalar series of every family's force, 1001 samples (not a multiple of LANES)
    sat = load_preset("satI")
    res = simulate(sat, 5, samples=1001, progress=False)
    m, air = model_index("derived"), uniform_air()
    Y, p = np.ascontiguousarray(res.model_states), parameter_vector(sat, "derived")
    peaks = family_force_peaks(m, air, res.t, Y, p)
    want = np.abs(family_forces_series(m, air, res.t, Y, p)).max(axis=(0, 1))
    assert _bits(peaks) == _bits(want)
    assert np.all(want > 0.0)


@pytest.mark.slow  # compiles an RK4 step of each lane model (~15 s cold)
@pytest.mark.parametrize("model", LANE_MODELS)
def test_lane_rk4_step_equals_the_scalar_step_bit_for_bit(model):
    m = model_index(model)
    k = lane_count()
    air = uniform_air()
    P, Y = _points(model, k, 7)
    n = Y.shape[1]
    H = np.linspace(20.0, 30.0, k)  # each lane its own step
    T = np.arange(k) * 26.55
    stages = [np.zeros(n * LANES) for _ in range(5)]
    out = np.zeros(n * LANES)
    S = np.zeros(KERNELS[m].N_TRANSCENDENTAL * LANES)
    step_lanes(m, T, _flat(Y), H, _flat(P), *stages, np.empty(k), out, S)
    got = _unflat(out, k, n)
    for j in range(k):
        want = np.empty(n)
        step_scalar(m, air, T[j], Y[j], H[j], P[j], P[j].copy(), np.empty((5, n)), want)
        assert _bits(got[j]) == _bits(want), (model, j)


def step_lanes(m, *args):
    return call(rk4_lanes_step, m, *args)


@njit
def _step_scalar(model, air, t, y, h, p, pw, work, y_new):
    rk4_step(model, air, t, y, h, p, pw, work, y_new)


def step_scalar(m, *args):
    return call(_step_scalar, m, *args)
