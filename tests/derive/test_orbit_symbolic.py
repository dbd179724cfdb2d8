"""The free-orbit derivation (derive/orbit.py): circular reduction, structure, kernels.

* On the thesis's orbit (r = r0, ṙ = r̈ = 0, ν̇ = ω = √(μ/r0³), ν̈ = 0, J2 = 0)
  the δx, δy, θ rows of every free model are exactly today's planar model
  (derive/models.py): left-hand sides and every force family, symbolically.
* Generated kernels (generated/free*.py) against the symbolic model at random
  states, in 30-digit mpmath arithmetic.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import pytest
import sympy as sp

import tethersim.generated as generated
from derive.energy import exact_gravity_as_powers
from derive.models import FREE_DEFINITIONS
from derive.orbit import (
    FREE_PARAMETERS,
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
from derive.symbols import TETHER_LENGTHS, P
from tethersim.engine.jacobian import jacobian
from tethersim.model.registry import BY_NAME as REGISTRY

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


# --------------------------------------------- generated kernels vs symbolic


def _random_states(rng, n):
    """States around a 200 km orbit: taut and slack tethers, any pitch, eccentric rates."""
    r0 = 6578.137e3
    n0 = math.sqrt(3.986004418e14 / r0**3)
    for _ in range(n):
        yield np.array([rng.uniform(-12, 12), rng.uniform(-12, 12), rng.uniform(-math.pi, math.pi),
                        r0 + rng.uniform(-5e4, 5e4), rng.uniform(0, 10),
                        rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1e-2, 1e-2),
                        rng.uniform(-50, 50), n0 * rng.uniform(0.98, 1.02)])


def _random_params(rng):
    values = dict(m1=10.0, m2=105.0, m3=1.0, A1=0.1, A2=1.05, A3=12.0, a=1.0, b=10.5,
                  l10=6.0, l20=6.0, E1=0.004, E2=0.0427, c1=0.03, c2=0.05, CD=2.0,
                  mu=3.986004418e14, omega_earth=7.292115e-5, rho1=2.7e-10, rho2=2.9e-10,
                  rho3=2.8e-10, J2=1.08263e-3, R_E=6378.137e3)
    values = {k: v * rng.uniform(0.8, 1.25) for k, v in values.items()}
    return np.array([values[p.name] for p in FREE_PARAMETERS])


@functools.cache
def _lambdified(name):
    """mpmath functions of (y, p): M, f, per-family Q (gated by λ > l0), energy."""
    model = free_model(name)
    sub = free_state_substitution()
    defs = {lam: d.subs(sub) for lam, d in free_kinematics().tether_length_defs.items()}
    args = list(FREE_STATE_SYMBOLS) + [p.symbol for p in FREE_PARAMETERS]

    def fn(expr):
        e = exact_gravity_as_powers(sp.sympify(expr).xreplace(defs))
        return sp.lambdify(args, e, modules="mpmath")

    lengths = [fn(defs[lam]) for lam in TETHER_LENGTHS]
    springs = [fn(sum(f.potential for f in model.families if f.tether == j + 1
                      and f.potential is not None)) for j in range(2)]
    return (fn(model.mass_matrix), [fn(e) for e in model.f],
            [(fam.tether, [fn(q) for q in fam.Q]) for fam in model.families],
            fn(model.energy), lengths, springs)


def _symbolic(name, y, p):
    mpmath.mp.dps = 30
    M, f, fams, energy, lengths, springs = _lambdified(name)
    args = [v if isinstance(v, mpmath.mpf) else mpmath.mpf(float(v)) for v in list(y) + list(p)]
    rest = (p[[i for i, q in enumerate(FREE_PARAMETERS) if q.name == "l10"][0]],
            p[[i for i, q in enumerate(FREE_PARAMETERS) if q.name == "l20"][0]])
    taut = [lengths[j](*args) > rest[j] for j in range(2)]
    Q = [[q(*args) if (t is None or taut[t - 1]) else 0 for q in qs] for t, qs in fams]
    Mm = mpmath.matrix(M(*args))
    rhs = mpmath.matrix([sum(col[k] for col in Q) - f[k](*args) for k in range(5)])
    qdd = mpmath.lu_solve(Mm, rhs)
    e = energy(*args) + sum(springs[j](*args) for j in range(2) if taut[j])
    return [qdd[k] for k in range(5)], Q, e, taut


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_generated_kernels_equal_the_symbolic_model_at_random_states(name):
    """rhs (q̈ by the kernel's LDLᵀ vs 30-digit LU of the symbolic M), family
    forces and energy, at 12 random states with taut and slack tethers."""
    rng = np.random.default_rng(12)
    module = generated.MODELS[name]
    seen = set()
    for y in _random_states(rng, 12):
        p = _random_params(rng)
        qdd, Q, energy, taut = _symbolic(name, y, p)
        seen.add(tuple(taut))
        d = np.zeros(10)
        module.rhs(0.0, y, p, d)
        assert np.array_equal(d[:5], y[5:])
        # m/s², rad/s²: rounding of the ~9 m/s² gravity/centrifugal terms (measured ≤ 3.3e-15),
        # eight orders below the ~1e-5 m/s² tidal terms
        scale = [1e-13, 1e-13, 1e-13, 1e-13, 1e-20]
        for k in range(5):
            truth = float(qdd[k])
            assert abs(d[5 + k] - truth) < scale[k] + 1e-12 * abs(truth), (k, d[5 + k], truth)
        out = np.zeros((7, 5))
        module.family_forces(y, p, out)
        assert np.allclose(out, np.array(Q, dtype=float), rtol=1e-10, atol=1e-14)
        h = float(energy)
        assert abs(module.jacobi(y, p) - h) < 1e-6 + 1e-15 * abs(h)
    assert len(seen) >= 3  # both tethers' gates were exercised


@pytest.mark.slow  # compiles each free model's difference loop
@pytest.mark.parametrize("name", NAMES)
def test_jacobian_matches_the_symbolic_difference_quotient(name):
    """The engine's Jacobian (central differences of the generated rhs, no generated
    jacobian for the free models) against the 30-digit difference quotient of the
    symbolic q̈ (step 1e-10 max(1, |y_c|)): per row, to 1e-4 of the row's largest entry
    (tethersim/engine/jacobian.py: the cancelling ~9 m/s² gravity rounds at ~1e-15 m/s²)."""
    rng = np.random.default_rng(5)
    for y in _random_states(rng, 3):
        p = _random_params(rng)
        J = np.zeros((10, 10))
        jacobian(REGISTRY[name].index, 0.0, y, p, J)
        assert np.array_equal(J[:5], np.eye(10)[5:])  # d(q)/dt = q̇
        truth = np.zeros((5, 10))
        with mpmath.workdps(30):
            for c in range(10):
                h = mpmath.mpf(1e-10) * max(1.0, abs(y[c]))
                yp, ym = [mpmath.mpf(float(v)) for v in y], [mpmath.mpf(float(v)) for v in y]
                yp[c] += h
                ym[c] -= h
                qp, qm = _symbolic(name, yp, p)[0], _symbolic(name, ym, p)[0]
                truth[:, c] = [float((qp[k] - qm[k]) / (2 * h)) for k in range(5)]
        scale = np.max(np.abs(truth), axis=1, keepdims=True)
        assert np.all(np.abs(J[5:] - truth) <= 1e-4 * scale), np.max(np.abs(J[5:] - truth) / scale)
