"""The pitch metrics in compiled code: the one implementation (definitions: docs/metrics.md).

:func:`~tethersim.analysis.metrics.pitch_metrics` and
:func:`~tethersim.analysis.outcome.outcome` call these kernels from Python, and
a sweep's compiled block (tethersim.experiments.sweep.kernel) calls them
without leaving compiled code: one function, so a sweep point is the same
record whichever path computed it, whatever numpy is installed.

Means are compensated (Neumaier) sums divided by the count: the rounding error
of a sum stays at a few ulps of the result whatever the number of samples (a
plain loop over a million samples loses ~1e-10 relative), in a fixed order, so
the result is the same on every call.

Constants that metrics.py owns (the settling band, the steady-state fraction)
are arguments, never baked in: the cache key of compiled code does not cover
metrics.py (tethersim/_jit.py).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.integrators.borrow import borrow

N_PITCH = 5  # mean, steady-state, settling, tumbled (0/1), upside down (0/1)


@njit(cache=True)
def compensated_sum(a, n):
    """Σ a[:n] by Neumaier's compensated summation (error a few ulps of the sum)."""
    s = 0.0
    c = 0.0
    for i in range(n):
        x = a[i]
        u = s + x
        if abs(s) >= abs(x):
            c += (s - u) + x
        else:
            c += (x - u) + s
        s = u
    if not math.isfinite(s):
        return s  # an inf among the samples (or an overflow): the plain sum's answer
    return s + c


@njit(cache=True)
def wrap_angle(x):
    """metrics.wrap of one angle: to (−π, π] (numpy's remainder: fmod, shifted by the
    divisor when the signs differ; −π mapped to π), the same bits as metrics.wrap."""
    period = 2 * math.pi
    mod = np.fmod(-x + math.pi, period)
    if mod != 0.0:
        if (period < 0.0) != (mod < 0.0):
            mod += period
    else:
        mod = math.copysign(0.0, period)
    w = -mod + math.pi
    if w <= -math.pi:
        w = w + 2 * math.pi
    return w


@njit(cache=True)
def window_start(t, n, ss_fraction):
    """The threshold of metrics.steady_state_window over t[:n]: samples t >= it."""
    return t[n - 1] - ss_fraction * (t[n - 1] - t[0])


@njit(cache=True)
def window_mean(t, Y, n, col, threshold, buf):
    """Mean of Y[i, col] over the samples i < n with t[i] >= threshold; buf: scratch (>= n)."""
    m = np.int64(0)  # not a literal 0: that would compile compensated_sum once more
    for i in range(n):
        if t[i] >= threshold:
            buf[m] = Y[i, col]
            m += 1
    return compensated_sum(buf, m) / m


@njit(cache=True)
def pitch_metrics_into(t, Y, n, col, tol, ss_fraction, buf, out):
    """The pitch metrics of θ = Y[:n, col] at times t[:n] (n >= 2) into out[:5].

    out = (mean pitch, steady-state pitch, settling time, tumbled, upside down),
    the booleans as 0.0 / 1.0.  buf: scratch of length >= n.  Returns the
    steady-state window's threshold (for the trail, outcome.py).
    """
    threshold = window_start(t, n, ss_fraction)
    for i in range(n):
        buf[i] = Y[i, col]
    mean = compensated_sum(buf, n) / n
    theta_ss = window_mean(t, Y, n, col, threshold, buf)
    last_out = -1
    out_in_tail = False
    tumbled = False
    for i in range(n):
        th = Y[i, col]
        if abs(th - theta_ss) > tol:
            last_out = i
            if t[i] >= threshold:
                out_in_tail = True
        if abs(th) >= math.pi:
            tumbled = True
    if last_out < 0:
        settling = t[0]
    elif out_in_tail:
        settling = math.nan  # the whole steady-state window must stay in the band
    else:
        settling = t[last_out + 1]
    wrapped = wrap_angle(theta_ss)
    out[0] = mean
    out[1] = wrapped
    out[2] = settling
    out[3] = 1.0 if tumbled else 0.0
    out[4] = 1.0 if abs(wrapped) > 3 * math.pi / 4 else 0.0
    return threshold


# From Python, the kernels above run on borrowed views of the caller's arrays: the types
# the sweeps' compiled blocks pass them (experiments/sweep/kernel.py _measure), so one
# compiled copy of each serves both (a plain array would compile a second).
@njit(cache=True)
def pitch_metrics_of(t, Y, n, col, tol, ss_fraction, buf, out):
    """:func:`pitch_metrics_into` called from Python (C-contiguous float arrays)."""
    return pitch_metrics_into(borrow(t), borrow(Y), n, col, tol, ss_fraction, borrow(buf),
                              borrow(out))


@njit(cache=True)
def window_mean_of(t, Y, n, col, threshold, buf):
    """:func:`window_mean` called from Python (C-contiguous float arrays)."""
    return window_mean(borrow(t), borrow(Y), n, col, threshold, borrow(buf))
