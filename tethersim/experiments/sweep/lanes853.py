"""The adaptive (DOP853) sweep block on SIMD lanes: K points advance together.

``sweep_block_lanes853`` computes what ``kernel.sweep_block`` computes for
``faithful=False`` (``dop853_run`` per point, switches located), record for record
(tests/experiments/test_sweep_lanes853.py), with K points of the block in the K lanes
of structure-of-arrays arrays (engine/integrators/dop853_lanes.py).  Every pass takes
one DOP853 step of all lanes, whose stages LLVM vectorises across the lanes; what
``dop853._dop853_loop`` decides, each lane decides for itself, in the same order:

* its own step size, step count, error norm, acceptance or rejection and next step
  (a rejecting lane retries with its smaller step at the next pass, the others go on);
* the interpolant's three extra stages of a step in which an output falls: the step
  (its start, end, stages, parameters, step and output rows) waits in a queue of
  LANES slots, and a full queue takes the three stages on every slot at once, then
  each slot's outputs from its own coefficients.  With 200 outputs an orbit and about
  800 steps, a pass had 1-2 lanes needing them: the extra stages on all lanes at
  once used a quarter of their work (the queue is emptied before a lane's point is
  recorded, so a point's outputs are all written when it is measured);
* its slack/taut switches and stopping limits: a lane whose accepted step changes the
  sign of an event slot redoes the step alone with the scalar code (``switching.locate``
  and ``steps.dop853_dense``, the scalar loop's calls on the same numbers);
* a finished lane (its end, a limit, a non-finite state, a step limit) is measured
  (``kernel._measure``) and takes the block's next point, its start (events, f, first
  step) computed by the scalar loop's own calls.

An idle lane (no point left) steps its last state by zero, unread.  Only the held
circular orbit in uniform air runs here (``batch._compiled`` picks this block then).
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.analysis.metrics_kernel import N_PITCH
from tethersim.engine.dynamics import derivative
from tethersim.engine.events import N_EVENTS, N_SWITCH, model_events
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.dop853 import (
    ERROR_EXPONENT,
    MAX_FACTOR,
    MIN_FACTOR,
    ORDER,
    SAFETY,
    STATUS_EVENT,
    STATUS_MAX_STEPS,
    STATUS_NONFINITE,
    STATUS_OK,
    STATUS_STEP_TOO_SMALL,
)
from tethersim.engine.integrators.dop853_lanes import (
    dop853_lanes_dense,
    dop853_lanes_error,
    dop853_lanes_interpolate,
    dop853_lanes_step,
)
from tethersim.engine.integrators.lanes import LANES, model_transcendentals
from tethersim.engine.integrators.steps import N_K, dop853_dense, dop853_interpolate, initial_step
from tethersim.experiments.sweep.kernel import _adaptive_status, _measure

# lane[k, :] columns, and the lane states of column ST (>= 0: a finished point's loop status)
J, STEPS, IOUT, NFEV, REJ, FRESH, ST, SLOT, DENSE = range(9)
RUNNING, IDLE, EMPTY = -1, -2, -3


@njit(cache=True, nogil=True)
def _load(model, air, k, j, Y0, P, span, EV, rtol, atol, Y, PL, Ks, TL, HL, TE, g0, lane,
          out_y, y, f, pw, F):
    """Point j into lane k: dop853._dop853_loop's start (events, f, first step)."""
    ns = Y0.shape[1]
    for i in range(ns):
        y[i] = Y0[j, i]
        Y[i * LANES + k] = y[i]
        out_y[k, 0, i] = y[i]
    for i in range(P.shape[1]):
        PL[i * LANES + k] = P[j, i]
        pw[i] = P[j, i]
    lane[k, J], lane[k, STEPS], lane[k, IOUT], lane[k, NFEV] = j, 0, 1, 0
    lane[k, REJ], lane[k, FRESH], lane[k, ST], lane[k, SLOT] = 0, 1, RUNNING, -1
    TL[k], TE[k] = 0.0, span[j]
    model_events(model, y, P[j], EV[j], g0[k], True)
    for s in range(N_SWITCH, N_EVENTS):
        if g0[k, s] <= 0.0:  # the start is outside: stop before any step
            lane[k, ST], lane[k, SLOT] = STATUS_EVENT, s
            return
    derivative(model, air, 0.0, y, P[j], pw, f)
    lane[k, NFEV] = 1
    for i in range(ns):
        Ks[i * LANES + k] = f[i]  # stage 0: f at the lane's state
        if not math.isfinite(f[i]):
            lane[k, ST] = STATUS_NONFINITE
            return
    h = initial_step(model, air, 0.0, y, f, P[j], pw, rtol, atol, span[j], F[0], F[1], ORDER)
    lane[k, NFEV] = 2
    HL[k] = h
    if not math.isfinite(h):
        lane[k, ST] = STATUS_NONFINITE


