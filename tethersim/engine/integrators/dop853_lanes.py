"""DOP853 on SIMD lanes: a step, its error norm and its dense output over K lanes.

The lane twins of ``steps.dop853_step``, ``steps.dop853_error_norm``,
``steps.dop853_dense`` and ``steps.dop853_interpolate``, in the structure-of-arrays
layout of engine/integrators/lanes.py: row i of a lane quantity sits at
[i*LANES, i*LANES + K), stage s of the stage array ``Ks`` at rows [s*n, (s+1)*n)
(n the state's length, a compile-time constant, so every row is at a constant offset).
Each lane has its own step H[k].  Every lane computes each component with the
scalar functions' operations in their order (the stage sums from 0.0 over j in
order, the error norms summed over i in order): no fast-math, so each lane's
numbers are those of the scalar step bit for bit
(tests/engine/test_dop853_lanes.py).  LLVM vectorises across the lanes where the lane
loop is the innermost loop: the rhs, the error norm and the interpolant's sums
(checked in the assembly on an AVX-512 CPU).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import model_size
from tethersim.engine.integrators.dop853_tableau import E3, E5, N_STAGES, A, D
from tethersim.engine.integrators.lanes import LANES, model_rhs_lanes
from tethersim.engine.integrators.steps import N_K

# unsigned lane indices: numba wraps a negative signed index around (a compare and a
# conditional move per access), and LLVM cannot prove (j*n + i)*LANES + kb + 1 >= 0, so
# with signed indices the stage, error and interpolant sums below stayed scalar code
U1, U2, U3 = np.uint64(1), np.uint64(2), np.uint64(3)


@njit(cache=True, inline="always", error_model="numpy")
def _stage_state_lanes(n, s, Y, H, Ks, YS):
    """YS = Y + H Σ_{j<s} A[s, j] K_j on every lane (steps._stage_state's sums, per lane
    from 0.0 over j in order).

    Four lanes at a time, each in its own scalar accumulator (written for AVX2, four
    lanes to a register): a sum kept in memory would chain every term through a store
    and a load.  The stage count s varies, so the lane loop cannot be the innermost
    one here (dop853_lanes_error); a constant count with the terms past s masked, lanes
    innermost, measured slower on AVX-512 (1200 against 890 ns a step).  K (H's length)
    is a multiple of 4.  Unsigned indices (U1).
    """
    for i in range(n):
        for kb in range(0, H.shape[0], 4):
            a0 = 0.0
            a1 = 0.0
            a2 = 0.0
            a3 = 0.0
            for j in range(s):
                c = A[s, j]
                o = np.uint64((j * n + i) * LANES + kb)
                a0 += c * Ks[o]
                a1 += c * Ks[o + U1]
                a2 += c * Ks[o + U2]
                a3 += c * Ks[o + U3]
            r = np.uint64(i * LANES + kb)
            h = np.uint64(kb)
            YS[r] = Y[r] + H[h] * a0
            YS[r + U1] = Y[r + U1] + H[h + U1] * a1
            YS[r + U2] = Y[r + U2] + H[h + U2] * a2
            YS[r + U3] = Y[r + U3] + H[h + U3] * a3


# error_model="numpy": a float division gives inf or NaN (IEEE) instead of a branch that
# raises, which would keep LLVM from vectorising the lane loops (integrators/lanes.py)
@njit(cache=True, error_model="numpy")
def dop853_lanes_step(model, Y, H, P, Ks, YS, Y_new, S):
    """One DOP853 step of every lane: lane k from Y by H[k] into Y_new.

    Stage 0 of ``Ks`` must hold f(t, Y) (the FSAL stage of the lane's last accepted
    step); stages 1..12 are written, stage 12 = f(t + H, Y_new).  The model is
    autonomous in uniform air (the lane rhs reads no time).

    Parameters
    ----------
    model : int literal
        Model index (a model with a lane rhs, integrators/lanes.py ``has_lanes``).
    Y, Y_new : ndarray
        (n*LANES,) start states, end states.
    H : ndarray
        (K,) steps; K <= LANES, a multiple of 4.
    P : ndarray
        (parameters*LANES,) parameter vectors.
    Ks : ndarray
        (N_K*n*LANES,) stages.
    YS : ndarray
        (n*LANES,) scratch: the stage state.
    S : ndarray
        (model_transcendentals(model)*LANES,) scratch of the lane rhs.
    """
    n = model_size(model, Y)
    m = n * LANES
    for s in range(1, N_STAGES + 1):
        _stage_state_lanes(n, s, Y, H, Ks, YS)
        model_rhs_lanes(model, H, YS, P, Ks[s * m:(s + 1) * m], S)
    # row N_STAGES of A is B: the FSAL stage's state is the solution (steps.dop853_step)
    _stage_state_lanes(n, N_STAGES, Y, H, Ks, Y_new)


@njit(cache=True, error_model="numpy")
def dop853_lanes_error(n, Ks, H, Y, Y_new, rtol, atol, err, acc):
    """err[k]: ``steps.dop853_error_norm`` of lane k's last step; ``acc`` is (2*LANES,)
    scratch (the norms' sums over the rows).

    The lane loop inside the row loop, each lane's sums over the stages (a constant
    count, unrolled) inside it: the lane loop is then innermost and LLVM vectorises it,
    one lane per vector element.  Measured on an AVX-512 EPYC (8 lanes): 150 ns a call
    against 500 ns for sums four lanes at a time, which compiled to scalar code there.
    Each lane's sums in the scalar function's order; unsigned indices (U1).
    """
    K = H.shape[0]
    for k in range(K):
        acc[k] = 0.0
        acc[LANES + k] = 0.0
    for i in range(n):
        for k in range(K):
            s5 = 0.0
            s3 = 0.0
            for j in range(N_STAGES + 1):
                o = np.uint64((j * n + i) * LANES + k)
                s5 += E5[j] * Ks[o]
                s3 += E3[j] * Ks[o]
            r = np.uint64(i * LANES + k)
            scale = atol + max(abs(Y[r]), abs(Y_new[r])) * rtol
            acc[k] += (s5 / scale) ** 2
            acc[LANES + k] += (s3 / scale) ** 2
    for k in range(K):
        e5, e3 = acc[k], acc[LANES + k]
        norm = abs(H[k]) * e5 / math.sqrt((e5 + 0.01 * e3) * n)
        err[k] = 0.0 if e5 == 0.0 and e3 == 0.0 else norm


@njit(cache=True, error_model="numpy")
def dop853_lanes_dense(model, Y, Y_new, H, P, Ks, YS, F, S):
    """F ((7*n)*LANES,): every lane's interpolant coefficients (``steps.dop853_dense``),
    row r of coefficient q at [(q*n + r)*LANES, ...); stages 13..15 of Ks are written."""
    n = model_size(model, Y)
    m = n * LANES
    um, us = np.uint64(m), np.uint64(N_STAGES)
    K = H.shape[0]
    for s in range(N_STAGES + 1, N_K):
        _stage_state_lanes(n, s, Y, H, Ks, YS)
        model_rhs_lanes(model, H, YS, P, Ks[s * m:(s + 1) * m], S)
    for i in range(n):
        for k in range(K):
            r = np.uint64(i * LANES + k)
            h = H[k]
            dy = Y_new[r] - Y[r]
            k0 = Ks[r]
            F[r] = dy
            F[um + r] = h * k0 - dy
            F[U2 * um + r] = 2.0 * dy - h * (Ks[us * um + r] + k0)
        # the lane loop innermost, each lane's sum over the stages (a constant count,
        # unrolled) inside it: LLVM vectorises across the lanes (dop853_lanes_error;
        # 340 ns against 650 ns for sums four lanes at a time, AVX-512, 8 lanes)
        for q in range(D.shape[0]):
            for k in range(K):
                acc = 0.0
                for j in range(N_K):
                    acc += D[q, j] * Ks[np.uint64(j * m + i * LANES + k)]
                F[np.uint64((3 + q) * m + i * LANES + k)] = H[k] * acc


@njit(cache=True)
def dop853_lanes_interpolate(n, k, F, Y, x, out):
    """Lane k's dense output at fraction x of its step into out (``steps.dop853_interpolate``)."""
    m = n * LANES
    q = F.shape[0] // m
    for i in range(n):
        acc = 0.0
        for c in range(q):
            acc += F[np.uint64((q - 1 - c) * m + i * LANES + k)]
            if c % 2 == 0:
                acc *= x
            else:
                acc *= 1.0 - x
        out[i] = acc + Y[i * LANES + k]
