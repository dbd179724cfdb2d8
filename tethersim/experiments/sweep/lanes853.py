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
  waits in a queue of LANES slots that computes them on every slot at once
  (sweep/lanes_dense.py), emptied before a lane's point is recorded;
* its slack/taut switches and stopping limits: a lane whose accepted step changes the
  sign of an event slot redoes the step alone with the scalar code (``switching.locate``
  and ``steps.dop853_dense``, the scalar loop's calls on the same numbers).  Whether it
  may have is seen first on all lanes at once (:func:`_clear`): the tether margins of
  the generated lane kernel (sqrt where the scalar one takes hypot, a few ulps apart)
  and the other slots from them; only a lane with a slot within ``CLEAR`` of zero, at
  either end of its step, evaluates the scalar events (model_events), whose signs
  decide, as in the scalar loop.  The scalar events on every lane took a tenth of a
  sweep;
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
from tethersim.engine.dynamics import derivative, model_size
from tethersim.engine.events import (
    EV_L10,
    EV_L20,
    EV_REACH2,
    N_EVENTS,
    N_SWITCH,
    line_limits,
    model_events,
)
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
    dop853_lanes_error,
    dop853_lanes_step,
)
from tethersim.engine.integrators.lanes import (
    LANES,
    model_tether_margins_lanes,
    model_transcendentals,
)
from tethersim.engine.integrators.steps import N_K, dop853_dense, dop853_interpolate, initial_step
from tethersim.experiments.sweep.kernel import _adaptive_status, _measure
from tethersim.experiments.sweep.lanes_dense import enqueue, flush, queue

# lane[k, :] columns, and the lane states of column ST (>= 0: a finished point's loop status)
J, STEPS, IOUT, NFEV, REJ, FRESH, ST, SLOT, DENSE = range(9)
RUNNING, IDLE, EMPTY = -1, -2, -3
# how far from zero, relative to the tethers' lengths, every event slot of a lane's step
# must be for the lane kernel's margins to rule out a sign change (_clear): they differ
# from the scalar ones by a few ulps of the length (~1e-15 of it), and a slot near zero
# subtracts numbers of about that length, so its rounding is of that size too
CLEAR = 1e-11


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


@njit(cache=True, inline="always")
def _clear(ev, GM, k, x, y, g0, g1):
    """Lane k's events at its step's end into g1, from the lane kernel's tether margins
    (GM, row j the margin of tether j) and the balloon's δx, δy there (x, y); True when
    no slot can have changed sign: every slot of g0 (the step's start) and g1 farther
    than CLEAR from zero.  The lane models are planar, on a held circular orbit: no
    re-entry or roll slot (+1, as model_events writes them)."""
    a0, a1 = GM[k], GM[LANES + k]
    g1[0], g1[1], g1[2], g1[3] = a0, a1, 1.0, 1.0
    g1[4] = ev[EV_REACH2] - (x * x + y * y)
    line_limits(ev, g1)
    eps = CLEAR * (ev[EV_L10] + ev[EV_L20] + abs(a0) + abs(a1))
    for s in range(N_EVENTS):
        a, b = g0[s], g1[s]
        if not (abs(a) > eps and abs(b) > eps and (a > 0.0) == (b > 0.0)):
            return False  # also for a NaN
    return True


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
    # the state size as the scalar DOP853 loop has it (a compile-time constant), so the
    # dense output below is the loop's own compiled interpolation, not a second copy
    ns = model_size(model, y)
    j = lane[k, J]
    for i in range(ns):
        y[i] = Y[i * LANES + k]
        f[i] = Ks[i * LANES + k]
    for i in range(pw.shape[0]):
        pw[i] = P[j, i]
    t = TL[k]
    # switches watched, as a run-time value: the scalar DOP853 loop's compiled location
    h_try, hit = switching.locate(1, model, air, t, y, f, H[k], P[j], pw, EV[j], work, yn,
                                  g0[k], g1[k], g, np.bool_(True))
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
def _lanes853_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, Y, PL, Ks, YS, Y_new, HR, S, Fd, H, TL, HL, HN,
                   TE, err, acc, lane, g0, g1, out_y, y, f, yn, pw, work, Fs, g, buf, pm,
                   QY, QYn, QH, QP, QK, QHR, QT, QI, GM):
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
    # the dense output's queue (sweep/lanes_dense.py), each array passed by itself: in a
    # tuple, the borrowed arrays lost the writes of the compiled call they were passed to
    QY, QYn, QH, QP, QK, QHR, QT, QI = (borrow(QY), borrow(QYn), borrow(QH), borrow(QP),
                                        borrow(QK), borrow(QHR), borrow(QT), borrow(QI))
    GM = borrow(GM)
    ix, iy = cols[0], cols[1]
    ns = Y0.shape[1]
    npar = P.shape[1]
    m = ns * LANES
    K = H.shape[0]
    rows = T.shape[1]
    n_points = P.shape[0]
    # counters as run-time values from the start: a literal 0 would compile _load and
    # flush once more for it
    nxt = np.int64(0)
    active = K
    queued = np.int64(0)  # steps waiting for their interpolant (lanes_dense.enqueue)
    on = np.bool_(True)  # switches watched (the scalar loop's run-time flag)
    while True:
        # each lane's step begins (a finished lane is recorded and takes the next point)
        for k in range(K):
            while lane[k, ST] != IDLE:
                if lane[k, ST] == RUNNING and _ready(k, max_steps, TL, HL, TE, H, lane):
                    break
                if lane[k, ST] != EMPTY:
                    queued = flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS,
                                   Fd, S, queued)  # its last rows
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
        model_tether_margins_lanes(model, K, Y_new, PL, GM, S)
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
            fired = False
            if not _clear(EV[j], GM, k, Y_new[ix * LANES + k], Y_new[iy * LANES + k], g0[k],
                          g1[k]):
                # the scalar loop's events at the step's start and end decide
                for i in range(ns):
                    y[i] = Y[i * LANES + k]
                    yn[i] = Y_new[i * LANES + k]
                model_events(model, y, P[j], EV[j], g0[k], True)
                model_events(model, yn, P[j], EV[j], g1[k], True)
                fired = switching.fired(g0[k], g1[k], on)
            if fired:
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
                    queued = flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS,
                                   Fd, S, queued)
                queued, i_next = enqueue(k, lane[k, J], lane[k, IOUT], TL[k], H[k], npar, T,
                                         Y, Y_new, PL, Ks, QY, QYn, QH, QP, QK, QHR, QT, QI,
                                         queued)
                lane[k, IOUT] = i_next
                lane[k, NFEV] += 3
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
    QY, QYn, QH, QP, QK, QHR, QT, QI = queue(m, npar)  # steps awaiting their interpolant
    _lanes853_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, Y, PL, Ks, YS, Y_new, HR, S, Fd, H, TL, HL, HN,
                   TE, err, acc, lane, g0, g1, out_y, y, f, yn, pw, work, Fs, g, buf, pm,
                   QY, QYn, QH, QP, QK, QHR, QT, QI, np.zeros(2 * LANES))