@njit(cache=True, nogil=True)
def _ready(k, max_steps, TL, HL, TE, H, lane):
    """The top of the scalar loop's step (and of its retry after a rejection): True when
    lane k steps now by H[k], else its loop status is set."""
    t = TL[k]
    if lane[k, FRESH] == 1:
        if not t < TE[k]:
            lane[k, ST] = STATUS_OK
            return False
        if lane[k, STEPS] >= max_steps:
            lane[k, ST] = STATUS_MAX_STEPS
            return False
        lane[k, STEPS] += 1
        lane[k, REJ] = 0
        lane[k, FRESH] = 0
    min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
    if not (HL[k] >= min_step):  # written so that a NaN step also stops
        lane[k, ST] = STATUS_STEP_TOO_SMALL
        return False
    H[k] = min(HL[k], TE[k] - t)
    return True


@njit(cache=True, nogil=True)
def _finish(model, air, k, lane, TL, T, out_y, P, cols, tol, ss_fraction, rec_f, rec_i, buf,
            pm):
    """kernel._block_loop's record of lane k's finished point."""
    j, n, st = lane[k, J], lane[k, IOUT], lane[k, ST]
    # a located stop is not a row of the grid (simulate appends it)
    end_time = TL[k] if st == STATUS_EVENT else T[j, n - 1]
    _measure(j, model, air, P[j], T[j], out_y[k], n, _adaptive_status(st, lane[k, SLOT]),
             lane[k, NFEV], end_time, cols, tol, ss_fraction, rec_f, rec_i, buf, pm)


@njit(cache=True, nogil=True)
def _located(model, air, k, T, P, EV, Y, Ks, TL, H, lane, out_y, g0, g1, y, f, yn, pw, work,
             Fs, g):
    """Lane k's accepted step crosses an event slot: the scalar loop's location, dense output
    and update on the lane's numbers; returns the event slot that stops it (-1: a switch)."""
    ns = y.shape[0]
    j = lane[k, J]
    for i in range(ns):
        y[i] = Y[i * LANES + k]
        f[i] = Ks[i * LANES + k]
    for i in range(pw.shape[0]):
        pw[i] = P[j, i]
    t = TL[k]
    h_try, hit = switching.locate(1, model, air, t, y, f, H[k], P[j], pw, EV[j], work, yn,
                                  g0[k], g1[k], g, True)
    if hit < N_SWITCH:
        hit = -1
    t_new = t + h_try
    t_last = t_new if hit < 0 else np.nextafter(t_new, -np.inf)
    i_out, rows = lane[k, IOUT], T.shape[1]
    if i_out < rows and T[j, i_out] <= t_last:
        dop853_dense(model, air, t, y, yn, h_try, P[j], pw, work[:N_K], work[N_K], Fs)
        lane[k, NFEV] += 3
    while i_out < rows and T[j, i_out] <= t_last:
        dop853_interpolate(ns, Fs, y, (T[j, i_out] - t) / h_try, out_y[k, i_out])
        i_out += 1
    lane[k, IOUT] = i_out
    for i in range(ns):
        Y[i * LANES + k] = yn[i]
        Ks[i * LANES + k] = work[12, i]
    TL[k] = t_new
    return hit


