"""Classical fixed-step RK4 (thesis Eqs 4.1-4.5): pure step + compiled loop.

The whole time loop runs in numba.  With ``locate=True`` a taut/slack switch
inside a step is found by Illinois root finding on the tether margin of the
step's end point (integrators.switching), the step is split there, and the
rest of the step is taken on the other side of the switch: the right-hand
side is smooth within every sub-step, which restores fourth order.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import tether_margins
from tethersim.engine.integrators import switching
from tethersim.engine.integrators.steps import rk4_step

ORDER = 4


@njit(cache=True)
def rk4_advance(cfg, t, y, h, p, pw, work, y_new, locate, g0, g1):
    """Advance y by h (in place); split at taut/slack switches if locate.

    Returns the number of switches located inside the step.
    """
    if not locate:
        rk4_step(cfg, t, y, h, p, pw, work, y_new)
        y[:] = y_new
        return 0
    splits = 0
    remaining = h
    while remaining > 0.0:
        rk4_step(cfg, t, y, remaining, p, pw, work, y_new)
        tether_margins(y, p, g0)
        tether_margins(y_new, p, g1)
        if switching.crossed(g0, g1) < 0:
            y[:] = y_new
            break
        tau = switching.locate(0, cfg, t, y, y, remaining, p, pw, work, y_new, g0, g1)
        # y_new now holds the state just past the switch, at t + tau
        y[:] = y_new
        t += tau
        remaining -= tau
        splits += 1
        if splits > 16:  # chattering: finish the step unsplit
            rk4_step(cfg, t, y, remaining, p, pw, work, y_new)
            y[:] = y_new
            break
    return splits


# nogil: sweeps run many trajectories on threads (tethersim.experiments.sweep)
@njit(cache=True, nogil=True)
def rk4_run(cfg, t0, y, h, n_steps, stride, p, pw, locate, out_t, out_y, row0):
    """n_steps RK4 steps of size h from (t0, y), y advanced in place.

    Writes every ``stride``-th state into out_y[row0 + ...] and its time into
    out_t.  Returns (number of rows written, switches located, status), where
    status is 0 (ok) or 1 (non-finite state: the run stopped there).
    """
    n = y.shape[0]
    work = np.empty((5, n))
    y_new = np.empty(n)
    g0 = np.empty(2)
    g1 = np.empty(2)
    row = row0
    switches = 0
    for k in range(1, n_steps + 1):
        t = t0 + (k - 1) * h
        switches += rk4_advance(cfg, t, y, h, p, pw, work, y_new, locate, g0, g1)
        if k % stride == 0:
            out_t[row] = t0 + k * h
            out_y[row, :] = y
            row += 1
        for i in range(n):
            if not math.isfinite(y[i]):
                return row - row0, switches, 1
    return row - row0, switches, 0


