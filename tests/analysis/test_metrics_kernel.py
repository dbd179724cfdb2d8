"""The compiled pitch metrics are metrics.py's, bit for bit (NaN equal, signed zeros distinct)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.analysis.metrics import pitch_metrics, steady_state_window, wrap
from tethersim.analysis.metrics_kernel import (
    pairwise_sum,
    pitch_metrics_into,
    sums_match_numpy,
    window_mean,
    window_start,
    wrap_angle,
)

RNG = np.random.default_rng(11)


def _same(a, b) -> bool:
    return np.float64(a).tobytes() == np.float64(b).tobytes() or (math.isnan(a) and math.isnan(b))


def test_installed_numpy_sums_pairwise_as_the_kernel_does():
    assert sums_match_numpy()


@pytest.mark.parametrize("n", [*range(1, 300), 1001, 4097, 8191, 8192, 8193, 10001, 20001, 65539])
def test_pairwise_sum_is_numpys_sum(n):
    a = RNG.normal(size=n) * 10.0 ** RNG.uniform(-6, 6, size=n)
    Y = np.column_stack([a, -a[::-1], a * 3])  # a strided column, as a state column is
    assert pairwise_sum(a, 0, n) == np.sum(a) == np.sum(Y[:, 0])
    assert pairwise_sum(np.concatenate([a, a]), n, n) == np.sum(a)  # an offset start


def test_wrap_is_numpys_wrap_bit_for_bit():
    edges = [k * math.pi + d for k in range(-9, 10) for d in (-4e-15, -1e-16, 0.0, 1e-16, 4e-15)]
    edges += [np.nextafter(math.pi, 4), np.nextafter(-math.pi, -4), 0.0, -0.0, 1e300, -1e300,
              math.inf, math.nan]
    values = np.concatenate([edges, RNG.normal(size=20000) * 10.0 ** RNG.uniform(-18, 4, 20000)])
    with np.errstate(invalid="ignore"):
        for v in values:
            assert _same(wrap_angle(v), float(wrap(v))), v


def _histories():
    """(t, theta) pairs: settling, never settling, settled from the start, tumbling,
    upside down, non-uniform times, two samples."""
    n = 1001
    t = np.linspace(0.0, 5 * 5300.0, n)
    decay = 0.6 * np.exp(-t / 4000) * np.cos(t / 500)
    yield t, decay + 0.01
    yield t, 0.3 * np.cos(t / 700)
    yield t, np.full(n, 0.02)
    yield t, np.linspace(0.0, 7.0, n)
    yield t, 3.0 + 0.2 * np.exp(-t / 3000) * np.cos(t / 400)
    yield t, -3.1 + 0.001 * np.sin(t)
    yield np.sort(RNG.uniform(0, 1e4, 777)), RNG.normal(size=777) * 0.04
    yield np.array([0.0, 1.0]), np.array([0.1, 0.2])
    for _ in range(40):
        m = int(RNG.integers(2, 12000))
        tt = np.cumsum(RNG.uniform(0.1, 30.0, m))
        yield tt, np.cumsum(RNG.normal(size=m)) * 10.0 ** RNG.uniform(-4, -1)


@pytest.mark.parametrize("tol", [0.05, 0.2])
def test_pitch_metrics_and_trail_are_metrics_py_bit_for_bit(tol):
    classes = set()
    for t, theta in _histories():
        n = t.size
        Y = np.column_stack([RNG.normal(size=n) + 28.0, theta, RNG.normal(size=n)])
        buf, out = np.empty(n), np.empty(5)
        threshold = pitch_metrics_into(t, Y, n, 1, tol, 0.2, buf, out)
        ref = pitch_metrics(t, Y[:, 1], tol=tol)
        assert _same(out[0], ref.mean_pitch)
        assert _same(out[1], ref.steady_state_pitch)
        assert _same(out[2], ref.settling_time)
        assert (out[3], out[4]) == (float(ref.tumbled), float(ref.upside_down))
        assert threshold == window_start(t, n, 0.2)
        tail = steady_state_window(t)
        assert _same(window_mean(t, Y, n, 0, threshold, buf), float(np.mean(Y[tail, 0])))
        classes.add((math.isnan(ref.settling_time), ref.settling_time == t[0], ref.tumbled,
                     ref.upside_down))
    assert len(classes) >= 5  # the histories reach the branches of pitch_metrics
