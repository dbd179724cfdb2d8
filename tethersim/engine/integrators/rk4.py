"""Classical fixed-step RK4 (thesis Eqs 4.1-4.5): pure step + compiled loop.

The whole time loop runs in numba.  With ``locate=True`` a taut/slack switch
inside a step is found by Illinois root finding on the tether margin of the
step's end point (integrators.switching), the step is split there, and the
rest of the step is taken on the other side of the switch: the right-hand
side is smooth within every sub-step, which restores fourth order.  The
stopping limits (engine/events.py) are evaluated at the end of every step,
with or without ``locate``: a step that crosses one is redone, landing just
past the crossing, and the run stops there.

``rk4_run`` is a thin wrapper: it makes the model index a compile-time literal
(one specialised loop per model, cached on disk), allocates the scratch
arrays and keeps them alive while ``_rk4_loop`` works on borrowed views of
every array (integrators/borrow.py), so no reference count is touched per step.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.engine.dynamics import model_size
from tethersim.engine.events import N_EVENTS, N_SWITCH, is_switch, model_events, model_n_events
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.steps import copy_into, rk4_step

ORDER = 4
MAX_SPLITS = 16  # switches located in one step before it is finished unsplit (chattering)
STATUS_OK, STATUS_NONFINITE, STATUS_EVENT = 0, 1, 2


@njit(cache=True)
def rk4_advance(model, air, t, y, h, p, pw, ev, work, y_new, g0, g1, g, switches):
    """Advance y by h (in place), split at events; stop at a stopping limit.

    Out of line: runs with switch location, or once when a step crossed a
    stopping limit.  g0 holds the events at y on entry and at the new y on
    return.  Returns (switches located inside the step, the slot of the
    stopping limit reached or -1, the time reached).
    """
    splits = 0
    remaining = h
    watch = switches  # the switch slots are still evaluated after MAX_SPLITS, not watched
    while remaining > 0.0:
        rk4_step(model, air, t, y, remaining, p, pw, work, y_new)
        model_events(model, y_new, p, ev, g1, switches)
        if not switching.fired(g0, g1, watch):
            copy_into(y, y_new)
            copy_into(g0, g1)
            t += remaining
            break
        tau, j = switching.locate(0, model, air, t, y, y, remaining, p, pw, ev, work, y_new,
                                  g0, g1, g, watch)
        # y_new now holds the state just past the event, at t + tau
        copy_into(y, y_new)
        copy_into(g0, g1)
        t += tau
        remaining -= tau
        if not is_switch(j):
            return splits, j, t
        splits += 1
        if splits > MAX_SPLITS:
            watch = False  # finish the step unsplit, still watching the limits
    return splits, -1, t


@njit(cache=True, nogil=True)
def _rk4_loop(model, air, k0, y, h, n_steps, stride, p, pw, ev, locate, out_t, out_y, row0,
              work, y_new, g):
    # every array is borrowed here, once: nothing below counts references
    y, p, pw, out_t, out_y = borrow(y), borrow(p), borrow(pw), borrow(out_t), borrow(out_y)
    air, ev = borrow(air), borrow(ev)
    work, y_new, g = borrow(work), borrow(y_new), borrow(g)
    g0, g1 = g[0], g[1]
    n = model_size(model, y)  # a compile-time constant: the loops below unroll
    row = row0
    switches = 0
    model_events(model, y, p, ev, g0, locate)
    for j in range(N_SWITCH, N_EVENTS):
        if g0[j] <= 0.0:  # the start is outside: stop before any step
            return 0, 0, STATUS_EVENT, j, k0 * h
    for k in range(1, n_steps + 1):
        # step k0 + k - 1 starts at (k0 + k - 1) h: the same time whether a run is one
        # call or resumed in chunks (t0 + (k - 1) h would round differently per chunk)
        t = (k0 + k - 1) * h
        hit, t_hit = -1, t
        # ``locate`` itself (True here, False below) rather than a constant: a literal
        # compiles rk4_advance, and the location under it, once more for each value
        if locate:
            sw, hit, t_hit = rk4_advance(model, air, t, y, h, p, pw, ev, work, y_new, g0, g1,
                                         g[2], locate)
            switches += sw
        else:
            rk4_step(model, air, t, y, h, p, pw, work, y_new)
            model_events(model, y_new, p, ev, g1, False)
            if switching.fired(g0, g1, locate):  # a stopping limit: redo the step, located
                _, hit, t_hit = rk4_advance(model, air, t, y, h, p, pw, ev, work, y_new, g0,
                                            g1, g[2], locate)
            else:
                for i in range(n):
                    y[i] = y_new[i]
                for i in range(g0.shape[0]):
                    g0[i] = g1[i]
        if hit >= 0:  # the located state is the last row, at the event's time
            if row < out_t.shape[0]:
                out_t[row] = t_hit
                for i in range(n):
                    out_y[row, i] = y[i]
                row += 1
            return row - row0, switches, STATUS_EVENT, hit, t_hit
        if k % stride == 0:
            out_t[row] = (k0 + k) * h
            for i in range(n):
                out_y[row, i] = y[i]
            row += 1
        for i in range(n):
            if not math.isfinite(y[i]):
                return row - row0, switches, STATUS_NONFINITE, -1, t + h
    return row - row0, switches, STATUS_OK, -1, (k0 + n_steps) * h


# nogil: sweeps run many trajectories on threads (tethersim.experiments.sweep)
@njit(cache=True, nogil=True)
def rk4_run(model, air, k0, y, h, n_steps, stride, p, pw, ev, locate, out_t, out_y, row0):
    """n_steps RK4 steps of size h from step k0 (time k0 h) and state y, advanced in place.

    Parameters
    ----------
    model : int
        Model index (tethersim.model.registry order); each value compiles
        (once, cached on disk) its own loop.
    air : ndarray
        The air vector (tethersim.model.air.vector; dynamics.derivative).
    k0 : int
        Steps taken before this call: the first step starts at t = k0 h, so a run
        resumed in chunks has the same times, to the last bit, as one call.
    y, h : ndarray, float
        State (advanced in place), step.
    n_steps, stride : int
        Steps to take; every stride-th state is written out.
    p, pw : ndarray
        Parameter vector and a scratch copy of it.
    ev : ndarray
        The run's event limits (engine/events.py, event_parameters).
    locate : bool
        Split steps at taut/slack switches (integrators.switching).  The
        stopping limits are located whatever this is.
    out_t, out_y : ndarray
        Output times and states, written from row row0 on.
    row0 : int
        First output row.

    Returns
    -------
    tuple
        (rows written, switches located, status, event slot, time reached) with
        status STATUS_OK, STATUS_NONFINITE (the run stopped there) or
        STATUS_EVENT: a stopping limit (engine/events.py slot ``event slot``) was
        crossed; the run stopped just past it, at the located time, and that
        state is y and the last row written (when the buffer has room).  The
        event slot is -1 for the other statuses.
    """
    literally(model)
    n = y.shape[0]
    work = np.empty((5, n))
    y_new = np.empty(n)
    g = np.empty((3, model_n_events(model, y)))  # events at both ends of a step, and a trial
    return _rk4_loop(model, air, k0, y, h, n_steps, stride, p, pw, ev, locate, out_t, out_y,
                     row0, work, y_new, g)
