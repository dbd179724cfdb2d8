"""Small dense linear algebra for the compiled loops: LU with partial pivoting, kept.

The implicit scheme (integrators/radau.py) factors its iteration matrices once
and solves with them for many Newton iterations and steps; numpy's solve,
the only dense solver numba offers in compiled code, refactors on every call.
And the Jacobian those matrices need, by finite differences of any model's
generated right-hand side (per-body air included), so no model needs a
generated Jacobian to run implicitly.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import derivative, model_size

EPS = np.finfo(float).eps
# the forward-difference step of the Jacobian, relative to max(|y_j|, 1): √ε balances
# truncation against rounding (J to ~1e-8); FD_STEP_FINE stays inside the taut margin of
# a stiff line at rest (a 1 mm fibre segment of a bead chain stretches by ~1e-9 m, a √ε
# step moves a node ~1e-7 m and crosses its slack kink, so J holds half a spring and
# Newton stalls), at the price of J to ~1e-5, which only slows Newton (radau.py uses it
# once Newton fails with a fresh √ε Jacobian)
FD_STEP = math.sqrt(EPS)
FD_STEP_FINE = 1e-3 * FD_STEP


@njit(cache=True)
def lu_factor(A, piv, n):
    """LU factorisation with partial pivoting of A[:n, :n] (real or complex), in place
    (LAPACK getrf's).

    The factors are kept across Newton iterations and steps, which numpy's solve
    (a factorisation per call) cannot do inside compiled code.
    """
    for k in range(n):
        p = k
        big = abs(A[k, k])
        for i in range(k + 1, n):
            if abs(A[i, k]) > big:
                big, p = abs(A[i, k]), i
        piv[k] = p
        if p != k:
            for j in range(n):
                A[k, j], A[p, j] = A[p, j], A[k, j]
        d = A[k, k]
        if d == 0.0:
            continue  # singular: the solve gives inf/NaN and the step is rejected
        for i in range(k + 1, n):
            A[i, k] /= d
            a = A[i, k]
            if a != 0.0:
                for j in range(k + 1, n):
                    A[i, j] -= a * A[k, j]


# Inlined with the state size n passed in: in the loops n is the model's compile-time
# size (dynamics.model_size), so LLVM unrolls the short rows (a 6 x 6 solve 3x faster;
# the factorisation, ~10x rarer than the solves, is not worth its compile time)
@njit(cache=True, inline="always")
def lu_solve(A, piv, b, n):
    """Solve (the factored A[:n, :n]) x = b in place of b (A, piv from lu_factor)."""
    for k in range(n):
        p = piv[k]
        if p != k:
            b[k], b[p] = b[p], b[k]
    for i in range(n):
        s = b[i]
        for j in range(i):
            s -= A[i, j] * b[j]
        b[i] = s
    for i in range(n - 1, -1, -1):
        s = b[i]
        for j in range(i + 1, n):
            s -= A[i, j] * b[j]
        b[i] = s / A[i, i]


@njit(cache=True)
def fd_jacobian(model, air, t, y, f, p, pw, J, ys, fs, step=FD_STEP):
    """J[i, j] = ∂f_i/∂y_j by forward differences of the generated rhs (f = f(t, y)).

    Steps ``step`` · max(|y_j|, 1) in each state's SI unit (FD_STEP: a relative error
    of ~1e-8 in J; FD_STEP_FINE: see there), which only slows the simplified Newton
    iteration, never the accuracy of the converged step.  ys, fs: scratch vectors.
    """
    n = model_size(model, y)
    for i in range(n):
        ys[i] = y[i]
    for j in range(n):
        d = step * max(abs(y[j]), 1.0)
        ys[j] = y[j] + d
        d = ys[j] - y[j]  # the step actually represented
        derivative(model, air, t, ys, p, pw, fs)
        for i in range(n):
            J[i, j] = (fs[i] - f[i]) / d
        ys[j] = y[j]
