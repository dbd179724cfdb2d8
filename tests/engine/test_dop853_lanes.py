"""DOP853 on SIMD lanes (engine/integrators/dop853_lanes.py): each lane is the scalar
step, error norm and dense output of steps.py, bit for bit.

The truth is steps.dop853_step, dop853_error_norm, dop853_dense and
dop853_interpolate, evaluated point by point; the lanes get K different points
(parameters, states with tethers taut and slack) and K different steps at once.
Equality is exact (repr of every float): the lane form reorders no floating-point
operation.
"""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from tethersim.engine.integrators.dop853_lanes import (
    dop853_lanes_dense,
    dop853_lanes_error,
    dop853_lanes_interpolate,
    dop853_lanes_step,
)
from tethersim.engine.integrators.lanes import LANES, lane_count
from tethersim.engine.integrators.select import call
from tethersim.engine.integrators.steps import (
    N_K,
    dop853_dense,
    dop853_error_norm,
    dop853_interpolate,
    dop853_step,
)
from tethersim.model.air.vector import uniform_air
from tethersim.model.registry import KERNELS, model_index

from .test_lanes import _bits, _flat, _points, _unflat

MODEL = "derived"

# the lane steps compiled on their own (~15 s cold) for a check the fast tier makes anyway
# through the whole block (tests/experiments/test_sweep_lanes853.py: records equal the scalar
# block's bit for bit): the slow tier (CI runs it)
pytestmark = pytest.mark.slow


@njit
def _scalar(model, air, y, f, h, p, pw, K, ys, y_new, F, x, out, rtol, atol):
    dop853_step(model, air, 0.0, y, f, h, p, pw, K, ys, y_new)
    err = dop853_error_norm(y.shape[0], K, h, y, y_new, rtol, atol)
    dop853_dense(model, air, 0.0, y, y_new, h, p, pw, K, ys, F)
    dop853_interpolate(y.shape[0], F, y, x, out)
    return err


# 4 (AVX2) and 8 (AVX-512) lanes on any CPU: idle lanes past K must not reach a lane's numbers
@pytest.mark.parametrize("k", sorted({4, LANES, lane_count()}))
def test_lane_dop853_step_error_and_dense_output_equal_the_scalar_ones_bit_for_bit(k):
    m = model_index(MODEL)
    kern = KERNELS[m]
    air = uniform_air()
    P, Y = _points(MODEL, k, 11)
    n = Y.shape[1]
    H = np.linspace(2.0, 9.0, k)  # s: each lane its own step
    rtol, atol, x = 1e-9, 1e-11, 0.37
    F0 = np.empty((k, n))
    rhs = njit(lambda t, y, p, d: kern.rhs(t, y, p, d))
    for j in range(k):
        rhs(0.0, Y[j], P[j], F0[j])
    m_rows = n * LANES
    Ks = np.zeros(N_K * m_rows)
    Ks[:m_rows] = _flat(F0)
    Yl, Pl = _flat(Y), _flat(P)
    Y_new, YS = np.zeros(m_rows), np.zeros(m_rows)
    S = np.zeros(kern.N_TRANSCENDENTAL * LANES)
    HR = np.zeros(m_rows)
    call(dop853_lanes_step, m, Yl, H, Pl, Ks, YS, Y_new, S, HR)
    err = np.empty(k)
    dop853_lanes_error(n, Ks, H, Yl, Y_new, rtol, atol, err, np.empty(2 * LANES))
    Fd = np.zeros(7 * m_rows)
    call(dop853_lanes_dense, m, Yl, Y_new, H, Pl, Ks, YS, Fd, S, HR)
    stages = [_unflat(Ks[s * m_rows:(s + 1) * m_rows], k, n) for s in range(N_K)]
    got_y = _unflat(Y_new, k, n)
    taut = set()
    for j in range(k):
        K = np.empty((N_K, n))
        y_new, F, out = np.empty(n), np.empty((7, n)), np.empty(n)
        want_err = call(_scalar, m, air, Y[j], F0[j], H[j], P[j], P[j].copy(), K,
                        np.empty(n), y_new, F, x, out, rtol, atol)
        assert _bits(got_y[j]) == _bits(y_new), j
        assert _bits([stages[s][j] for s in range(N_K)]) == _bits(K), j
        assert repr(float(err[j])) == repr(want_err), j
        lane_out = np.empty(n)
        dop853_lanes_interpolate(n, j, Fd, Yl, x, lane_out)
        assert _bits(lane_out) == _bits(out), j
        g = np.empty(2)
        kern.tether_margins(y_new, P[j], g)
        taut.add(tuple(g > 0))
    assert 0.0 < err.min() and len(taut) >= 2  # real error estimates, taut and slack lanes
