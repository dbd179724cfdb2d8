"""The faithful (fixed-step RK4) sweep block on SIMD lanes: K points advance together.

``sweep_block_lanes`` computes what ``kernel.sweep_block`` computes for
``faithful=True``, record for record and bit for bit
(tests/experiments/test_sweep_lanes.py), with K points of the block in the K lanes
of structure-of-arrays arrays (engine/integrators/lanes.py): every step is one
:func:`~tethersim.engine.integrators.lanes.rk4_lanes_step` of all lanes, whose rhs
LLVM vectorises across the lanes.  What differs per lane stays per lane:

* each lane is its own point, with its own step H[k], step count and output rows;
* after each step the stopping limits are evaluated per lane (``model_events``, as
  ``rk4._rk4_loop`` does); a lane whose step crosses one redoes that step alone with the
  scalar ``rk4_advance`` (the same location as the scalar loop) and is finished;
* a finished lane (its steps done, a limit, a non-finite state) is measured
  (``kernel._measure``, the same compiled metrics) and takes the block's next point,
  so the lanes stay busy whatever the points' outcomes.

An idle lane (no point left) keeps stepping its last state, unread.  Only the held
circular orbit in uniform air runs here (``batch._compiled`` picks this block then).
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.analysis.metrics_kernel import N_PITCH
from tethersim.engine.events import N_EVENTS, N_SWITCH, model_events
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.lanes import LANES, model_transcendentals, rk4_lanes_step
from tethersim.engine.integrators.rk4 import rk4_advance
from tethersim.experiments.sweep.kernel import (
    EVENT_STATUS,
    STATUS_NONFINITE,
    STATUS_OK,
    _measure,
)

RUNNING, DONE, HIT, NONFINITE, IDLE = 0, 1, 2, 3, 4  # lane states


@njit(cache=True, nogil=True)
def _load(model, k, j, Y0, P, span, EV, Y, PL, H, g0, out_t, out_y, lane):
    """Point j into lane k; returns the lane's state (HIT when it starts outside)."""
    ns = Y0.shape[1]
    for i in range(ns):
        Y[i * LANES + k] = Y0[j, i]
        out_y[k, 0, i] = Y0[j, i]
    for i in range(P.shape[1]):
        PL[i * LANES + k] = P[j, i]
    H[k] = span[j]
    out_t[k, 0] = 0.0
    lane[k, 0] = j  # point
    lane[k, 1] = 1  # next step
    lane[k, 2] = 1  # next row
    lane[k, 3] = -1  # event slot
    # rk4._rk4_loop: the start is outside a stopping limit -> stop before any step
    model_events(model, Y0[j], P[j], EV[j], g0[k], False)
    for s in range(N_SWITCH, N_EVENTS):
        if g0[k, s] <= 0.0:
            lane[k, 3] = s
            return HIT
    return RUNNING


@njit(cache=True, nogil=True)
def _finish(model, air, k, state, n_steps, lane, out_t, out_y, P, cols, tol, ss_fraction,
            rec_f, rec_i, buf, pm):
    """kernel._block_loop's bookkeeping and record of lane k's finished point."""
    j, rows = lane[k, 0], lane[k, 2] - 1
    n = 1 + rows
    nfev = 4 * (rows if state == HIT else n_steps)
    status = (STATUS_OK if state == DONE else EVENT_STATUS[lane[k, 3]] if state == HIT
              else STATUS_NONFINITE)
    t = out_t[k]
    _measure(j, model, air, P[j], t, out_y[k], n, status, nfev, t[n - 1], cols, tol,
             ss_fraction, rec_f, rec_i, buf, pm)