@njit(cache=True, nogil=True)
def _flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS, Fd, S, queued):
    """The interpolant of every queued step (one ``dop853_lanes_dense`` over the slots,
    the scalar ``dop853_dense``'s numbers slot by slot) and their outputs; returns 0,
    the queue's new length."""
    if queued == 0:
        return 0
    ns = out_y.shape[2]
    dop853_lanes_dense(model, QY, QYn, QH, QP, QK, YS, Fd, S, QHR)
    for q in range(queued):
        k, j, r0, r1 = QI[q, 0], QI[q, 1], QI[q, 2], QI[q, 3]
        t, h = QT[q, 0], QT[q, 1]
        for i_out in range(r0, r1):
            dop853_lanes_interpolate(ns, q, Fd, QY, (T[j, i_out] - t) / h, out_y[k, i_out])
    return 0


# inlined, and unsigned indices (dop853_lanes.U2 says why): a call that passes twenty
# arrays, 64,000 times in the bench's 64-point sweep, took 3-4 of its 104 ms
@njit(cache=True, nogil=True, inline="always")
def _enqueue(k, npar, T, Y, Y_new, PL, Ks, TL, H, lane, QY, QYn, QH, QP, QK, QHR, QT, QI,
             queued):
    """Lane k's accepted step, in which an output falls, into queue slot ``queued`` (its
    outputs written at the next _flush); returns the queue's new length."""
    ns = Y.shape[0] // LANES
    m = ns * LANES
    q = queued
    j, i_out, rows = lane[k, J], lane[k, IOUT], T.shape[1]
    t, h = TL[k], H[k]
    uk, uq, ul = np.uint64(k), np.uint64(q), np.uint64(LANES)
    for i in range(ns):
        a, b = np.uint64(i) * ul + uk, np.uint64(i) * ul + uq
        QY[b] = Y[a]
        QYn[b] = Y_new[a]
        QHR[b] = h
    for s in range(N_K - 3):  # the step's stages 0..12 (the dense ones are computed)
        for i in range(ns):
            o = np.uint64(s * m + i * LANES)
            QK[o + uq] = Ks[o + uk]
    for i in range(npar):
        QP[np.uint64(i) * ul + uq] = PL[np.uint64(i) * ul + uk]
    QH[q] = h
    QT[q, 0], QT[q, 1] = t, h
    r0 = i_out
    while i_out < rows and T[j, i_out] <= t + h:
        i_out += 1
    QI[q, 0], QI[q, 1], QI[q, 2], QI[q, 3] = k, j, r0, i_out
    lane[k, IOUT] = i_out
    lane[k, NFEV] += 3
    return queued + 1


