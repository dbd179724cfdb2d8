"""The de-orbit lifetime law, trail or hang, and the verdicts (tethersim.analysis.deorbit)."""
import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

import tethersim
from tethersim.analysis import deorbit as law
from tethersim.analysis.trail_bound import decay_life, differential_drag
from tethersim.model import atmosphere
from tethersim.model.air import orbit_mean

SAT = tethersim.load_preset("satI")
NODES = orbit_mean.NODES
DAY = 86400.0


def _same_every_day(logq_row):
    return np.tile(logq_row, (3, 1)), (lambda d: np.zeros_like(d))


def test_lifetime_in_an_exponential_air_equals_the_closed_form():
    # q = q0 exp(-(h - h0)/H): t = H/(B q0) (exp((h0 - h0)/H) - exp((h_end - h0)/H)) exactly,
    # across the day boundaries the law steps through (start at 07:00 of a day)
    H, q0, h0, h_end, bc = 50e3, 0.3, 500e3, 120e3, 0.05
    logq, rows = _same_every_day(math.log(q0) - (NODES - h0) / H)
    t = law.lifetimes(logq, NODES, rows, [h0], bc, [7 * 3600.0], h_end, 1e12)[0]
    exact = H / (bc * q0) * (1 - math.exp((h_end - h0) / H))
    assert t > 30 * DAY  # many days crossed
    assert t == pytest.approx(exact, rel=1e-9)


def test_lifetime_scales_as_one_over_the_ballistic_coefficient():
    logq, rows = _same_every_day(np.log(np.array([atmosphere.density(h) for h in NODES])
                                        * law.orbit_factor(SAT, NODES)))
    t = law.lifetimes(logq, NODES, rows, [400e3, 400e3], [law.ballistic(SAT, True),
                                                          law.ballistic(SAT, False)],
                      [0.0, 0.0], SAT.reentry_altitude, 1e12)
    assert t[1] / t[0] == pytest.approx(law.ballistic(SAT, True) / law.ballistic(SAT, False),
                                        rel=1e-9)


@pytest.mark.parametrize("h0", [300e3, 600e3])
def test_lifetime_in_a_fixed_air_matches_the_trail_bound_quadrature(h0):
    # an independent integral of the same law: trail_bound.decay_life (trapezoid in h) in
    # the air the law interpolates (log-linear q between nodes) -- the day stepping and the
    # closed form within an interval are checked, not the interpolation
    vallado = np.log(np.array([atmosphere.density(h) for h in NODES]))
    f = law.orbit_factor(SAT, NODES)
    logq, rows = _same_every_day(vallado + np.log(f))
    sat = SAT.replace(altitude=h0)

    def rho(h):
        return math.exp(np.interp(h, NODES, logq[0])) / law.orbit_factor(SAT, [h])[0]
    t = law.lifetimes(logq, NODES, rows, [h0], law.ballistic(SAT, True), [0.0],
                      SAT.reentry_altitude, 1e12)[0]
    assert t == pytest.approx(decay_life(sat, rho), rel=2e-3)
    # and the log-linear interpolation of Vallado's table between the nodes costs little
    assert t == pytest.approx(decay_life(sat, atmosphere.density), rel=0.03)


def test_a_life_beyond_the_cap_is_censored():
    logq, rows = _same_every_day(np.log(np.array([atmosphere.density(h) for h in NODES])
                                        * law.orbit_factor(SAT, NODES)))
    t = law.lifetimes(logq, NODES, rows, [800e3, 300e3], law.ballistic(SAT, False), [0.0, 0.0],
                      SAT.reentry_altitude, 365.25 * DAY)
    assert math.isinf(t[0]) and math.isfinite(t[1])


def test_start_outside_the_nodes_is_refused_in_one_line():
    logq, rows = _same_every_day(np.zeros(NODES.size))
    with pytest.raises(ValueError, match=r"^start altitudes must lie in 120-1000 km$"):
        law.lifetimes(logq, NODES, rows, [1100e3], 0.1, [0.0], 120e3, 1e9)


@pytest.mark.parametrize("rho", [1e-13, 1e-12, 5e-12, 1e-10])
def test_trail_angle_is_the_minimum_of_the_pendulum_potential(rho):
    # a point mass on a rigid line of length l from the COM, in Hill's frame at rest:
    # U(phi) = -(3/2) n^2 m l^2 cos^2(phi) - dD l sin(phi), phi from the local vertical
    ell, n, m = 29.0, SAT.omega, SAT.m3
    dd = differential_drag(SAT, rho)
    u = minimize_scalar(lambda p: -1.5 * n * n * m * ell * ell * math.cos(p) ** 2
                        - dd * ell * math.sin(p), bounds=(0, math.pi / 2), method="bounded",
                        options={"xatol": 1e-10})
    assert law.trail_angle(SAT, rho, ell) == pytest.approx(u.x, abs=1e-4)


def test_line_pull_is_the_resultant_of_tide_and_drag_at_the_equilibrium():
    ell, n, m = 29.0, SAT.omega, SAT.m3
    for rho in (1e-13, 1e-10):
        phi = law.trail_angle(SAT, rho, ell)
        tide = 3 * n * n * m * ell * math.cos(phi)  # radial, at y = -l cos(phi)
        assert law.line_pull(SAT, rho, ell) == pytest.approx(
            math.hypot(tide, differential_drag(SAT, rho)), rel=1e-12)


def test_trail_altitude_is_where_the_trail_strength_is_one():
    ell = 29.0
    h = law.trail_altitude(SAT, ell, atmosphere.density)
    s = SAT.replace(altitude=h)
    eps = differential_drag(s, atmosphere.density(h)) / (3 * s.omega ** 2 * s.m3 * ell)
    assert 150e3 < h < 900e3
    assert eps == pytest.approx(1.0, rel=1e-4)
    # below it trails (phi = 90 deg), above it hangs
    below, above = SAT.replace(altitude=h - 50e3), SAT.replace(altitude=h + 50e3)
    assert law.trail_angle(below, atmosphere.density(h - 50e3), ell) == pytest.approx(math.pi / 2)
    assert law.trail_angle(above, atmosphere.density(h + 50e3), ell) < math.radians(80)


@pytest.mark.parametrize("p10, p90, verdict", [
    (1.0, 25.0, "met"), (1.0, 25.001, "epoch-dependent"), (25.0, 40.0, "epoch-dependent"),
    (25.001, 40.0, "failed")])
def test_verdict_thresholds_of_the_25_year_rule(p10, p90, verdict):
    assert law.verdict(p10 * law.YEAR, p90 * law.YEAR, 25.0) == verdict


def test_ballistic_coefficient_counts_the_balloon_only_with_it():
    assert law.ballistic(SAT, True) == pytest.approx(
        SAT.CD * (SAT.A1 + SAT.A2 + SAT.A3) / (SAT.m1 + SAT.m2 + SAT.m3))
    assert law.ballistic(SAT, False) == pytest.approx(SAT.CD * (SAT.A1 + SAT.A2) / (SAT.m1 + SAT.m2))
