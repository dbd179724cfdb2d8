"""The compiled Radau IIA loop (pieces: integrators/radau_step.py; why Radau: there).

``radau_run`` has dop853_run's arguments and returns, so simulate() drives
either the same way; ``counters`` gains Jacobian evaluations and LU
factorisations (slots 5, 6) and ``carry`` keeps what a run resumed in calls
needs (Jacobian, controller memory, last dense output) to take exactly the
steps of one call.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.engine.dynamics import derivative, model_size
from tethersim.engine.events import N_EVENTS, N_SWITCH, is_switch, model_events, model_n_events
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.dop853 import (
    STATUS_EVENT,
    STATUS_MAX_STEPS,
    STATUS_NONFINITE,
    STATUS_OK,
    STATUS_STEP_TOO_SMALL,
)
from tethersim.engine.integrators.linalg import EPS, FD_STEP, FD_STEP_FINE, fd_jacobian, lu_solve
from tethersim.engine.integrators.radau_step import (
    ERROR_ESTIMATOR_ORDER,
    MAX_FACTOR,
    MIN_FACTOR,
    NEWTON_MAXITER,
    NEWTON_TOL,
    C,
    E,
    _dense,
    _dense_q,
    _dense_tau,
    _factor,
    _predict_factor,
    _rms,
    radau_newton,
)
from tethersim.engine.integrators.steps import initial_step

N_COUNTERS = 7  # nfev, accepted, rejected, switches, steps, Jacobians, LU factorisations


@njit(cache=True)
def carry_size(n: int) -> int:
    """Length of the float array radau_run keeps between calls for a state of length n."""
    return 8 + n * n + 4 * n


# carry layout: what a run resumed in calls needs to take exactly one call's steps
_C_STARTED, _C_CURRENT_JAC, _C_H_OLD, _C_ERR_OLD, _C_HAVE_SOL, _C_T_OLD, _C_H_LAST = range(7)
_C_FINE = 7  # 1: the Jacobian held was taken with the fine difference step
_C_J = 8


@njit(cache=True, nogil=True)
def _radau_loop(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y, i_out,
                max_steps, counters, carry, t_pause, Z, W, F, Q, J, LR, LC, pr, pc, v, bc, g):
    y, p, pw, out_t, out_y = borrow(y), borrow(p), borrow(pw), borrow(out_t), borrow(out_y)
    air, ev, counters, carry = borrow(air), borrow(ev), borrow(counters), borrow(carry)
    Z, W, F, Q, J, LR, LC = borrow(Z), borrow(W), borrow(F), borrow(Q), borrow(J), borrow(LR), borrow(LC)
    pr, pc, v, bc, g = borrow(pr), borrow(pc), borrow(v), borrow(bc), borrow(g)
    n = model_size(model, y)
    f, y_new, f_new, ys, fs, scale, err, y_old = v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]
    br = v[8]
    # what the previous call left (carry): Jacobian, controller memory, last dense output
    for i in range(n):
        for j in range(n):
            J[i, j] = carry[_C_J + i * n + j]
        for k in range(3):
            Q[i, k] = carry[_C_J + n * n + 3 * i + k]
        y_old[i] = carry[_C_J + n * n + 3 * n + i]
    t = t0
    g0, g1 = g[0], g[1]
    model_events(model, y, p, ev, g0, locate)
    for j in range(N_SWITCH, N_EVENTS):
        if not g0[j] > 0.0:  # the start is outside (or NaN): stop before any step
            return t, h, i_out, STATUS_EVENT, j
    derivative(model, air, t, y, p, pw, f)
    counters[0] += 1
    for i in range(n):
        if not math.isfinite(f[i]):
            return t, h, i_out, STATUS_NONFINITE, -1
    fd_step = FD_STEP_FINE if carry[_C_FINE] != 0.0 else FD_STEP  # the step of J held
    if carry[_C_STARTED] == 0.0:
        fd_jacobian(model, air, t, y, f, p, pw, J, ys, fs, fd_step)
        counters[0] += n
        counters[5] += 1
        carry[_C_STARTED], carry[_C_CURRENT_JAC] = 1.0, 1.0
        carry[_C_H_OLD], carry[_C_ERR_OLD], carry[_C_HAVE_SOL] = -1.0, -1.0, 0.0
    current_jac = carry[_C_CURRENT_JAC] != 0.0
    h_abs_old, err_old = carry[_C_H_OLD], carry[_C_ERR_OLD]
    have_sol, t_old, h_last = carry[_C_HAVE_SOL] != 0.0, carry[_C_T_OLD], carry[_C_H_LAST]
    if h <= 0.0:
        h = initial_step(model, air, t, y, f, p, pw, rtol, atol, t_end, ys, fs,
                         ERROR_ESTIMATOR_ORDER)
        counters[0] += 1
    if not math.isfinite(h):
        return t, h, i_out, STATUS_NONFINITE, -1
    newton_tol = max(10 * EPS / rtol, NEWTON_TOL)
    h_abs = h
    lu_h = -1.0  # the step the LU factors are for (-1: none)
    steps = 0
    while t < t_end and t < t_pause:
        if steps >= max_steps:
            return t, h_abs, i_out, STATUS_MAX_STEPS, -1
        steps += 1
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if h_abs < min_step:
            h_abs, h_abs_old, err_old = min_step, -1.0, -1.0
        rejected = False
        h_start = h_abs  # the controller's memory is the step predicted, not the one taken
        while True:
            if not (h_abs >= min_step):
                return t, h_abs, i_out, STATUS_STEP_TOO_SMALL, -1
            t_new = min(t + h_abs, t_end)
            hs = t_new - t
            for i in range(n):
                scale[i] = atol + abs(y[i]) * rtol
            converged = False
            while True:
                # predictor: the last step's collocation cubic, extrapolated
                for s in range(3):
                    if have_sol:
                        _dense(n, Q, y_old, 1.0 + hs * C[s] / h_last, ys)
                        for i in range(n):
                            Z[s, i] = ys[i] - y[i]
                    else:
                        for i in range(n):
                            Z[s, i] = 0.0
                if lu_h != hs:
                    _factor(n, hs, J, LR, LC, pr, pc)
                    lu_h = hs
                    counters[6] += 1
                converged, n_iter, rate = radau_newton(model, air, t, y, hs, p, pw, Z, W, F,
                                                       ys, br, bc, scale, newton_tol, LR, LC,
                                                       pr, pc)
                counters[0] += 3 * n_iter
                if converged or (current_jac and fd_step == FD_STEP_FINE):
                    break
                # Newton fails with a fresh Jacobian: a stiff line's slack kink may lie
                # inside the difference step; retry with the fine one (linalg.FD_STEP_FINE)
                fd_step = FD_STEP_FINE if current_jac else FD_STEP
                fd_jacobian(model, air, t, y, f, p, pw, J, ys, fs, fd_step)
                counters[0] += n
                counters[5] += 1
                current_jac = True
                lu_h = -1.0
            if not converged:
                h_abs = 0.5 * hs
                lu_h = -1.0
                counters[2] += 1
                rejected = True
                continue
            for i in range(n):
                y_new[i] = y[i] + Z[2, i]
                ze = (Z[0, i] * E[0] + Z[1, i] * E[1] + Z[2, i] * E[2]) / hs
                F[0, i] = ze  # F is free after Newton: the filtered error's right side
                err[i] = f[i] + ze
            lu_solve(LR, pr, err, n)
            for i in range(n):
                scale[i] = atol + max(abs(y[i]), abs(y_new[i])) * rtol
            err_norm = _rms(err, n, scale)
            safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
            if rejected and err_norm > 1.0:
                for i in range(n):
                    ys[i] = y[i] + err[i]
                derivative(model, air, t, ys, p, pw, fs)
                counters[0] += 1
                for i in range(n):
                    err[i] = fs[i] + F[0, i]
                lu_solve(LR, pr, err, n)
                err_norm = _rms(err, n, scale)
            if not math.isfinite(err_norm):
                err_norm = 1e10
            if err_norm > 1.0:
                factor = _predict_factor(hs, h_abs_old, err_norm, err_old)
                h_abs = hs * max(MIN_FACTOR, safety * factor)
                lu_h = -1.0
                rejected = True
                counters[2] += 1
                continue
            break
        recompute_jac = n_iter > 2 and rate > 1e-3
        factor = min(MAX_FACTOR, safety * _predict_factor(hs, h_abs_old, err_norm, err_old))
        if not recompute_jac and factor < 1.2:
            factor = 1.0
        else:
            lu_h = -1.0
        h_next = hs * factor
        _dense_q(n, Z, Q)
        # events (engine/events.py): located on the step's collocation cubic
        # (switching.locate, method 2), then the step is retaken to land on the crossing
        hit = -1
        model_events(model, y_new, p, ev, g1, locate)
        if switching.fired(g0, g1, locate):
            _dense_tau(n, Q, hs, W)
            tau, hit = switching.locate(2, model, air, t, y, f, hs, p, pw, ev, W, y_new, g0,
                                        g1, g[2], locate)
            if tau < hs:  # y_new is the cubic's value there; a converged step replaces it
                for s in range(3):
                    for i in range(n):
                        Z[s, i] = C[s] * tau * (W[0, i] + C[s] * tau * (W[1, i] + C[s] * tau
                                                                          * W[2, i]))
                _factor(n, tau, J, LR, LC, pr, pc)
                counters[6] += 1
                lu_h = -1.0
                ok, it, _ = radau_newton(model, air, t, y, tau, p, pw, Z, W, F, ys, br, bc,
                                         scale, newton_tol, LR, LC, pr, pc)
                counters[0] += 3 * it
                if ok:
                    for i in range(n):
                        y_new[i] = y[i] + Z[2, i]
                    _dense_q(n, Z, Q)
                    model_events(model, y_new, p, ev, g1, locate)
                else:  # the cubic's state stands, and the cubic, rescaled to the shorter step
                    r = tau / hs
                    for i in range(n):
                        Q[i, 0] *= r
                        Q[i, 1] *= r * r
                        Q[i, 2] *= r * r * r
                hs = tau
                t_new = t + tau
            if is_switch(hit):
                counters[3] += 1
                hit = -1
        counters[1] += 1
        derivative(model, air, t_new, y_new, p, pw, f_new)
        counters[0] += 1
        if recompute_jac:
            fd_step = FD_STEP
            fd_jacobian(model, air, t_new, y_new, f_new, p, pw, J, ys, fs, fd_step)
            counters[0] += n
            counters[5] += 1
            current_jac = True
        else:
            current_jac = False
        # a step that ends on a stopping limit writes the outputs before it only (dop853.py)
        t_last = t_new if hit < 0 else np.nextafter(t_new, -np.inf)
        while i_out < out_t.shape[0] and out_t[i_out] <= t_last:
            _dense(n, Q, y, (out_t[i_out] - t) / hs, out_y[i_out])
            i_out += 1
        h_abs_old, err_old = h_start, err_norm
        for i in range(n):
            y_old[i] = y[i]
            y[i] = y_new[i]
            f[i] = f_new[i]
        for i in range(g0.shape[0]):
            g0[i] = g1[i]
        t_old, h_last, have_sol = t, hs, True
        t = t_new
        h_abs = h_next
        if hit >= 0:
            counters[4] += steps
            return t, h_abs, i_out, STATUS_EVENT, hit
        for i in range(n):
            if not math.isfinite(y[i]):
                return t, h_abs, i_out, STATUS_NONFINITE, -1
    counters[4] += steps
    # what the next call needs to continue exactly as one call would
    carry[_C_CURRENT_JAC] = 1.0 if current_jac else 0.0
    carry[_C_FINE] = 1.0 if fd_step == FD_STEP_FINE else 0.0
    carry[_C_H_OLD], carry[_C_ERR_OLD] = h_abs_old, err_old
    carry[_C_HAVE_SOL], carry[_C_T_OLD], carry[_C_H_LAST] = 1.0 if have_sol else 0.0, t_old, h_last
    for i in range(n):
        for j in range(n):
            carry[_C_J + i * n + j] = J[i, j]
        for k in range(3):
            carry[_C_J + n * n + 3 * i + k] = Q[i, k]
        carry[_C_J + n * n + 3 * n + i] = y_old[i]
    return t, h_abs, i_out, STATUS_OK, -1


@njit(cache=True, nogil=True)
def radau_run(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y, i_out,
              max_steps, counters, carry, t_pause=math.inf):
    """Integrate y (in place) from t0 to t_end with Radau IIA (order 5).

    Parameters and returns as :func:`tethersim.engine.integrators.dop853.dop853_run`,
    with ``counters`` int64[7] (adds Jacobian evaluations and LU factorisations)
    and ``carry``, a float array of :func:`carry_size` zeros before the first call,
    holding what a run resumed in calls needs to take exactly one call's steps.
    """
    literally(model)
    n = y.shape[0]
    Z = np.empty((3, n))
    W = np.empty((3, n))
    F = np.empty((3, n))
    Q = np.empty((n, 3))
    J = np.empty((n, n))
    LR = np.empty((n, n))
    LC = np.empty((n, n), dtype=np.complex128)
    pr = np.empty(n, dtype=np.int64)
    pc = np.empty(n, dtype=np.int64)
    v = np.empty((9, n))
    bc = np.empty(n, dtype=np.complex128)
    g = np.empty((3, model_n_events(model, y)))  # events at both ends of a step, and a trial
    return _radau_loop(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y,
                       i_out, max_steps, counters, carry, t_pause, Z, W, F, Q, J, LR, LC, pr,
                       pc, v, bc, g)
