"""Radau IIA of order 5, the pieces of a step: tableau, Newton, controller, dense output.

Why Radau IIA (issue 21).  A tether of a real fibre (EA ~ 1e4-1e5 N on a ~1 kg
balloon) has an axial mode of 40-120 rad/s beside an attitude motion of ~1e-3
rad/s: an explicit scheme (RK4, DOP853, a Taylor method) must resolve the axial
mode, 1e3-1e5 times more steps than the attitude needs.  Radau IIA (3 stages,
order 5) is L-stable (a mode far faster than the step is damped to its
quasi-static balance, not amplified), stiffly accurate (the step's end is its
last stage, so the tether's slow manifold is followed), and its simplified
Newton iteration converges with an approximate Jacobian, so a finite-difference
Jacobian of the generated right-hand side serves every model, per-body air
included.  Rosenbrock methods (RODAS) need the exact Jacobian to keep their
order, which the free-orbit and per-body-air models do not generate; ESDIRK and
IMEX schemes are of lower order for the same number of solves.

The algorithm is scipy.integrate.Radau's (Hairer & Wanner, Solving ODEs II,
Sec. IV.8): the stage system is solved in the eigenbasis of the Butcher matrix
(one real and one complex n x n system), the error is estimated by the embedded
third-order formula filtered through the real matrix, the step size follows the
predictive (Gustafsson) controller, the Jacobian is refreshed only when Newton
converges slowly, and the dense output is the collocation cubic.  One departure:
Newton stops at NEWTON_TOL (0.03) of the error scale at every rtol, where scipy asks
min(0.03, √rtol) (below).  Ported to a
compiled loop: the complex system is factored in complex arithmetic (as scipy and
RADAU5 do; its real 2n x 2n form costs ~1.7x more per solve for n = 6), and the LU
factors are kept across the Newton iterations and steps, as scipy keeps them.

integrators/radau.py runs them in a compiled loop.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import derivative, model_size
from tethersim.engine.integrators.linalg import lu_factor, lu_solve

S6 = 6 ** 0.5
C = np.array([(4 - S6) / 10, (4 + S6) / 10, 1.0])  # collocation nodes
E = np.array([-13 - 7 * S6, -13 + 7 * S6, -1.0]) / 3  # embedded error estimate
# eigenvalues of the inverse Butcher matrix: one real, a complex pair
MU_REAL = 3 + 3 ** (2 / 3) - 3 ** (1 / 3)
MU_RE = 3 + 0.5 * (3 ** (1 / 3) - 3 ** (2 / 3))
MU_IM = -0.5 * (3 ** (5 / 6) + 3 ** (7 / 6))
# the transformation to that eigenbasis and back (scipy.integrate._ivp.radau)
T = np.array([[0.09443876248897524, -0.14125529502095421, 0.03002919410514742],
              [0.25021312296533332, 0.20412935229379994, -0.38294211275726192],
              [1.0, 1.0, 0.0]])
TI = np.array([[4.17871859155190428, 0.32768282076106237, 0.52337644549944951],
               [-4.17871859155190428, -0.32768282076106237, 0.47662355450055044],
               [0.50287263494578682, -2.57192694985560522, 0.59603920482822492]])
# dense output: y(t_old + x h) = y_old + Σ_k Q[:, k] x^(k+1), Q = Zᵀ P
P = np.array([[13 / 3 + 7 * S6 / 3, -23 / 3 - 22 * S6 / 3, 10 / 3 + 5 * S6],
              [13 / 3 - 7 * S6 / 3, -23 / 3 + 22 * S6 / 3, 10 / 3 - 5 * S6],
              [1 / 3, -8 / 3, 10 / 3]])

ORDER = 5
ERROR_ESTIMATOR_ORDER = 3
NEWTON_MAXITER = 6
# Newton stops when its remaining error is estimated below NEWTON_TOL of the error
# scale (Hairer & Wanner IV.8, kappa; RADAU5's fnewt is at most 0.03).  scipy's
# min(0.03, rtol**0.5) asks 1e-3 to 1e-4 of it at rtol 1e-6 to 1e-8: below the
# rounding of a real line's force (EA/l0 x ulp(λ) ~ 1e-11 N), which the stages of a
# long step pick up, so Newton stalled and the steps shrank to a tenth of a second
# (docs/tethers.md, "The implicit scheme's Newton tolerance")
NEWTON_TOL = 0.03
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0


@njit(cache=True)
def _factor(n, h, J, LR, LC, pr, pc):
    # the real system MU_REAL/h − J and the complex (MU_RE + i MU_IM)/h − J (LC complex),
    # each factored once for many solves
    a, ac = MU_REAL / h, complex(MU_RE / h, MU_IM / h)
    for i in range(n):
        for j in range(n):
            LR[i, j] = -J[i, j]
            LC[i, j] = -J[i, j]
        LR[i, i] += a
        LC[i, i] += ac
    lu_factor(LR, pr, n)
    lu_factor(LC, pc, n)


@njit(cache=True)
def _rms(v, n, scale):
    s = 0.0
    for i in range(n):
        s += (v[i] / scale[i]) ** 2
    return math.sqrt(s / n)


@njit(cache=True)
def radau_newton(model, air, t, y, h, p, pw, Z, W, F, ys, br, bc, scale, tol, LR, LC, pr, pc):
    """Solve the collocation system for Z (3, n) by simplified Newton (in place).

    Z holds the initial guess (stage states y + Z[i]).  Returns (converged,
    iterations, convergence rate or -1) as scipy's solve_collocation_system.
    """
    n = model_size(model, y)
    for i in range(n):
        for s in range(3):
            W[s, i] = TI[s, 0] * Z[0, i] + TI[s, 1] * Z[1, i] + TI[s, 2] * Z[2, i]
    a, ar, b = MU_REAL / h, MU_RE / h, MU_IM / h
    norm_old = -1.0
    rate = -1.0
    converged = False
    k = 0
    for k in range(NEWTON_MAXITER):
        finite = True
        for s in range(3):
            for i in range(n):
                ys[i] = y[i] + Z[s, i]
            derivative(model, air, t + C[s] * h, ys, p, pw, F[s])
            for i in range(n):
                if not math.isfinite(F[s, i]):
                    finite = False
        if not finite:
            break
        for i in range(n):
            fr = TI[0, 0] * F[0, i] + TI[0, 1] * F[1, i] + TI[0, 2] * F[2, i]
            fre = TI[1, 0] * F[0, i] + TI[1, 1] * F[1, i] + TI[1, 2] * F[2, i]
            fim = TI[2, 0] * F[0, i] + TI[2, 1] * F[1, i] + TI[2, 2] * F[2, i]
            br[i] = fr - a * W[0, i]
            bc[i] = complex(fre - (ar * W[1, i] - b * W[2, i]), fim - (ar * W[2, i] + b * W[1, i]))
        lu_solve(LR, pr, br, n)
        lu_solve(LC, pc, bc, n)
        dn = 0.0
        for i in range(n):
            dn += (br[i] / scale[i]) ** 2 + (bc[i].real / scale[i]) ** 2 + (bc[i].imag / scale[i]) ** 2
        dn = math.sqrt(dn / (3 * n))
        if norm_old >= 0.0:
            rate = dn / norm_old
        if rate >= 0.0 and (rate >= 1.0 or rate ** (NEWTON_MAXITER - k) / (1 - rate) * dn > tol):
            break
        if not math.isfinite(dn):
            break
        for i in range(n):
            W[0, i] += br[i]
            W[1, i] += bc[i].real
            W[2, i] += bc[i].imag
            for s in range(3):
                Z[s, i] = T[s, 0] * W[0, i] + T[s, 1] * W[1, i] + T[s, 2] * W[2, i]
        if dn == 0.0 or (rate >= 0.0 and rate / (1 - rate) * dn < tol):
            converged = True
            break
        norm_old = dn
    return converged, k + 1, rate


@njit(cache=True)
def _predict_factor(h_abs, h_abs_old, err, err_old):
    # Hairer & Wanner's predictive controller (scipy.integrate._ivp.radau.predict_factor)
    if err_old <= 0.0 or h_abs_old <= 0.0 or err == 0.0:
        multiplier = 1.0
    else:
        multiplier = h_abs / h_abs_old * (err_old / err) ** 0.25
    if err == 0.0:
        return math.inf
    return min(1.0, multiplier) * err ** -0.25


@njit(cache=True)
def _dense(n, Q, y_old, x, out):
    for i in range(n):
        out[i] = y_old[i] + x * (Q[i, 0] + x * (Q[i, 1] + x * Q[i, 2]))


@njit(cache=True)
def _dense_tau(n, Q, h, W):
    """W[k] = Q[:, k] / h^(k+1): the cubic's coefficients per power of τ = t − t_old, the
    form integrators/switching.py's trial (method 2) evaluates."""
    for i in range(n):
        W[0, i] = Q[i, 0] / h
        W[1, i] = Q[i, 1] / (h * h)
        W[2, i] = Q[i, 2] / (h * h * h)


@njit(cache=True)
def _dense_q(n, Z, Q):
    for i in range(n):
        for k in range(3):
            Q[i, k] = Z[0, i] * P[0, k] + Z[1, i] * P[1, k] + Z[2, i] * P[2, k]
