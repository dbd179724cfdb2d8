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
loop is the innermost loop: the rhs, the stage sums and the interpolant's coefficients
(each a loop over all rows of all lanes, idle lanes included) and the error norm
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
# conditional move per access), and LLVM cannot prove (j*m + r) >= 0, so with signed
# indices the stage, error and interpolant sums below stayed scalar code
U2 = np.uint64(2)


def _stage_sum(s):
    """YS = Y + HR Σ_{j<s} A[s, j] K_j over all m = n*LANES rows of the lane arrays, for
    stage s fixed when compiled (``steps._stage_state``'s sums, per row from 0.0 over j in
    order).  HR holds each lane's step on every row.

    With s a constant the j loop unrolls into one chain of s terms per row, the rows
    (lanes innermost, idle lanes included) vectorise, and A[s, j] are constants: 280 ns
    for the twelve stages of a 6-state step on 8 lanes (AVX-512 EPYC) against 930 ns with
    s a run-time count, whose sums LLVM could not vectorise across the lanes.
    """
    @njit(inline="always", error_model="numpy")
    def stage(m, Y, HR, Ks, YS):
        for r in range(m):
            acc = 0.0
            for j in range(s):
                acc += A[s, j] * Ks[np.uint64(j * m + r)]
            YS[r] = Y[r] + HR[r] * acc
    return stage


def _dispatch(first, last):
    """f(s, m, Y, HR, Ks, YS): the sum of stage s, for first <= s <= last, as a chain of
    tests on s (a constant-s sum per stage, one rhs call site in the step's loop)."""
    head = _stage_sum(first)
    if first == last:
        @njit(inline="always", error_model="numpy")
        def leaf(s, m, Y, HR, Ks, YS):
            head(m, Y, HR, Ks, YS)
        return leaf
    rest = _dispatch(first + 1, last)

    @njit(inline="always", error_model="numpy")
    def branch(s, m, Y, HR, Ks, YS):
        if s == first:
            head(m, Y, HR, Ks, YS)
        else:
            rest(s, m, Y, HR, Ks, YS)
    return branch


# the step's stages and the interpolant's, each chain only where it is called: one chain
# of all fifteen at both call sites compiled thirty sums (a cold compile of the lane
# block took 72 s, against 55 s split and 41 s before the per-stage sums, 2 cores)
_step_stage = _dispatch(1, N_STAGES)
_dense_stage = _dispatch(N_STAGES + 1, N_K - 1)


@njit(cache=True, inline="always")
def _row_steps(n, H, HR):
    """HR[i*LANES + k] = H[k] on every row i (0 on the idle lanes past K)."""
    for i in range(n):
        for k in range(LANES):
            HR[i * LANES + k] = H[k] if k < H.shape[0] else 0.0


# error_model="numpy": a float division gives inf or NaN (IEEE) instead of a branch that
# raises, which would keep LLVM from vectorising the lane loops (integrators/lanes.py)
@njit(cache=True, error_model="numpy")
def dop853_lanes_step(model, Y, H, P, Ks, YS, Y_new, S, HR):
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
    HR : ndarray
        (n*LANES,) out: each lane's step on every row (read by ``dop853_lanes_dense``).
    """
    n = model_size(model, Y)
    m = n * LANES
    _row_steps(n, H, HR)
    for s in range(1, N_STAGES + 1):
        _step_stage(s, m, Y, HR, Ks, YS)
        if s == N_STAGES:
            # row N_STAGES of A is B: the FSAL stage's state is the solution (steps.dop853_step)
            for r in range(m):
                Y_new[r] = YS[r]
        model_rhs_lanes(model, H, YS, P, Ks[s * m:(s + 1) * m], S)


@njit(cache=True, error_model="numpy")
def dop853_lanes_error(n, Ks, H, Y, Y_new, rtol, atol, err, acc):
    """err[k]: ``steps.dop853_error_norm`` of lane k's last step; ``acc`` is (2*LANES,)
    scratch (the norms' sums over the rows).

    The lane loop inside the row loop, each lane's sums over the stages (a constant
    count, unrolled) inside it: the lane loop is then innermost and LLVM vectorises it,
    one lane per vector element.  Measured on an AVX-512 EPYC (8 lanes): 150 ns a call
    against 500 ns for sums four lanes at a time, which compiled to scalar code there.
    Each lane's sums in the scalar function's order; unsigned indices (U2).
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
def dop853_lanes_dense(model, Y, Y_new, H, P, Ks, YS, F, S, HR):
    """F ((7*n)*LANES,): every lane's interpolant coefficients (``steps.dop853_dense``),
    row r of coefficient q at [(q*n + r)*LANES, ...); stages 13..15 of Ks are written.
    HR: the rows' steps of the last ``dop853_lanes_step``."""
    n = model_size(model, Y)
    m = n * LANES
    um, us = np.uint64(m), np.uint64(N_STAGES)
    for s in range(N_STAGES + 1, N_K):
        _dense_stage(s, m, Y, HR, Ks, YS)
        model_rhs_lanes(model, H, YS, P, Ks[s * m:(s + 1) * m], S)
    # every row of every lane (idle lanes included) in one loop of constant length m, each
    # sum over the stages (a constant count, unrolled) inside it: LLVM vectorises across
    # the rows (as _stage_sum)
    for r in range(m):
        ur = np.uint64(r)
        h = HR[r]
        dy = Y_new[r] - Y[r]
        k0 = Ks[r]
        F[ur] = dy
        F[um + ur] = h * k0 - dy
        F[U2 * um + ur] = 2.0 * dy - h * (Ks[us * um + ur] + k0)
    for q in range(D.shape[0]):
        for r in range(m):
            acc = 0.0
            for j in range(N_K):
                acc += D[q, j] * Ks[np.uint64(j * m + r)]
            F[np.uint64((3 + q) * m + r)] = HR[r] * acc


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
