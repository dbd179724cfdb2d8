"""Statistics of a Monte Carlo: probabilities, quantiles and Sobol' indices with their confidence.

* :func:`proportion_ci` -- a probability from k successes in n trials with Wilson's
  score interval (scipy.stats.binomtest): close to its nominal coverage even for
  small n and p near 0 or 1, where the normal (Wald) interval is not;
* :func:`quantile_ci` -- a quantile and its distribution-free interval from order
  statistics (the number of samples below the true quantile is binomial, whatever the
  distribution), which also holds for right-censored values (+inf: "beyond the run");
* :func:`sobol_design` and :func:`sobol_indices` -- Saltelli's design and the first-order
  and total indices with bootstrap intervals, through SALib (Saltelli 2010, Jansen 1999
  estimators), over the unit hypercube: the caller maps each column to its input.

Definitions and why these estimators: docs/montecarlo.md.
"""
from __future__ import annotations

import math

import numpy as np

LEVEL = 0.95


def _check_level(level: float) -> None:
    if not (isinstance(level, float) and 0.0 < level < 1.0):
        raise ValueError(f"level = {level!r}: must be a float between 0 and 1")


def proportion_ci(k: int, n: int, level: float = LEVEL) -> tuple:
    """(estimate k/n, low, high) of a probability, with Wilson's score interval.

    Parameters
    ----------
    k, n : int
        Successes and trials (0 <= k <= n, n >= 1).
    level : float, optional
        Confidence level (default 0.95).

    Returns
    -------
    tuple of float
    """
    from scipy.stats import binomtest
    _check_level(level)
    if not (isinstance(n, (int, np.integer)) and n >= 1 and 0 <= k <= n):
        raise ValueError(f"k = {k!r}, n = {n!r}: need integers 0 <= k <= n, n >= 1")
    ci = binomtest(int(k), int(n)).proportion_ci(confidence_level=level, method="wilson")
    return k / n, float(ci.low), float(ci.high)


def order_statistic_ranks(n: int, p: float, level: float = LEVEL) -> tuple:
    """1-based ranks (l, u) of the order statistics that bracket the p-quantile with
    probability >= ``level``; l = 0 or u = n + 1 where the sample is too small on that
    side (the bound is then -inf or +inf).

    The count of samples below the true quantile ξ_p is Binomial(n, p) for any
    continuous distribution, so P(X_(l) <= ξ_p < X_(u)) = F(u - 1) - F(l - 1), F that
    binomial's CDF; l is the largest rank with F(l - 1) <= (1 - level)/2 and u the smallest
    with F(u - 1) >= (1 + level)/2 (equal tails, each at most (1 - level)/2).
    """
    from scipy.stats import binom
    _check_level(level)
    if not 0.0 < p < 1.0:
        raise ValueError(f"p = {p!r}: a quantile's probability must be between 0 and 1")
    a = (1.0 - level) / 2
    cdf = binom.cdf(np.arange(n + 1), n, p)  # cdf[j] = P(count <= j)
    # l: F(l-1) <= a  <=>  cdf[l-1] <= a, largest such l in 1..n (0: none)
    low_ok = np.nonzero(cdf[:n] <= a)[0]
    lo = int(low_ok[-1]) + 1 if low_ok.size else 0
    # u: F(u-1) >= 1 - a, smallest u in 1..n (n + 1: none)
    high_ok = np.nonzero(cdf[:n] >= 1.0 - a)[0]
    hi = int(high_ok[0]) + 1 if high_ok.size else n + 1
    return lo, hi


def quantile_ci(values, p: float, level: float = LEVEL) -> tuple:
    """(estimate, low, high) of the p-quantile of ``values``, distribution-free.

    The estimate is the inverted-CDF sample quantile X_(ceil(n p)); the interval is
    [X_(l), X_(u)] of :func:`order_statistic_ranks`.  A value of +inf stands for a
    right-censored sample (e.g. a lifetime beyond the run's cap): the ranks do not
    depend on the values, so the interval stays valid, and a bound that lands on a
    censored sample is +inf ("beyond the cap").  NaN values are refused.

    Parameters
    ----------
    values : array_like
        The samples (finite or +inf).
    p : float
        The quantile's probability, 0 < p < 1.
    level : float, optional
        Confidence level.

    Returns
    -------
    tuple of float
    """
    x = np.sort(np.asarray(values, dtype=float).ravel())
    if x.size == 0:
        raise ValueError("values: need at least one sample")
    if np.isnan(x).any() or (x == -np.inf).any():
        raise ValueError("values: NaN or -inf among the samples (censored ones are +inf)")
    n = x.size
    lo, hi = order_statistic_ranks(n, p, level)
    est = x[max(1, math.ceil(n * p)) - 1]
    return (float(est), float(x[lo - 1]) if lo >= 1 else -math.inf,
            float(x[hi - 1]) if hi <= n else math.inf)


def _problem(names) -> dict:
    names = list(names)
    return {"num_vars": len(names), "names": names, "bounds": [[0.0, 1.0]] * len(names)}


def check_sobol_base(n: int) -> None:
    """Refuse a Sobol' base sample size that is not a power of two >= 2 (one line)."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2 or n & (n - 1):
        raise ValueError(f"sobol = {n!r}: the base sample size must be a power of two >= 2 "
                         f"(2, 4, ..., 64, 128, ...): the Sobol' sequence is balanced only there")


def sobol_design(names, n: int, seed: int) -> np.ndarray:
    """Saltelli's design over the unit hypercube: (n (d + 2), d) points, d = len(names).

    Rows come in groups of d + 2 (A, the d AB matrices, B), as
    :func:`sobol_indices` expects; a scrambled Sobol' sequence seeded by ``seed``
    (the same seed gives the same design).  Second-order indices are not computed
    (they would double the runs).
    """
    from SALib.sample import sobol as sampler
    check_sobol_base(n)
    return sampler.sample(_problem(names), int(n), calc_second_order=False, scramble=True,
                          seed=int(seed))


def sobol_indices(names, y, seed: int, level: float = LEVEL) -> dict:
    """First-order and total Sobol' indices of output ``y`` on :func:`sobol_design`'s rows.

    Parameters
    ----------
    names : sequence of str
        The inputs, in the design's column order.
    y : array_like
        The output at every design row (finite).
    seed : int
        Seed of the bootstrap that gives the intervals.
    level : float, optional
        Confidence level of the intervals.

    Returns
    -------
    dict
        ``{name: {"S1", "S1_conf", "ST", "ST_conf"}}``: the indices and the half-widths
        of their bootstrap intervals.  An output with zero variance has no indices:
        every value is NaN.
    """
    from SALib.analyze import sobol as analyser
    _check_level(level)
    y = np.asarray(y, dtype=float)
    names = list(names)
    if y.ndim != 1 or y.size % (len(names) + 2) or not np.isfinite(y).all():
        raise ValueError(f"y: need {len(names) + 2} x N finite values (one per design row), "
                         f"got {y.size}")
    if np.ptp(y) == 0.0:  # SALib divides by the variance
        return {k: dict.fromkeys(("S1", "S1_conf", "ST", "ST_conf"), math.nan) for k in names}
    r = analyser.analyze(_problem(names), y, calc_second_order=False, conf_level=level,
                         print_to_console=False, seed=int(seed))
    return {k: {"S1": float(r["S1"][i]), "S1_conf": float(r["S1_conf"][i]),
                "ST": float(r["ST"][i]), "ST_conf": float(r["ST_conf"][i])}
            for i, k in enumerate(names)}
