"""A block of sweep points in one compiled, nogil call: integrate, check, measure.

``sweep_block`` runs each point of a block through the engine's own compiled
loop (``dop853_run`` or ``rk4_run``, called exactly as ``simulate`` calls them
with ``progress=False``: same arguments and event limits, same single call, hence
the same trajectory bit for bit, and the same stop at a limit of the model's
domain, located by the loop itself: engine/events.py), then, still in compiled
code and without the GIL:

* outcome.py's rule: a point counts when its run ended ok (so stayed in the
  domain), has at least two samples and every one of them is finite;
* for a counting point, the pitch metrics and the trail (analysis.metrics_kernel,
  the one implementation outcome() uses) and the largest family force on each
  coordinate (evaluate's own compiled loop _family_force_peaks).

Python then builds the block's inputs and writes the records
(tethersim.experiments.sweep.batch).  What a point needs beyond this (per-body
air, a free orbit) runs the per-point path instead.

Layout of the outputs, per point j:

``rec_f[j]``  mean pitch, steady-state pitch, settling time, trail δx, trail δy,
              largest family force on δx, δy, θ (NaN where not computed), end time
              (every point: its last sample), drag make-up of a held circular orbit
              (analysis.makeup_kernel, the one implementation outcome() uses)
``rec_i[j]``  status code (the index of the engine's status in
              tethersim.engine.result.STATUSES: ok, diverged, failed, or the stopping
              event's status, left-domain for a circular orbit),
              counts (0/1), tumbled, upside down, right-hand-side evaluations
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.analysis.makeup_kernel import drag_makeup_kernel
from tethersim.analysis.metrics_kernel import N_PITCH, pitch_metrics_into, window_mean
from tethersim.engine.evaluate import _family_force_peaks
from tethersim.engine.events import EVENTS
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.dop853 import STATUS_EVENT as DOP853_EVENT
from tethersim.engine.integrators.dop853 import dop853_run
from tethersim.engine.integrators.radau import N_COUNTERS as RADAU_COUNTERS
from tethersim.engine.integrators.radau import carry_size, radau_run
from tethersim.engine.integrators.rk4 import STATUS_EVENT as RK4_EVENT
from tethersim.engine.integrators.rk4 import rk4_run
from tethersim.engine.result import STATUSES

F_FIELDS = ("mean_pitch", "steady_state_pitch", "settling_time", "trail_delta_x",
            "trail_delta_y", "max_force_delta_x", "max_force_delta_y", "max_force_theta",
            "end_time", "drag_makeup")
I_FIELDS = ("status", "counts", "tumbled", "upside_down", "nfev")
# the state columns the block measures (cols)
COL_FIELDS = ("delta_x", "delta_y", "theta")
# the engine's status names, coded by their index in STATUSES (the store's flag_values)
STATUS_OK, STATUS_NONFINITE, STATUS_FAILED = (
    STATUSES.index(s) for s in ("ok", "diverged", "failed"))
# the status code of a run stopped by each event slot (engine/events.py EVENTS; -1: a
# switch, which stops nothing): a constant array of the compiled block
EVENT_STATUS = np.array([STATUSES.index(e.status) if e.terminal else -1 for e in EVENTS],
                        dtype=np.int64)


@njit(cache=True, nogil=True)
def _all_finite(Y, n):
    """Whether the first n rows of Y are all finite (outcome.py's rule)."""
    for i in range(n):
        for k in range(Y.shape[1]):
            if not math.isfinite(Y[i, k]):
                return False
    return True


@njit(cache=True, nogil=True)
def _measure(j, model, air, p, t, out_y, n, status, nfev, end_time, cols, tol, ss_fraction,
             rec_f, rec_i, buf, pm):
    """Point j's record from its run (n rows of out_y at times t): outcome.py's rule, the
    pitch metrics, the trail and the force peaks of a run that counts."""
    ix, iy, ith = cols[0], cols[1], cols[2]
    counts = status == STATUS_OK and n >= 2 and _all_finite(out_y, n)
    for k in range(rec_f.shape[1]):
        rec_f[j, k] = math.nan
    rec_f[j, 8] = end_time
    rec_i[j, 0] = status
    rec_i[j, 1] = 1 if counts else 0
    rec_i[j, 2] = 0
    rec_i[j, 3] = 0
    rec_i[j, 4] = nfev
    if not counts:
        return
    threshold = pitch_metrics_into(t, out_y, n, ith, tol, ss_fraction, buf, pm)
    rec_f[j, 0], rec_f[j, 1], rec_f[j, 2] = pm[0], pm[1], pm[2]
    rec_i[j, 2] = 1 if pm[3] != 0.0 else 0
    rec_i[j, 3] = 1 if pm[4] != 0.0 else 0
    rec_f[j, 3] = window_mean(t, out_y, n, ix, threshold, buf)
    rec_f[j, 4] = window_mean(t, out_y, n, iy, threshold, buf)
    peaks = _family_force_peaks(model, air, t, out_y[:n], p)  # uniform air: p's densities
    rec_f[j, 5], rec_f[j, 6], rec_f[j, 7] = peaks[ix], peaks[iy], peaks[ith]
    rec_f[j, 9] = drag_makeup_kernel(model, air, t, out_y, n, p)  # NaN on a free orbit


@njit(cache=True, nogil=True)
def _adaptive_status(st, slot):
    """The record's status code of an adaptive (DOP853 or Radau) run's loop status."""
    return (STATUS_OK if st == 0 else STATUS_NONFINITE if st == 1
            else EVENT_STATUS[slot] if st == DOP853_EVENT else STATUS_FAILED)


@njit(cache=True, nogil=True)
def _block_loop(model, air, faithful, T, Y0, P, span, n_steps, rtol, atol, max_steps, EV,
                cols, tol, ss_fraction, rec_f, rec_i, out_t, out_y, pw, counters, buf, pm):
    # The run loops are called with plain arrays, the types simulate() calls them with,
    # so that a sweep loads the loops simulate() compiled rather than compiling a second
    # copy for borrowed arrays (each loop borrows its arrays itself, once per call: no
    # reference count per step).  The rest is borrowed here, once (integrators/borrow.py).
    T_, P_, span, cols = borrow(T), borrow(P), borrow(span), borrow(cols)
    rec_f, rec_i, buf, pm = borrow(rec_f), borrow(rec_i), borrow(buf), borrow(pm)
    air_, out_t_, out_y_ = borrow(air), borrow(out_t), borrow(out_y)
    ns = Y0.shape[1]
    # the loops' flags and first rows as run-time values: a constant would be typed as a
    # literal and compile a second copy of each loop (same arithmetic, twice the compile)
    locate = not faithful  # DOP853 locates the switches, the thesis's RK4 does not
    zero, one = np.int64(0), np.int64(1)
    for j in range(P_.shape[0]):
        y, p, ev = Y0[j], P[j], EV[j]
        for i in range(p.shape[0]):
            pw[i] = p[i]
        for i in range(ns):
            out_y_[0, i] = y[i]
        if faithful:  # simulate._run_rk4, progress=False: one call for every step
            out_t_[0] = 0.0
            rows, _, st, slot, _ = rk4_run(model, air, zero, y, span[j], n_steps, one, p, pw,
                                           ev, locate, out_t, out_y, one)
            n = 1 + rows
            # a run stopped at a limit took the steps up to it (simulate._run_rk4)
            nfev = 4 * (rows if st == RK4_EVENT else n_steps)
            status = (STATUS_OK if st == 0 else EVENT_STATUS[slot] if st == RK4_EVENT
                      else STATUS_NONFINITE)
            t = out_t_
            end_time = t[n - 1]  # a located stop is the last row (rk4_run)
        else:  # simulate._run_adaptive, progress=False, circular orbit: one call
            t = T_[j]
            for i in range(counters.shape[0]):
                counters[i] = 0
            t_stop, _, n, st, slot = dop853_run(model, air, 0.0, span[j], y, 0.0, p, pw, ev,
                                                rtol, atol, locate, T[j], out_y, one,
                                                max_steps, counters, math.inf)
            nfev = counters[0]
            status = _adaptive_status(st, slot)
            # a located stop is not a row of the grid (simulate appends it)
            end_time = t_stop if st == DOP853_EVENT else t[n - 1]
        _measure(j, model, air_, P_[j], t, out_y_, n, status, nfev, end_time, cols, tol,
                 ss_fraction, rec_f, rec_i, buf, pm)


@njit(cache=True, nogil=True)
def _implicit_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, out_y, pw, counters, carry, buf, pm):
    # the run loop takes plain arrays, as simulate() calls it (_block_loop)
    T_, P_, span, cols = borrow(T), borrow(P), borrow(span), borrow(cols)
    rec_f, rec_i, buf, pm = borrow(rec_f), borrow(rec_i), borrow(buf), borrow(pm)
    air_, out_y_ = borrow(air), borrow(out_y)
    ns = Y0.shape[1]
    one = np.int64(1)
    # True as a run-time bool, as simulate() passes it: a literal compiles a second loop
    locate = np.bool_(True)
    for j in range(P_.shape[0]):
        y, p, ev = Y0[j], P[j], EV[j]
        for i in range(p.shape[0]):
            pw[i] = p[i]
        for i in range(ns):
            out_y_[0, i] = y[i]
        for i in range(counters.shape[0]):
            counters[i] = 0
        for i in range(carry.shape[0]):
            carry[i] = 0.0
        # simulate._run_adaptive(scheme="implicit"): the switches located, one call
        t_stop, _, n, st, slot = radau_run(model, air, 0.0, span[j], y, 0.0, p, pw, ev, rtol,
                                           atol, locate, T[j], out_y, one, max_steps,
                                           counters, carry, math.inf)
        t = T_[j]
        end_time = t_stop if st == DOP853_EVENT else t[n - 1]
        _measure(j, model, air_, P_[j], t, out_y_, n, _adaptive_status(st, slot),
                 counters[0], end_time, cols, tol, ss_fraction, rec_f, rec_i, buf, pm)


