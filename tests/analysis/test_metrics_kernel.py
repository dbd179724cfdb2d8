"""The one compiled implementation of the pitch metrics (analysis.metrics_kernel).

Checked against independent computations: the compensated sum against math.fsum
(the correctly rounded sum), wrap against numpy's remainder, and the metrics and
trail against a plain numpy transcription of the definitions in docs/metrics.md.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.analysis.metrics import pitch_metrics, steady_metrics, steady_state_mean, wrap
from tethersim.analysis.metrics_kernel import compensated_sum, wrap_angle

RNG = np.random.default_rng(11)


def _same(a, b) -> bool:
    return np.float64(a).tobytes() == np.float64(b).tobytes() or (math.isnan(a) and math.isnan(b))


@pytest.mark.parametrize("n", [0, 1, 2, 7, 129, 1001, 65539, 1_000_003])
def test_compensated_sum_is_within_two_ulps_of_the_exact_sum(n):
    # magnitudes over 12 decades and both signs: a plain loop loses digits here
    a = RNG.normal(size=n) * 10.0 ** RNG.uniform(-6, 6, size=n)
    exact = math.fsum(a)
    assert abs(compensated_sum(a, n) - exact) <= 2 * np.spacing(max(abs(exact), 1e-300))


def test_compensated_sum_of_an_infinite_sample_is_infinite_not_nan():
    assert compensated_sum(np.array([1.0, math.inf, 2.0]), 3) == math.inf


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


def _numpy_definitions(t, theta, tol, ss=0.2):
    """docs/metrics.md transcribed with numpy (means in exact arithmetic: math.fsum)."""
    tail = t >= t[-1] - ss * (t[-1] - t[0])
    theta_ss = math.fsum(theta[tail]) / tail.sum()
    outside = np.nonzero(np.abs(theta - theta_ss) > tol)[0]
    if outside.size == 0:
        settling = t[0]
    elif tail[outside].any():
        settling = math.nan
    else:
        settling = t[outside[-1] + 1]
    return (math.fsum(theta) / t.size, float(wrap(theta_ss)), settling,
            bool(np.any(np.abs(theta) >= math.pi)), abs(float(wrap(theta_ss))) > 3 * math.pi / 4,
            tail)


@pytest.mark.parametrize("tol", [0.05, 0.2])
def test_pitch_metrics_and_trail_follow_their_definitions(tol):
    classes = set()
    for t, theta in _histories():
        n = t.size
        Y = np.column_stack([RNG.normal(size=n) + 28.0, theta, RNG.normal(size=n)])
        mean, ss, settling, tumbled, upside, tail = _numpy_definitions(t, theta, tol)
        m, trail = steady_metrics(t, Y, 1, (0, 2), tol=tol)
        alone = pitch_metrics(t, theta, tol=tol)
        assert all(_same(a, b) for a, b in zip(m.to_dict().values(), alone.to_dict().values()))
        # the means to a few ulps of their exact values (compensated sums)
        assert m.mean_pitch == pytest.approx(mean, rel=1e-14, abs=1e-300)
        assert m.steady_state_pitch == pytest.approx(ss, rel=1e-14, abs=1e-300)
        assert (m.tumbled, m.upside_down) == (tumbled, upside)
        # the settling sample is decided by comparisons with θ_ss ± tol: equal unless a
        # sample lies within rounding of the band's edge (none does in these histories)
        assert _same(m.settling_time, settling)
        for c, value in zip((0, 2), trail):
            assert value == pytest.approx(math.fsum(Y[tail, c]) / tail.sum(), rel=1e-14)
            assert value == steady_state_mean(t, Y[:, c])
        classes.add((math.isnan(settling), settling == t[0], tumbled, upside))
    assert len(classes) >= 5  # the histories reach the branches of the definitions