@njit(cache=True, nogil=True)
def _lanes853_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, Y, PL, Ks, YS, Y_new, HR, S, Fd, H, TL, HL, HN,
                   TE, err, acc, lane, g0, g1, out_y, y, f, yn, pw, work, Fs, g, buf, pm,
                   QY, QYn, QH, QP, QK, QHR, QT, QI):
    air, T, Y0, P, span, EV, cols = (borrow(air), borrow(T), borrow(Y0), borrow(P),
                                     borrow(span), borrow(EV), borrow(cols))
    rec_f, rec_i, Y, PL, Ks, YS = (borrow(rec_f), borrow(rec_i), borrow(Y), borrow(PL),
                                   borrow(Ks), borrow(YS))
    Y_new, HR, S, Fd, H, TL = (borrow(Y_new), borrow(HR), borrow(S), borrow(Fd), borrow(H),
                               borrow(TL))
    HL, HN, TE, err, acc = borrow(HL), borrow(HN), borrow(TE), borrow(err), borrow(acc)
    lane, g0, g1, out_y, y, f = (borrow(lane), borrow(g0), borrow(g1), borrow(out_y),
                                 borrow(y), borrow(f))
    yn, pw, work, Fs, g, buf, pm = (borrow(yn), borrow(pw), borrow(work), borrow(Fs),
                                    borrow(g), borrow(buf), borrow(pm))
    QY, QYn, QH, QP, QK, QHR, QT, QI = (borrow(QY), borrow(QYn), borrow(QH), borrow(QP),
                                        borrow(QK), borrow(QHR), borrow(QT), borrow(QI))
    ns = Y0.shape[1]
    npar = P.shape[1]
    m = ns * LANES
    K = H.shape[0]
    rows = T.shape[1]
    n_points = P.shape[0]
    nxt = 0
    active = K
    queued = 0  # steps waiting for their interpolant (_enqueue)
    while True:
        # each lane's step begins (a finished lane is recorded and takes the next point)
        for k in range(K):
            while lane[k, ST] != IDLE:
                if lane[k, ST] == RUNNING and _ready(k, max_steps, TL, HL, TE, H, lane):
                    break
                if lane[k, ST] != EMPTY:
                    queued = _flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS,
                                    Fd, S, queued)  # the point's last outputs
                    _finish(model, air, k, lane, TL, T, out_y, P, cols, tol, ss_fraction,
                            rec_f, rec_i, buf, pm)
                if nxt >= n_points:
                    lane[k, ST] = IDLE
                    H[k] = 0.0
                    active -= 1
                    break
                _load(model, air, k, nxt, Y0, P, span, EV, rtol, atol, Y, PL, Ks, TL, HL, TE,
                      g0, lane, out_y, y, f, pw, Fs)
                nxt += 1
        if active == 0:
            return
        dop853_lanes_step(model, Y, H, PL, Ks, YS, Y_new, S, HR)
        dop853_lanes_error(ns, Ks, H, Y, Y_new, rtol, atol, err, acc)
        for k in range(K):
            lane[k, DENSE] = 0
            if lane[k, ST] != RUNNING:
                continue
            lane[k, NFEV] += 12
            e = err[k]
            if not math.isfinite(e):
                e = 1e10  # a NaN/inf stage: reject and shrink the step (MIN_FACTOR)
            if not e < 1.0:
                HL[k] = H[k] * max(MIN_FACTOR, SAFETY * e ** ERROR_EXPONENT)
                lane[k, REJ] = 1
                continue
            factor = MAX_FACTOR if e == 0.0 else min(MAX_FACTOR, SAFETY * e ** ERROR_EXPONENT)
            if lane[k, REJ] == 1:
                factor = min(1.0, factor)
            HN[k] = H[k] * factor
            j = lane[k, J]
            for i in range(ns):
                yn[i] = Y_new[i * LANES + k]
            model_events(model, yn, P[j], EV[j], g1[k], True)
            if switching.fired(g0[k], g1[k], True):
                hit = _located(model, air, k, T, P, EV, Y, Ks, TL, H, lane, out_y, g0, g1, y,
                               f, yn, pw, work, Fs, g)
                lane[k, DENSE] = 2  # done
                if hit >= 0:
                    lane[k, ST], lane[k, SLOT] = STATUS_EVENT, hit
            else:
                lane[k, DENSE] = 1
                i_out = lane[k, IOUT]
                if i_out < rows and T[j, i_out] <= TL[k] + H[k]:
                    lane[k, DENSE] = 3
        for k in range(K):
            d = lane[k, DENSE]
            if d == 0:
                continue
            if d == 3:  # an output falls in the step: its interpolant waits in the queue
                if queued == LANES:
                    queued = _flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS,
                                    Fd, S, queued)
                queued = _enqueue(k, npar, T, Y, Y_new, PL, Ks, TL, H, lane, QY, QYn, QH, QP,
                                  QK, QHR, QT, QI, queued)
            if d != 2:  # the step is taken: y, f (FSAL) and the time move on
                for i in range(ns):
                    Y[i * LANES + k] = Y_new[i * LANES + k]
                    Ks[i * LANES + k] = Ks[12 * m + i * LANES + k]
                TL[k] = TL[k] + H[k]
            for i in range(N_EVENTS):
                g0[k, i] = g1[k, i]
            HL[k] = HN[k]
            lane[k, FRESH] = 1
            if lane[k, ST] != RUNNING:
                continue
            for i in range(ns):
                if not math.isfinite(Y[i * LANES + k]):
                    lane[k, ST] = STATUS_NONFINITE
                    break


