"""The trail bound against closed forms (no simulation): decay life, the bound's ratio."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tethersim.analysis.trail_bound import decay_life, drags, trail_bound
from tethersim.model.constants import MU_EARTH, OMEGA_EARTH, R_EARTH

SAT = ts.load_preset("satI")
H = 40e3  # m, scale height of the test's exponential air
RHO0 = 2.8e-10  # kg/m^3 at the start


def _exp_air(sat):
    return lambda h: RHO0 * math.exp(-(h - sat.altitude) / H)


def _g(r):
    """√(μ r) (1 − ω_E/n)²: the part of |ṙ| that varies with the radius besides ρ."""
    n = math.sqrt(MU_EARTH / r ** 3)
    return math.sqrt(MU_EARTH * r) * (1 - OMEGA_EARTH / n) ** 2


def _closed_bracket(sat):
    """The exponential air's decay time, ∫ dh / (K ρ(h) g(r)), bracketed by g at both ends."""
    k = sat.CD * (sat.A1 + sat.A2 + sat.A3) / (sat.m1 + sat.m2 + sat.m3)
    dh = sat.altitude - sat.reentry_altitude
    c = H * (1 - math.exp(-dh / H)) / (k * RHO0)
    g = (_g(R_EARTH + sat.reentry_altitude), _g(R_EARTH + sat.altitude))
    return c / max(g), c / min(g)


def test_decay_life_lies_within_the_exponential_airs_closed_form_bracket():
    lo, hi = _closed_bracket(SAT)
    life = decay_life(SAT, _exp_air(SAT))
    assert lo <= life <= hi
    assert hi / lo < 1.02  # the bracket is tight: this is a test of the integral


def test_the_bound_ratio_matches_its_closed_form_in_exponential_air():
    tol, trail = 0.05, 29.0
    b = trail_bound(SAT, trail, tol, density=_exp_air(SAT))
    d = drags(SAT, RHO0)
    a0 = SAT.initial[2]
    torque = trail * b.tension + d[0] * SAT.b + d[1] * SAT.a
    mass = SAT.m1 + SAT.m2 + SAT.m3
    dh = SAT.altitude - SAT.reentry_altitude
    # B = 2√3 I cos A0 (A0 − 2 tol) D / (M H (1 − e^{−Δh/H}) torque), at the start's radius
    closed = (2 * math.sqrt(3) * SAT.pitch_inertia * math.cos(a0) * (a0 - 2 * tol) * sum(d)
              / (mass * H * (1 - math.exp(-dh / H)) * torque))
    lo, hi = _closed_bracket(SAT)
    # the closed form holds the radius at the start; the integral lets it fall: the
    # two differ by at most the bracket's width
    assert b.ratio == pytest.approx(closed, rel=hi / lo - 1)


def test_the_bound_ratio_does_not_depend_on_the_air_when_the_balloon_trails_hard():
    """More drag settles no faster relative to the life: both scale as 1/ρ."""
    ratios = [trail_bound(SAT, 29.0, 0.05, scale=s) for s in (0.25, 1.0, 4.0)]
    assert all(r.epsilon > 100 for r in ratios)
    assert ratios[0].decay_life == pytest.approx(16 * ratios[2].decay_life, rel=1e-9)
    for r in ratios[1:]:
        assert r.ratio == pytest.approx(ratios[0].ratio, rel=1 / ratios[0].epsilon ** 2 * 10)


def test_trail_strength_is_linear_in_the_drag():
    one, two = (trail_bound(SAT, 29.0, 0.05, scale=s) for s in (1.0, 2.0))
    assert two.epsilon == pytest.approx(2 * one.epsilon, rel=1e-12)
    assert two.tension > one.tension > one.differential_drag


def test_a_start_inside_the_band_needs_no_settling():
    sat = SAT.replace(initial=(29.0, 0.0, 0.05, 0.0, 0.0, 0.0))
    assert trail_bound(sat, 29.0, 0.05).settle_min == 0.0


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_a_trail_length_that_is_not_a_length_is_refused_naming_it(bad):
    with pytest.raises(ValueError, match="trail_length"):
        trail_bound(SAT, bad, 0.05)
