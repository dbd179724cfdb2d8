"""The free-orbit derivation (derive/orbit.py): circular reduction and structure.

* On the thesis's orbit (r = r0, ṙ = r̈ = 0, ν̇ = ω = √(μ/r0³), ν̈ = 0, J2 = 0)
  the δx, δy, θ rows of every free model are exactly today's planar model
  (derive/models.py): left-hand sides and every force family, symbolically.
* Structure: truncated gravity, tethers as internal forces, the J2 term.

The generated kernels against this derivation: tests/derive/test_contract_symbolic.py.
"""
from __future__ import annotations

import functools

import pytest
import sympy as sp

from derive.energy import exact_gravity_as_powers
from derive.models import FREE_DEFINITIONS
from derive.orbit import (
    FREE_STATE_SYMBOLS,
    J2,
    R_E,
    circular_substitution,
    free_kinematics,
    free_potential,
    free_state_substitution,
    inverse_powers_binomial,
    inverse_powers_exact,
    r_ref,
)
from derive.reference import derived
from derive.symbols import P

ROWS = ("delta_x", "delta_y", "theta")
NAMES = tuple(d.name for d in FREE_DEFINITIONS)


@functools.cache
def free_model(name):
    return derived(name)


@functools.cache
def planar_model(name):
    return derived(name)


# ------------------------------------------------------- circular reduction


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_circular_orbit_reproduces_the_planar_equations(name):
    """δx, δy, θ left-hand sides and all force families: difference expands to 0."""
    model = free_model(name)
    planar = planar_model(model.definition.circular)
    sub = circular_substitution()
    for k in range(3):
        assert sp.expand(model.lhs[k].subs(sub) - planar.lhs[k]) == 0, ROWS[k]
    assert [f.name for f in model.families] == [f.name for f in planar.families]
    for fam, ref in zip(model.families, planar.families):
        for k in range(3):
            assert sp.expand(fam.Q[k].subs(sub) - ref.Q[k]) == 0, (fam.name, ROWS[k])


@pytest.mark.slow
def test_truncated_gravity_keeps_the_point_mass_term_and_drops_only_the_thesis_remainder():
    """1/|r_i| to third degree in the offsets (x_i, y_i), minus the truncated law,
    is −(5/2) y_i³/r⁴: the u³ term −(5/16)u³ missing from the thesis's three-term
    binomial (docs/errata.md N2).  Degrees 0-2 (μ m/r exact in r, the Hill
    terms) are complete; V_exact − V_free = (5/2) μ m_i y_i³/r⁴ + O(offset⁴)."""
    kin = free_kinematics()
    eps = sp.Symbol("eps")
    X, Yv = sp.symbols("X Y", real=True)
    R = sp.Symbol("R", positive=True)
    exact_xy = 1 / sp.sqrt(R**2 + 2 * R * eps * Yv + eps**2 * (X**2 + Yv**2))
    series = sp.series(exact_xy, eps, 0, 4).removeO().subs({eps: 1, R: r_ref})
    for i in range(3):
        x_i = kin.positions[i].dot(kin.L.x)
        y_i = kin.positions[i].dot(kin.L.y) - r_ref
        taylor = series.subs({X: x_i, Yv: y_i})
        trunc = inverse_powers_binomial(kin, i)[0]
        assert sp.simplify(sp.expand(taylor - trunc + sp.Rational(5, 2) * y_i**3 / r_ref**4)) == 0


def _q_of(family, k, kin_defs):
    return sp.simplify(sp.sympify(family.Q[k]).xreplace(kin_defs))


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_tethers_are_internal_forces_on_the_orbit(name):
    """Springs and the objective dampers act along the tether between two bodies:
    no generalized force on r or ν (no net force or torque on the system).  The
    thesis damper −c(ṙ3 − ṙ_end) is not along the tether: it exerts a net torque
    (Q_ν ≠ 0) but still no radial force (Q_r = 0)."""
    model = free_model(name)
    sub = free_state_substitution()
    defs = {lam: d.subs(sub) for lam, d in free_kinematics().tether_length_defs.items()}
    for fam in model.families:
        if fam.tether is None:
            continue
        assert _q_of(fam, 3, defs) == 0, fam.name
        along = fam.name.startswith("spring") or name == "free-objective-damper"
        assert (_q_of(fam, 4, defs) == 0) == along, fam.name


def test_j2_potential_of_a_body_at_the_reference_point():
    """V = −μ m (1/r + J2 R_E²/(2 r³)) at zero offset: the φ = 0 value of
    U = μ/r [1 − J2 (R_E/r)² P2(sin φ)] (Vallado Eq 8-21), V = −m U."""
    kin = free_kinematics()
    for law in (inverse_powers_binomial, inverse_powers_exact):
        V = exact_gravity_as_powers(free_potential(kin, law))
        at_ref = V.subs({P["m1"]: 0, P["m2"]: 0}).subs(free_state_substitution()).subs(
            {FREE_STATE_SYMBOLS[0]: 0, FREE_STATE_SYMBOLS[1]: 0})
        r = FREE_STATE_SYMBOLS[3]
        expected = -P["mu"] * P["m3"] * (1 / r + J2 * R_E**2 / (2 * r**3))
        assert sp.simplify(at_ref - expected) == 0