# nogil: the sweep's threads run blocks side by side
@njit(cache=True, nogil=True)
def sweep_block(model, air, faithful, T, Y0, P, span, n_steps, rtol, atol, max_steps, EV,
                cols, tol, ss_fraction, rec_f, rec_i):
    """Integrate and measure every point of a block (one compiled call, no GIL).

    Parameters
    ----------
    model : int
        Model index (a compile-time literal: one block loop per model); a
        circular-orbit model.
    air : ndarray
        The uniform air vector (tethersim.model.air.vector.uniform_air).
    faithful : bool
        RK4 at a fixed step, switches not located (else DOP853, switches located).
    T : ndarray
        (points, samples): adaptive, each point's output grid (the metrics grid
        of simulate, ending at its t_end); RK4, scratch.
    Y0, P : ndarray
        (points, state) initial states, overwritten; (points, parameters).
    span : ndarray
        Per point: the RK4 step [s], or the adaptive run's end time [s].
    n_steps : int
        RK4 steps (samples = n_steps + 1).
    rtol, atol : float
        Adaptive tolerances.
    max_steps : int
        Adaptive step limit (engine/guards.py step_budget).
    EV : ndarray
        (points, N_EV): each point's event limits (engine/events.py event_parameters).
    cols : ndarray
        int64 state columns of δx, δy, θ.
    tol, ss_fraction : float
        Settling band [rad] and steady-state fraction (metrics.py).
    rec_f, rec_i : ndarray
        Outputs (points, 9) float64 and (points, 5) int64: module docstring.
    """
    literally(model)
    ns = Y0.shape[1]
    rows = T.shape[1]
    out_t = np.empty(rows)
    out_y = np.empty((rows, ns))
    pw = np.empty(P.shape[1])
    counters = np.zeros(5, dtype=np.int64)
    buf = np.empty(rows)
    pm = np.empty(N_PITCH)
    _block_loop(model, air, faithful, T, Y0, P, span, n_steps, rtol, atol, max_steps, EV,
                cols, tol, ss_fraction, rec_f, rec_i, out_t, out_y, pw, counters, buf, pm)


@njit(cache=True, nogil=True)
def sweep_block_implicit(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                         ss_fraction, rec_f, rec_i):
    """:func:`sweep_block` with the implicit scheme (Radau IIA, for stiff tethers).

    Its own compiled entry, so that the blocks of the explicit schemes do not carry
    (and compile) the Radau loop.  Arguments as :func:`sweep_block` without
    ``faithful`` and ``n_steps``; ``T`` is each point's output grid.
    """
    literally(model)
    ns = Y0.shape[1]
    rows = T.shape[1]
    out_y = np.empty((rows, ns))
    pw = np.empty(P.shape[1])
    counters = np.zeros(RADAU_COUNTERS, dtype=np.int64)
    carry = np.zeros(carry_size(ns))
    buf = np.empty(rows)
    pm = np.empty(N_PITCH)
    _implicit_loop(model, air, T, Y0, P, span, rtol, atol, max_steps, EV, cols, tol,
                   ss_fraction, rec_f, rec_i, out_y, pw, counters, carry, buf, pm)
