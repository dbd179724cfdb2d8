"""Classical fixed-step RK4 (thesis Eqs 4.1-4.5): pure step + compiled loop.

The whole time loop runs in numba.  With ``locate=True`` a taut/slack switch
inside a step is found by Illinois root finding on the tether margin of the
step's end point (integrators.switching), the step is split there, and the
rest of the step is taken on the other side of the switch: the right-hand
side is smooth within every sub-step, which restores fourth order.

``rk4_run`` is a thin wrapper: it makes the model index a compile-time literal
(one specialised loop per model, cached on disk), allocates the scratch
arrays and keeps them alive while ``_rk4_loop`` works on borrowed views of
every array (integrators/borrow.py), so no reference count is touched per step.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit

from tethersim.engine.dynamics import model_size, model_tether_margins
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.steps import copy_into, rk4_step

ORDER = 4
MAX_SPLITS = 16  # switches located in one step before it is finished unsplit (chattering)


@njit(cache=True)
def rk4_advance(model, air, t, y, h, p, pw, work, y_new, g0, g1, g):
    """Advance y by h (in place), split at taut/slack switches.

    Out of line: only runs with locate=True.  Returns the number of switches
    located inside the step.
    """
    splits = 0
    remaining = h
    while remaining > 0.0:
        rk4_step(model, air, t, y, remaining, p, pw, work, y_new)
        model_tether_margins(model, y, p, g0)
        model_tether_margins(model, y_new, p, g1)
        if switching.crossed(g0, g1) < 0:
            copy_into(y, y_new)
            break
        tau = switching.locate(0, model, air, t, y, y, remaining, p, pw, work, y_new,
                               g0, g1, g)
        # y_new now holds the state just past the switch, at t + tau
        copy_into(y, y_new)
        t += tau
        remaining -= tau
        splits += 1
        if splits > MAX_SPLITS:
            rk4_step(model, air, t, y, remaining, p, pw, work, y_new)
            copy_into(y, y_new)
            break
    return splits


@njit(cache=True, nogil=True)
def _rk4_loop(model, air, k0, y, h, n_steps, stride, p, pw, locate, out_t, out_y, row0,
              work, y_new, g):
    # every array is borrowed here, once: nothing below counts references
    y, p, pw, out_t, out_y = borrow(y), borrow(p), borrow(pw), borrow(out_t), borrow(out_y)
    air = borrow(air)
    work, y_new, g = borrow(work), borrow(y_new), borrow(g)
    n = model_size(model)  # a compile-time constant: the loops below unroll
    row = row0
    switches = 0
    for k in range(1, n_steps + 1):
        # step k0 + k - 1 starts at (k0 + k - 1) h: the same time whether a run is one
        # call or resumed in chunks (t0 + (k - 1) h would round differently per chunk)
        t = (k0 + k - 1) * h
        if locate:
            switches += rk4_advance(model, air, t, y, h, p, pw, work, y_new,
                                    g[0], g[1], g[2])
        else:
            rk4_step(model, air, t, y, h, p, pw, work, y_new)
            for i in range(n):
                y[i] = y_new[i]
        if k % stride == 0:
            out_t[row] = (k0 + k) * h
            for i in range(n):
                out_y[row, i] = y[i]
            row += 1
        for i in range(n):
            if not math.isfinite(y[i]):
                return row - row0, switches, 1
    return row - row0, switches, 0


# nogil: sweeps run many trajectories on threads (tethersim.experiments.sweep)
@njit(cache=True, nogil=True)
def rk4_run(model, air, k0, y, h, n_steps, stride, p, pw, locate, out_t, out_y, row0):
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
    locate : bool
        Split steps at taut/slack switches (integrators.switching).
    out_t, out_y : ndarray
        Output times and states, written from row row0 on.
    row0 : int
        First output row.

    Returns
    -------
    tuple
        (rows written, switches located, status) with status 0 (ok) or 1
        (non-finite state: the run stopped there).
    """
    literally(model)
    n = y.shape[0]
    work = np.empty((5, n))
    y_new = np.empty(n)
    g = np.empty((3, 2))  # tether margins at both ends of a step, and a trial
    return _rk4_loop(model, air, k0, y, h, n_steps, stride, p, pw, locate, out_t, out_y,
                     row0, work, y_new, g)
