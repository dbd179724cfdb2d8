"""Monte Carlo statistics against independent truths: exact binomial coverage, order
statistics by simulation, Sobol' indices of models whose indices are known in closed form."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import binom

from tethersim.analysis.uncertainty import (
    order_statistic_ranks,
    proportion_ci,
    quantile_ci,
    sobol_design,
    sobol_indices,
)


@pytest.mark.parametrize("n, p", [(50, 0.1), (200, 0.3), (2000, 0.5), (2000, 0.05)])
def test_wilson_interval_exact_coverage_is_near_95_percent(n, p):
    # coverage = sum over k of P(k) [p inside the interval from k]: exact, no simulation
    k = np.arange(n + 1)
    inside = np.array([lo <= p <= hi for _, lo, hi in (proportion_ci(int(j), n) for j in k)])
    coverage = binom.pmf(k, n, p)[inside].sum()
    assert 0.93 <= coverage <= 0.975


def test_wilson_half_width_at_2000_samples_meets_the_target():
    _, lo, hi = proportion_ci(1000, 2000)  # p = 0.5: the widest
    assert (hi - lo) / 2 <= 0.025


@pytest.mark.parametrize("n, p", [(20, 0.5), (100, 0.1), (100, 0.9), (2000, 0.5)])
def test_order_statistic_ranks_cover_with_scipy_binomial(n, p):
    lo, hi = order_statistic_ranks(n, p)
    # P(X_(l) <= xi < X_(u)) = P(l <= count < u), count ~ Binomial(n, p)
    below = binom.cdf(lo - 1, n, p) if lo >= 1 else 0.0
    above = binom.sf(hi - 1, n, p) if hi <= n else 0.0
    assert below <= 0.025 and above <= 0.025
    # and tight: one rank further in breaks a tail
    if lo < n:
        assert binom.cdf(lo, n, p) > 0.025
    if hi > 1:
        assert binom.sf(hi - 2, n, p) > 0.025


def test_quantile_interval_covers_the_true_median_of_an_exponential():
    rng = np.random.default_rng(7)
    truth = math.log(2)  # median of Exp(1)
    hits = sum(lo <= truth <= hi for _, lo, hi in
               (quantile_ci(rng.exponential(size=40), 0.5) for _ in range(2000)))
    assert hits / 2000 >= 0.93


def test_censored_values_leave_a_lower_quantile_interval_unchanged():
    x = np.random.default_rng(1).normal(size=200)
    censored = np.where(x > np.quantile(x, 0.7), math.inf, x)
    assert quantile_ci(censored, 0.5) == quantile_ci(x, 0.5)
    assert quantile_ci(censored, 0.9)[0] == math.inf  # the P90 lies beyond the censoring


def test_nan_values_are_refused():
    with pytest.raises(ValueError, match="NaN"):
        quantile_ci([1.0, math.nan], 0.5)


def test_sobol_indices_of_a_linear_model_are_its_variance_shares():
    a = np.array([1.0, 2.0, 3.0, 0.0, 0.5, 1.5])
    names = [f"x{i}" for i in range(a.size)]
    u = sobol_design(names, 1024, seed=3)
    idx = sobol_indices(names, u @ a, seed=4)
    share = a ** 2 / (a ** 2).sum()  # uniform inputs of equal variance, no interactions
    for name, s in zip(names, share):
        assert idx[name]["S1"] == pytest.approx(s, abs=0.03)
        assert idx[name]["ST"] == pytest.approx(s, abs=0.03)


def test_sobol_indices_of_the_ishigami_function_match_the_closed_form():
    a, b = 7.0, 0.1
    names = ["x1", "x2", "x3"]
    x = -math.pi + 2 * math.pi * sobol_design(names, 4096, seed=5)
    y = np.sin(x[:, 0]) + a * np.sin(x[:, 1]) ** 2 + b * x[:, 2] ** 4 * np.sin(x[:, 0])
    # Ishigami & Homma (1990); Sobol' & Levitan (1999)
    v1 = 0.5 * (1 + b * math.pi ** 4 / 5) ** 2
    v2 = a ** 2 / 8
    v13 = b ** 2 * math.pi ** 8 * (1 / 18 - 1 / 50)
    v = v1 + v2 + v13
    idx = sobol_indices(names, y, seed=6)
    truth = {"x1": (v1 / v, (v1 + v13) / v), "x2": (v2 / v, v2 / v), "x3": (0.0, v13 / v)}
    for k, (s1, st) in truth.items():
        assert idx[k]["S1"] == pytest.approx(s1, abs=0.04)
        assert idx[k]["ST"] == pytest.approx(st, abs=0.04)


def test_constant_output_has_no_indices():
    idx = sobol_indices(["a", "b"], np.ones(4 * 8), seed=0)
    assert all(math.isnan(v) for d in idx.values() for v in d.values())


@pytest.mark.parametrize("n", [0, 3, 12, True])
def test_sobol_base_not_a_power_of_two_is_refused(n):
    with pytest.raises(ValueError, match="power of two"):
        sobol_design(["a", "b"], n, seed=0)
