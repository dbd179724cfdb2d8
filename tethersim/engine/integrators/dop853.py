"""Adaptive, error-controlled DOP853 driver (whole loop compiled).

Step-size control as scipy.integrate.DOP853 (Hairer's rules).  Taut/slack
switches are handled by event location: an accepted step whose end point has
a different tether tautness is shortened to land just past the switch
(integrators.switching), so no step straddles a discontinuity of the
right-hand side.  The stopping limits (engine/events.py) are located the
same way, after every accepted step whether or not switches are: the step is
shortened to land just past the crossing and the run stops there.  Output is
the 7th-order dense interpolant on a caller's time grid.

``dop853_run`` is a thin wrapper: it makes the model index a compile-time
literal (one specialised loop per model, cached on disk), allocates the
scratch arrays and keeps them alive while ``_dop853_loop`` works on borrowed
views of every array (integrators/borrow.py): no reference count per step.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.engine.dynamics import derivative, model_size
from tethersim.engine.events import N_EVENTS, N_SWITCH, is_switch, model_events, model_n_events
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.steps import (
    N_K,
    dop853_dense,
    dop853_error_norm,
    dop853_interpolate,
    dop853_step,
    initial_step,
)

ORDER = 8
ERROR_ESTIMATOR_ORDER = 7
SAFETY = 0.9  # fraction of the optimal step taken (scipy, Hairer)
MIN_FACTOR = 0.2  # largest decrease of the step in one rejection
MAX_FACTOR = 10.0  # largest increase of the step after an acceptance
ERROR_EXPONENT = -1.0 / (ERROR_ESTIMATOR_ORDER + 1)

STATUS_OK, STATUS_NONFINITE, STATUS_STEP_TOO_SMALL, STATUS_MAX_STEPS, STATUS_EVENT = 0, 1, 2, 3, 4


@njit(cache=True, nogil=True)
def _dop853_loop(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y,
                 i_out, max_steps, counters, t_pause, work, y_new, f, F, g):
    # every array is borrowed here, once: nothing below counts references
    y, p, pw, out_t, out_y = borrow(y), borrow(p), borrow(pw), borrow(out_t), borrow(out_y)
    air, ev = borrow(air), borrow(ev)
    counters, work, y_new, f, F, g = (borrow(counters), borrow(work), borrow(y_new), borrow(f),
                                      borrow(F), borrow(g))
    n = model_size(model, y)  # a compile-time constant: the loops below unroll
    K = work[:N_K]
    ys = work[N_K]
    g0, g1 = g[0], g[1]
    t = t0
    model_events(model, y, p, ev, g0, locate)
    for j in range(N_SWITCH, N_EVENTS):
        if g0[j] <= 0.0:  # the start is outside: stop before any step
            return t, h, i_out, STATUS_EVENT, j
    derivative(model, air, t, y, p, pw, f)
    counters[0] += 1
    for i in range(n):
        if not math.isfinite(f[i]):
            return t, h, i_out, STATUS_NONFINITE, -1
    if h <= 0.0:
        # F's rows are free until the first dense output: scratch for the trial step
        h = initial_step(model, air, t, y, f, p, pw, rtol, atol, t_end, F[0], F[1], ORDER)
        counters[0] += 1
    if not math.isfinite(h):
        return t, h, i_out, STATUS_NONFINITE, -1
    steps = 0
    while t < t_end and t < t_pause:
        if steps >= max_steps:
            return t, h, i_out, STATUS_MAX_STEPS, -1
        steps += 1
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        rejected = False
        while True:
            if not (h >= min_step):  # written so that a NaN step also stops
                return t, h, i_out, STATUS_STEP_TOO_SMALL, -1
            h_try = min(h, t_end - t)
            dop853_step(model, air, t, y, f, h_try, p, pw, K, ys, y_new)
            counters[0] += 12
            err = dop853_error_norm(n, K, h_try, y, y_new, rtol, atol)
            if not math.isfinite(err):
                err = 1e10  # a NaN/inf stage: reject and shrink the step (MIN_FACTOR)
            if err < 1.0:
                factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * err ** ERROR_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h_next = h_try * factor
                break
            h = h_try * max(MIN_FACTOR, SAFETY * err ** ERROR_EXPONENT)
            rejected = True
            counters[2] += 1
        hit = -1
        model_events(model, y_new, p, ev, g1, locate)
        if switching.fired(g0, g1, locate):
            h_try, hit = switching.locate(1, model, air, t, y, f, h_try, p, pw, ev, work, y_new,
                                          g0, g1, g[2], locate)
            if is_switch(hit):
                counters[3] += 1
                hit = -1
        counters[1] += 1
        t_new = t + h_try
        # the step that ends on a stopping limit writes the outputs before it only: the
        # caller writes the event's state
        t_last = t_new if hit < 0 else np.nextafter(t_new, -np.inf)
        if i_out < out_t.shape[0] and out_t[i_out] <= t_last:
            # the 3 extra stages of the interpolant only when an output falls in the step
            dop853_dense(model, air, t, y, y_new, h_try, p, pw, K, ys, F)
            counters[0] += 3
        while i_out < out_t.shape[0] and out_t[i_out] <= t_last:
            dop853_interpolate(n, F, y, (out_t[i_out] - t) / h_try, out_y[i_out])
            i_out += 1
        for i in range(n):
            y[i] = y_new[i]
            f[i] = K[12, i]
        for i in range(g0.shape[0]):
            g0[i] = g1[i]
        t = t_new
        h = h_next
        if hit >= 0:
            counters[4] += steps
            return t, h, i_out, STATUS_EVENT, hit
        for i in range(n):
            if not math.isfinite(y[i]):
                return t, h, i_out, STATUS_NONFINITE, -1
    counters[4] += steps
    return t, h, i_out, STATUS_OK, -1


# nogil: sweeps run many trajectories on threads (tethersim.experiments.sweep)
@njit(cache=True, nogil=True)
def dop853_run(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y, i_out,
               max_steps, counters, t_pause=math.inf):
    """Integrate y (in place) from t0 to t_end with DOP853.

    Parameters
    ----------
    model : int
        Model index (tethersim.model.registry order); each value compiles
        (once, cached on disk) its own loop.
    air : ndarray
        The air vector (tethersim.model.air.vector; dynamics.derivative).
    t0, t_end : float
        Start and end time [s].
    y : ndarray
        State, advanced in place.
    h : float
        First step to try (<= 0: choose one).
    p, pw : ndarray
        Parameter vector and a scratch copy of it.
    ev : ndarray
        The run's event limits (engine/events.py, event_parameters).
    rtol, atol : float
        Tolerances.
    locate : bool
        Shorten a step that changes a tether's tautness to land on the switch.
        The stopping limits are located whatever this is.
    out_t, out_y : ndarray
        Output grid; the dense output at each out_t[i] in (t0, t_end] goes to
        out_y[i], starting at index i_out.
    i_out, max_steps : int
        First output index; most steps in this call.
    counters : ndarray
        int64[5], accumulates nfev, accepted, rejected, switches, steps.
    t_pause : float
        Return after the first step that reaches it (the step is not
        shortened to land on it), so a run split into calls at any pause
        times takes exactly the steps of one call.

    Returns
    -------
    tuple
        (t reached, next step size, next output index, status, event slot).
        Status STATUS_EVENT: a stopping limit (engine/events.py slot ``event
        slot``, else -1) was crossed; the run stopped just past it, at t, y holds
        that state, and the outputs before t are written (none at or after it).
    """
    literally(model)
    n = y.shape[0]
    work = np.empty((N_K + 1, n))  # stages, then a stage state
    y_new = np.empty(n)
    f = np.empty(n)
    F = np.empty((7, n))
    g = np.empty((3, model_n_events(model, y)))  # events at both ends of a step, and a trial
    return _dop853_loop(model, air, t0, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t,
                        out_y, i_out, max_steps, counters, t_pause, work, y_new, f, F, g)
