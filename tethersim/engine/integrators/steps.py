"""Pure step functions: one step of a Runge-Kutta method, no state kept.

rk4_step     classical RK4, thesis Eqs 4.1-4.5
dop853_step  Dormand-Prince 8(5,3) (Hairer's DOP853) with its error norm and
             7th-order dense output, ported from scipy.integrate._ivp.rk.

Each step function evaluates the right-hand side at one call site (a loop
over its stages), so a model's generated rhs is compiled once per step
function and per model; the model index is a literal (dynamics.derivative).
The arrays they receive are borrowed (integrators/borrow.py) by the run
function that calls them.  Stage arithmetic is written so that every
floating-point operation is the one of the textbook formulas (e.g. the RK4
stage state y + (c h) k with c = 1/2 or 1), which keeps trajectories bit for
bit what they were when the stages were written out one by one.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import derivative, model_size
from tethersim.engine.integrators.dop853_tableau import E3, E5, N_STAGES, A, B, C, D


@njit(cache=True)
def copy_into(dst, src):
    """dst[i] = src[i] for every i of src.

    A loop, not ``dst[:] = src``: numba compiles a shape-mismatch error path
    (string formatting, about a second) for every slice assignment it lowers.
    """
    for i in range(src.shape[0]):
        dst[i] = src[i]


N_K = 16  # rows of the DOP853 stage array: 12 stages, FSAL, 3 dense-output stages
RK4_C = (0.0, 0.5, 0.5, 1.0)  # nodes of classical RK4 (stage s uses k_{s-1} with weight c_s)


@njit(cache=True)
def rk4_step(model, air, t, y, h, p, pw, work, y_new):
    """One RK4 step of size h from (t, y) into y_new (Eqs 4.1-4.5).

    Parameters
    ----------
    model, air
        Model index literal and air vector (dynamics.derivative).
    t, y, h : float, ndarray, float
        Start time, start state, step.
    p, pw : ndarray
        Parameters and the per-body scratch parameter vector.
    work : ndarray
        (5, n) scratch: k1..k4 and a stage state.
    y_new : ndarray
        Output: the state at t + h.
    """
    n = model_size(model, y)
    ys = work[4]
    for s in range(4):
        if s == 0:
            ts = t
            for i in range(n):
                ys[i] = y[i]
        else:
            ts = t + RK4_C[s] * h
            a = RK4_C[s] * h
            for i in range(n):
                ys[i] = y[i] + a * work[s - 1, i]
        derivative(model, air, ts, ys, p, pw, work[s])
    for i in range(n):
        y_new[i] = y[i] + h / 6.0 * (work[0, i] + 2.0 * work[1, i] + 2.0 * work[2, i]
                                     + work[3, i])


if not np.array_equal(A[N_STAGES, :N_STAGES], B):
    raise ImportError("DOP853 tableau: row 12 of A must be the weights B (FSAL)")


@njit(cache=True, inline="always")
def _stage_state(n, s, y, h, K, ys):
    """ys = y + h Σ_{j<s} A[s, j] K[j]: the state at which stage s is evaluated.

    Four state components at a time, each in its own scalar accumulator: the
    sums are chains of dependent additions, and four independent chains keep
    the adder busy (as a C compiler's outer-loop vectorisation does).  Each
    component still sums A[s, 0] K[0] + A[s, 1] K[1] + ... in that order, so
    the rounding is that of a plain per-component loop.  n: the state's length
    (dynamics.model_size, a compile-time constant).
    """
    i = 0
    while i + 4 <= n:
        a0 = 0.0
        a1 = 0.0
        a2 = 0.0
        a3 = 0.0
        for j in range(s):
            c = A[s, j]
            a0 += c * K[j, i]
            a1 += c * K[j, i + 1]
            a2 += c * K[j, i + 2]
            a3 += c * K[j, i + 3]
        ys[i] = y[i] + h * a0
        ys[i + 1] = y[i + 1] + h * a1
        ys[i + 2] = y[i + 2] + h * a2
        ys[i + 3] = y[i + 3] + h * a3
        i += 4
    if i + 2 <= n:  # 10-float states: two blocks of 4, then this pair
        a0 = 0.0
        a1 = 0.0
        for j in range(s):
            c = A[s, j]
            a0 += c * K[j, i]
            a1 += c * K[j, i + 1]
        ys[i] = y[i] + h * a0
        ys[i + 1] = y[i + 1] + h * a1
        i += 2
    while i < n:
        acc = 0.0
        for j in range(s):
            acc += A[s, j] * K[j, i]
        ys[i] = y[i] + h * acc
        i += 1


@njit(cache=True)
def dop853_step(model, air, t, y, f, h, p, pw, K, ys, y_new):
    """One DOP853 step from (t, y) with f = f(t, y).

    y_new receives the state at t + h; K[0..12] the stages, K[12] = f(t + h,
    y_new) (first same as last); ys is a stage-state scratch vector.
    """
    n = model_size(model, y)
    for i in range(n):
        K[0, i] = f[i]
    for s in range(1, N_STAGES + 1):
        # row N_STAGES of A is B: the FSAL stage is evaluated at the solution itself
        _stage_state(n, s, y, h, K, ys)
        if s == N_STAGES:
            for i in range(n):
                y_new[i] = ys[i]
        derivative(model, air, t + C[s] * h, ys, p, pw, K[s])


@njit(cache=True)
def dop853_error_norm(n, K, h, y, y_new, rtol, atol):
    """Scaled RMS error estimate of the last step (DOP853's 5th/3rd-order blend); n = len(y)."""
    e5, e3 = 0.0, 0.0
    for i in range(n):
        scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol
        s5, s3 = 0.0, 0.0
        for j in range(N_STAGES + 1):
            s5 += E5[j] * K[j, i]
            s3 += E3[j] * K[j, i]
        e5 += (s5 / scale) ** 2
        e3 += (s3 / scale) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


@njit(cache=True)
def dop853_dense(model, air, t, y, y_new, h, p, pw, K, ys, F):
    """Coefficients F (7, n) of the 7th-order interpolant on [t, t + h]."""
    n = model_size(model, y)
    for s in range(N_STAGES + 1, N_K):
        _stage_state(n, s, y, h, K, ys)
        derivative(model, air, t + C[s] * h, ys, p, pw, K[s])
    for i in range(n):
        dy = y_new[i] - y[i]
        F[0, i] = dy
        F[1, i] = h * K[0, i] - dy
        F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
        for r in range(D.shape[0]):
            acc = 0.0
            for j in range(N_K):
                acc += D[r, j] * K[j, i]
            F[3 + r, i] = h * acc


@njit(cache=True)
def dop853_interpolate(n, F, y, x, out):
    """Dense output at fraction x of the step (0 <= x <= 1) into out; n = len(y)."""
    m = F.shape[0]
    for i in range(n):
        acc = 0.0
        for k in range(m):
            acc += F[m - 1 - k, i]
            if k % 2 == 0:
                acc *= x
            else:
                acc *= 1.0 - x
        out[i] = acc + y[i]


@njit(cache=True)
def initial_step(model, air, t0, y0, f0, p, pw, rtol, atol, t_end, y1, f1, order):
    """Hairer's starting step (scipy.integrate._ivp.common.select_initial_step).

    ``order``: the exponent is 1 / (order + 1) (DOP853 passes its order 8, Radau its
    error estimate's 3).

    y1, f1: scratch vectors like y0.
    """
    n = y0.shape[0]
    d0, d1 = 0.0, 0.0
    for i in range(n):
        sc = atol + abs(y0[i]) * rtol
        d0 += (y0[i] / sc) ** 2
        d1 += (f0[i] / sc) ** 2
    d0, d1 = math.sqrt(d0 / n), math.sqrt(d1 / n)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, t_end - t0)
    for i in range(n):
        y1[i] = y0[i] + h0 * f0[i]
    derivative(model, air, t0 + h0, y1, p, pw, f1)
    d2 = 0.0
    for i in range(n):
        sc = atol + abs(y0[i]) * rtol
        d2 += ((f1[i] - f0[i]) / sc) ** 2
    d2 = math.sqrt(d2 / n) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (order + 1))
    return min(100 * h0, h1, t_end - t0)
