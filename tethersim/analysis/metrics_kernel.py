"""The pitch metrics of tethersim.analysis.metrics in compiled code, bit for bit.

A sweep computes the metrics of a block of runs without leaving compiled code
(tethersim.experiments.sweep.kernel); its records must be the numbers that
:func:`~tethersim.analysis.metrics.pitch_metrics` and
:func:`~tethersim.analysis.outcome.outcome` give for the same samples, exactly,
so that a sweep point is the same record whichever path computed it.  Three
things make that hold:

* **means** are numpy's: ``np.mean`` sums float64 by *pairwise summation*
  (blocks of 128 summed with 8 accumulators, halves above that, a plain loop
  below 8) and divides by the count; :func:`pairwise_sum` is that algorithm,
  step for step.  Older numpy releases summed strided or large arrays in
  buffered chunks instead; :func:`sums_match_numpy` checks the installed numpy
  once, and callers use this module only when it says yes;
* **wrap** is ``-remainder(-x + π, 2π) + π`` with numpy's remainder (C fmod,
  shifted by the divisor when the signs differ; fmod is exact, so any correct
  fmod gives the same bits), then −π mapped to π;
* every other step (thresholds, comparisons, the settling index) is the same
  IEEE operation in the same order as metrics.py.

Constants that metrics.py owns (the settling band, the steady-state fraction)
are arguments, never baked in: the cache key of compiled code does not cover
metrics.py (tethersim/_jit.py).
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numba import njit

PW_BLOCK = 128  # numpy's PW_BLOCKSIZE (numpy/_core/src/umath/loops_utils.h.src)
N_PITCH = 5  # mean, steady-state, settling, tumbled (0/1), upside down (0/1)


@njit(cache=True)
def _block_sum(a, lo, n):
    # numpy's pairwise_sum below its block size: a loop under 8, else 8 accumulators
    if n < 8:
        s = 0.0
        for i in range(lo, lo + n):
            s += a[i]
        return s
    r0, r1, r2, r3 = a[lo], a[lo + 1], a[lo + 2], a[lo + 3]
    r4, r5, r6, r7 = a[lo + 4], a[lo + 5], a[lo + 6], a[lo + 7]
    i = 8
    whole = n - n % 8
    while i < whole:
        j = lo + i
        r0 += a[j]
        r1 += a[j + 1]
        r2 += a[j + 2]
        r3 += a[j + 3]
        r4 += a[j + 4]
        r5 += a[j + 5]
        r6 += a[j + 6]
        r7 += a[j + 7]
        i += 8
    s = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    while i < n:
        s += a[lo + i]
        i += 1
    return s


@njit(cache=True)
def pairwise_sum(a, lo, n):
    """Sum of a[lo:lo + n] in numpy's pairwise order (float64, contiguous ``a``).

    numpy recurses: above the block size it sums the halves (the first rounded
    down to a multiple of 8) and adds them.  The same tree, walked with an
    explicit stack (a recursive function loaded from numba's disk cache crashes).
    """
    if n <= PW_BLOCK:
        return _block_sum(a, lo, n)
    depth = 2 * 64  # a tree of depth < 64 for any n < 2**63
    node_lo = np.empty(depth, dtype=np.int64)
    node_n = np.empty(depth, dtype=np.int64)
    joined = np.zeros(depth, dtype=np.bool_)
    values = np.empty(depth)
    top, nv = 0, 0
    node_lo[0], node_n[0], joined[0] = lo, n, False
    while top >= 0:
        lo_k, n_k, join = node_lo[top], node_n[top], joined[top]
        top -= 1
        if join:  # both halves are on the value stack: left below right
            values[nv - 2] = values[nv - 2] + values[nv - 1]
            nv -= 1
        elif n_k <= PW_BLOCK:
            values[nv] = _block_sum(a, lo_k, n_k)
            nv += 1
        else:
            half = n_k // 2
            half -= half % 8
            top += 1
            node_lo[top], node_n[top], joined[top] = lo_k, n_k, True
            top += 1  # the right half, taken after the left one
            node_lo[top], node_n[top], joined[top] = lo_k + half, n_k - half, False
            top += 1
            node_lo[top], node_n[top], joined[top] = lo_k, half, False
    return values[0]


@njit(cache=True)
def wrap_angle(x):
    """metrics.wrap of one angle: to (−π, π], the same bits as numpy's."""
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
    """np.mean(Y[:n][t[:n] >= threshold, col]); buf: scratch of length >= n."""
    m = 0
    for i in range(n):
        if t[i] >= threshold:
            buf[m] = Y[i, col]
            m += 1
    return pairwise_sum(buf, 0, m) / m


@njit(cache=True)
def pitch_metrics_into(t, Y, n, col, tol, ss_fraction, buf, out):
    """metrics.pitch_metrics of θ = Y[:n, col] at times t[:n] (n >= 2) into out[:5].

    out = (mean pitch, steady-state pitch, settling time, tumbled, upside down),
    the booleans as 0.0 / 1.0.  buf: scratch of length >= n.  Returns the
    steady-state window's threshold (for the trail, outcome.py).
    """
    threshold = window_start(t, n, ss_fraction)
    for i in range(n):
        buf[i] = Y[i, col]
    mean = pairwise_sum(buf, 0, n) / n
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


@njit(cache=True)
def _strided_sum(Y, col):
    n = Y.shape[0]
    buf = np.empty(n)
    for i in range(n):
        buf[i] = Y[i, col]
    return pairwise_sum(buf, 0, n)


@lru_cache(maxsize=1)
def sums_match_numpy() -> bool:
    """Whether :func:`pairwise_sum` gives np.sum's bits with the installed numpy.

    Checked once per process on the lengths a sweep meets (below and above
    numpy's 8192-element buffer, contiguous and as a strided state column).
    """
    rng = np.random.default_rng(20260101)
    for n in (1, 7, 8, 9, 127, 128, 129, 1001, 8191, 8192, 8193, 10001, 20001, 100001):
        Y = rng.normal(size=(n, 3)) * np.array([1e-3, 1.0, 1e3])
        for col in range(3):
            c = np.ascontiguousarray(Y[:, col])
            s = pairwise_sum(c, 0, n)
            if s != np.sum(c) or s != np.sum(Y[:, col]) or _strided_sum(Y, col) != s:
                return False
    return True