@njit(cache=True, nogil=True)
def _lanes_loop(model, air, Y0, P, span, n_steps, EV, cols, tol, ss_fraction, rec_f, rec_i,
                Y, PL, H, T, stages, ts, Y_new, S, out_t, out_y, lane, g0, g1, g, y, y_new,
                work1, pw, buf, pm):
    k1, k2, k3, k4, ys = (borrow(stages[0]), borrow(stages[1]), borrow(stages[2]),
                          borrow(stages[3]), borrow(stages[4]))
    air, Y0, P, span, EV, cols = (borrow(air), borrow(Y0), borrow(P), borrow(span),
                                  borrow(EV), borrow(cols))
    rec_f, rec_i, Y, PL, H, T = (borrow(rec_f), borrow(rec_i), borrow(Y), borrow(PL),
                                 borrow(H), borrow(T))
    ts, Y_new, S, out_t, out_y = (borrow(ts), borrow(Y_new), borrow(S), borrow(out_t),
                                  borrow(out_y))


    lane, g0, g1, g, y, y_new = (borrow(lane), borrow(g0), borrow(g1), borrow(g), borrow(y),
                                 borrow(y_new))
    work1, pw, buf, pm = borrow(work1), borrow(pw), borrow(buf), borrow(pm)
    ns = Y0.shape[1]
    K = T.shape[0]
    n_points = P.shape[0]
    # run-time values, not literals: a literal argument compiles a second copy of the
    # function it is passed to (the scalar loops pass these as run-time values)
    nxt = np.int64(0)
    off = np.bool_(False)  # the faithful scheme locates no switch
    active = 0
    for k in range(K):  # fill the lanes; a point that starts outside is recorded at once
        state = IDLE
        while nxt < n_points:
            state = _load(model, k, nxt, Y0, P, span, EV, Y, PL, H, g0, out_t, out_y, lane)
            nxt += 1
            if state == RUNNING:
                break
            _finish(model, air, k, state, n_steps, lane, out_t, out_y, P, cols, tol,
                    ss_fraction, rec_f, rec_i, buf, pm)
            state = IDLE
        lane[k, 4] = state
        if state == RUNNING:
            active += 1
    while active > 0:
        for k in range(K):
            # step s of a run starts at (s - 1) h (rk4._rk4_loop with k0 = 0)
            T[k] = (lane[k, 1] - 1) * H[k]
        rk4_lanes_step(model, T, Y, H, PL, k1, k2, k3, k4, ys, ts, Y_new, S)
        for k in range(K):
            if lane[k, 4] != RUNNING:
                continue
            j, step, row = lane[k, 0], lane[k, 1], lane[k, 2]
            for i in range(ns):
                y_new[i] = Y_new[i * LANES + k]
            model_events(model, y_new, P[j], EV[j], g1, False)
            state = RUNNING
            if switching.fired(g0[k], g1, off):  # a stopping limit: redo the step, located
                for i in range(ns):
                    y[i] = Y[i * LANES + k]
                _, hit, t_hit = rk4_advance(model, air, T[k], y, H[k], P[j], pw, EV[j],
                                            work1, y_new, g0[k], g1, g, off)
                for i in range(ns):
                    Y[i * LANES + k] = y[i]
                if hit >= 0:  # the located state is the last row, at the event's time
                    out_t[k, row] = t_hit
                    for i in range(ns):
                        out_y[k, row, i] = y[i]
                    lane[k, 2] = row + 1
                    lane[k, 3] = hit
                    state = HIT
            else:
                for i in range(ns):
                    Y[i * LANES + k] = Y_new[i * LANES + k]
                for i in range(N_EVENTS):
                    g0[k, i] = g1[i]
            if state == RUNNING:
                out_t[k, row] = step * H[k]
                for i in range(ns):
                    out_y[k, row, i] = Y[i * LANES + k]
                lane[k, 2] = row + 1
                for i in range(ns):
                    if not math.isfinite(Y[i * LANES + k]):
                        state = NONFINITE
                        break
                lane[k, 1] = step + 1
                if state == RUNNING and step == n_steps:
                    state = DONE
            if state == RUNNING:
                continue
            _finish(model, air, k, state, n_steps, lane, out_t, out_y, P, cols, tol,
                    ss_fraction, rec_f, rec_i, buf, pm)
            state = IDLE
            while nxt < n_points:
                state = _load(model, k, nxt, Y0, P, span, EV, Y, PL, H, g0, out_t, out_y,
                              lane)
                nxt += 1
                if state == RUNNING:
                    break
                _finish(model, air, k, state, n_steps, lane, out_t, out_y, P, cols, tol,
                        ss_fraction, rec_f, rec_i, buf, pm)
                state = IDLE
            lane[k, 4] = state
            if state != RUNNING:
                active -= 1


# nogil: the sweep's threads run blocks side by side
@njit(cache=True, nogil=True)
def sweep_block_lanes(model, air, Y0, P, span, n_steps, EV, cols, tol, ss_fraction, rec_f,
                      rec_i, K):
    """``kernel.sweep_block(faithful=True)`` on K lanes: the same records, bit for bit.

    Parameters
    ----------
    model : int
        Model index (a compile-time literal), a model with a lane rhs
        (engine/integrators/lanes.py ``has_lanes``), circular orbit.
    air : ndarray
        The uniform air vector.
    Y0, P, span, n_steps, EV, cols, tol, ss_fraction, rec_f, rec_i
        As :func:`tethersim.experiments.sweep.kernel.sweep_block` (span: each point's
        RK4 step [s]).
    K : int
        Lanes, at most LANES (engine/integrators/lanes.py ``lane_count``).
    """
    literally(model)
    ns, npar = Y0.shape[1], P.shape[1]
    rows = n_steps + 1
    Y = np.zeros(ns * LANES)  # an idle lane steps zeros, never uninitialised (denormal) data
    PL = np.zeros(npar * LANES)
    H = np.zeros(K)
    T = np.empty(K)
    # the stages, each its own array (integrators/lanes.py says why)
    stages = (np.zeros(ns * LANES), np.zeros(ns * LANES), np.zeros(ns * LANES),
              np.zeros(ns * LANES), np.zeros(ns * LANES))
    ts = np.empty(K)
    Y_new = np.zeros(ns * LANES)
    S = np.zeros(model_transcendentals(model) * LANES)
    out_t = np.empty((K, rows))
    out_y = np.zeros((K, rows, ns))
    lane = np.zeros((K, 5), dtype=np.int64)
    g0 = np.ones((K, N_EVENTS))
    g1, g = np.empty(N_EVENTS), np.empty(N_EVENTS)
    y, y_new = np.empty(ns), np.empty(ns)
    work1 = np.empty((5, ns))
    pw = np.empty(npar)
    buf = np.empty(rows)
    pm = np.empty(N_PITCH)
    _lanes_loop(model, air, Y0, P, span, n_steps, EV, cols, tol, ss_fraction, rec_f, rec_i,
                Y, PL, H, T, stages, ts, Y_new, S, out_t, out_y, lane, g0, g1, g, y, y_new,
                work1, pw, buf, pm)