# nogil: the sweep's threads run blocks side by side
@njit(cache=True, nogil=True)
def sweep_block_lanes853(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                         ss_fraction, rec_f, rec_i, K):
    """``kernel.sweep_block(faithful=False)`` on K lanes: the same records.

    Parameters
    ----------
    model : int
        Model index (a compile-time literal), a model with a lane rhs
        (engine/integrators/lanes.py ``has_lanes``), circular orbit.
    air : ndarray
        The uniform air vector.
    T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol, ss_fraction, rec_f, rec_i
        As :func:`tethersim.experiments.sweep.kernel.sweep_block` (T: each point's
        output grid; span: each point's end time [s]).  Y0 is not overwritten.
    K : int
        Lanes: 4 or 8, at most LANES (engine/integrators/lanes.py ``lane_count``).
    """
    literally(model)
    if K % 4 != 0 or not 0 < K <= LANES:
        raise ValueError("K: the lanes must be 4 or 8")
    ns, npar = Y0.shape[1], P.shape[1]
    rows = T.shape[1]
    m = ns * LANES
    Y = np.zeros(m)  # an idle lane steps zeros, never uninitialised (denormal) data
    PL = np.zeros(npar * LANES)
    Ks = np.zeros(N_K * m)
    YS, Y_new, HR = np.zeros(m), np.zeros(m), np.zeros(m)
    S = np.zeros(model_transcendentals(model) * LANES)
    Fd = np.zeros(7 * m)
    H, TL, HL, HN, TE = np.zeros(K), np.zeros(K), np.zeros(K), np.zeros(K), np.zeros(K)
    err, acc = np.zeros(K), np.zeros(2 * LANES)  # the error norms, their sums' scratch
    lane = np.zeros((K, 9), dtype=np.int64)
    for k in range(K):
        lane[k, ST] = EMPTY
    g0, g1 = np.ones((K, N_EVENTS)), np.ones((K, N_EVENTS))
    out_y = np.zeros((K, rows, ns))
    y, f, yn = np.empty(ns), np.empty(ns), np.empty(ns)
    pw = np.empty(npar)
    work = np.empty((N_K + 1, ns))
    Fs = np.empty((7, ns))
    g = np.empty(N_EVENTS)
    buf = np.empty(rows)
    pm = np.empty(N_PITCH)
    # the queue of steps waiting for their interpolant: LANES slots in the lane layout (a
    # slot never read holds zeros, not uninitialised data), each slot's lane, point and
    # output rows (QI) and start time and step (QT)
    QY, QYn, QHR = np.zeros(m), np.zeros(m), np.zeros(m)
    QH, QP, QK = np.zeros(LANES), np.zeros(npar * LANES), np.zeros(N_K * m)
    QT, QI = np.zeros((LANES, 2)), np.zeros((LANES, 4), dtype=np.int64)
    _lanes853_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, Y, PL, Ks, YS, Y_new, HR, S, Fd, H, TL, HL, HN,
                   TE, err, acc, lane, g0, g1, out_y, y, f, yn, pw, work, Fs, g, buf, pm,
                   QY, QYn, QH, QP, QK, QHR, QT, QI)
