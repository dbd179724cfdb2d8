"""The balloon as a de-orbit device: lifetime, trail or hang, verdicts (docs/deorbit.md).

* **Lifetime** -- the orbit-averaged circular decay of tethersim.analysis.trail_bound,
  ȧ = −ρ̄ B √(μ a)(1 − ω_E/n)², B = C_D ΣA / M, integrated day by day from the start
  altitude to re-entry.  ρ̄ is NRLMSISE-00 averaged over the orbit on each UTC day with
  that day's indices (tethersim.model.air.orbit_mean).  Within a day the product
  q(h) = ρ̄(h) √(μ a)(1 − ω_E/n)² is taken exponential between the profile's altitude
  nodes (log-linear), where the time to sink from h to h' has a closed form,
  t = (g(h) − g(h')) / (B |s|), g = 1/q, s = d ln q/dh, so a day is crossed exactly and
  the only approximation is the log-linear q between nodes.
  *With* the balloon B = C_D (A1 + A2 + A3)/(m1 + m2 + m3): towed, trailing or hanging,
  the balloon keeps its frontal area A3 to the flow (a sphere does; a sail that turns
  edge-on does not, docs/deorbit.md); *without*, the host alone, C_D (A1 + A2)/(m1 + m2).
* **Trail or hang** -- a point mass m_b on a rigid line of length ℓ from the centre of
  mass, in Hill's frame at rest: the tidal force 3 n² m_b y is radial, the differential
  drag ΔD along-track, and the line must carry their sum, so at angle φ from the local
  vertical, ΔD cos φ = 3 n² m_b ℓ cos φ sin φ: sin φ = ε = ΔD/(3 n² m_b ℓ) while ε < 1
  (it hangs, tilted by φ), and φ = 90° for ε >= 1 (it trails level behind: the tide has
  no along-track part to hold it).  The pull is 3 n² m_b ℓ (hanging) or ΔD (trailing).
* **Verdicts** -- a rule of N years is *met* when the P90 lifetime over epochs is within
  it, *failed* when the P10 is beyond it, and *epoch-dependent* between.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.trail_bound import decay_rate, differential_drag
from tethersim.model.constants import R_EARTH

DAY = 86400.0
YEAR = 365.25 * DAY
#: the rules: IADC / ISO 24113 (25 years) and the FCC's 2024 rule for LEO (5 years)
RULES_YEARS = (25.0, 5.0)


def ballistic(sat, balloon: bool) -> float:
    """B = C_D ΣA / M [m^2/kg] of the satellite with (``balloon``) or without the balloon."""
    if balloon:
        return sat.CD * (sat.A1 + sat.A2 + sat.A3) / (sat.m1 + sat.m2 + sat.m3)
    return sat.CD * (sat.A1 + sat.A2) / (sat.m1 + sat.m2)


def orbit_factor(sat, altitude) -> np.ndarray:
    """√(μ a)(1 − ω_E/n)² [m^2/s] at each altitude [m]: the decay law per unit ρ B
    (trail_bound.decay_rate, the one law, divided by the satellite's own B)."""
    b = ballistic(sat, True)
    return np.array([decay_rate(sat, 1.0, R_EARTH + h) / b for h in np.atleast_1d(altitude)])


def lifetimes(logq: np.ndarray, nodes: np.ndarray, rows, h0, bc, start_s, h_end: float,
              cap_s: float) -> np.ndarray:
    """Seconds from each start to re-entry under the day-by-day circular decay.

    Parameters
    ----------
    logq : numpy.ndarray
        (days, nodes) ln q, q = ρ̄ √(μ a)(1 − ω_E/n)² [kg/(m s)] of each day of a history.
    nodes : numpy.ndarray
        Increasing altitudes [m] of the columns.
    rows : callable
        Day index since the history's first day (int array) -> row of ``logq``.
    h0, bc, start_s : array_like
        Per run: start altitude [m], B [m^2/kg], start [s since the history's first day 0 h].
    h_end : float
        Re-entry altitude [m], inside the nodes.
    cap_s : float
        Longest life followed [s]; a run still flying then gets +inf.

    Returns
    -------
    numpy.ndarray
        Lifetimes [s] (+inf: beyond ``cap_s``).
    """
    h = np.array(h0, dtype=float)
    bc = np.broadcast_to(np.asarray(bc, dtype=float), h.shape).copy()
    start = np.broadcast_to(np.asarray(start_s, dtype=float), h.shape)
    if not (nodes[0] <= h_end and np.all(h <= nodes[-1]) and np.all(h > h_end)):
        raise ValueError(f"start altitudes must lie in {h_end / 1e3:g}-{nodes[-1] / 1e3:g} km")
    day = np.floor(start / DAY).astype(np.int64)
    budget = (day + 1) * DAY - start  # seconds left in the first day
    life = np.full(h.shape, math.inf)
    t = np.zeros(h.shape)
    k = np.clip(np.searchsorted(nodes, h, side="right") - 1, 0, nodes.size - 2)
    live = np.arange(h.size)
    while live.size:
        r = rows(day[live])
        kk = k[live]
        lo, hi = nodes[kk], nodes[kk + 1]
        q0, q1 = logq[r, kk], logq[r, kk + 1]
        s = (q1 - q0) / (hi - lo)  # d ln q / dh: < 0, the air thins upwards
        hb = np.maximum(lo, h_end)
        g_h = np.exp(-(q0 + s * (h[live] - lo)))
        g_b = np.exp(-(q0 + s * (hb - lo)))
        need = (g_h - g_b) / (-s * bc[live])  # seconds to sink to the interval's floor
        left = budget[live]
        within = need > left
        # runs that stay in this interval for the rest of the day
        w = live[within]
        g_new = g_h[within] - left[within] * (-s[within]) * bc[w]
        h[w] = lo[within] + (-np.log(g_new) - q0[within]) / s[within]
        t[w] += left[within]
        day[w] += 1
        budget[w] = DAY
        # runs that reach the floor: re-entered, or on to the interval below
        f = live[~within]
        t[f] += need[~within]
        budget[f] -= need[~within]
        h[f] = hb[~within]
        done = f[hb[~within] <= h_end]
        life[done] = t[done]
        k[f] -= 1
        over = w[t[w] > cap_s]
        keep = np.ones(h.size, bool)
        keep[done] = False
        keep[over] = False
        live = live[keep[live]]
    return life


def trail_angle(sat, rho: float, length: float) -> float:
    """Equilibrium angle [rad] of the towed balloon from the local vertical: asin(min(ε, 1)),
    ε = ΔD/(3 n² m_b ℓ) for a line of length ``length`` [m] in air ``rho`` (module text)."""
    eps = differential_drag(sat, rho) / (3 * sat.omega ** 2 * sat.m3 * length)
    return math.asin(min(eps, 1.0))


def line_pull(sat, rho: float, length: float) -> float:
    """The line's quasi-static pull [N] at that equilibrium: max(ΔD, 3 n² m_b ℓ)."""
    return max(differential_drag(sat, rho), 3 * sat.omega ** 2 * sat.m3 * length)


def trail_altitude(sat, length: float, density, low: float = 120e3,
                   high: float = 1000e3) -> float:
    """Altitude [m] where ε = 1: the balloon trails below it and hangs above it.

    Parameters
    ----------
    sat : Satellite
        The design (masses, areas, C_D); its altitude is replaced along the search.
    length : float
        The line's length ℓ [m] (the balloon's distance from the centre of mass).
    density : callable
        Air density [kg/m^3] at altitude [m] (decreasing).
    low, high : float, optional
        The search bracket [m].

    Returns
    -------
    float
        The altitude, or ``low`` (hangs everywhere) / ``high`` (trails everywhere)
        when ε does not cross 1 inside the bracket.
    """
    from scipy.optimize import brentq

    def f(h):
        s = sat.replace(altitude=h)
        return math.log(differential_drag(s, density(h)) / (3 * s.omega ** 2 * s.m3 * length))
    lo, hi = f(low), f(high)
    if lo <= 0:
        return low
    if hi >= 0:
        return high
    return brentq(f, low, high, xtol=1.0)


def verdict(p10: float, p90: float, years: float) -> str:
    """"met" (P90 within ``years``), "failed" (P10 beyond) or "epoch-dependent"."""
    if p90 <= years * YEAR:
        return "met"
    if p10 > years * YEAR:
        return "failed"
    return "epoch-dependent"
