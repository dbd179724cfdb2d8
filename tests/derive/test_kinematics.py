"""Kinematics and gravity potential of the derivation (Eqs 3.10-3.25).

References are to the thesis as printed (Maramba 2005, chapter III).
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from derive.energy import (
    InverseCubeMinusOne,
    InverseSqrt,
    inverse_distance_binomial,
    inverse_distance_exact,
)
from derive.pipeline import to_state_symbols
from derive.printer import NumbaPrinter
from derive.symbols import COORDINATES, STATE_SYMBOLS, TETHER_LENGTHS, P, t

a, b, r0, omega = P["a"], P["b"], P["r0"], P["omega"]
dx, dy, th = COORDINATES
dxd, dyd, thd = (q.diff(t) for q in COORDINATES)
s, c = sp.sin(th), sp.cos(th)

# Eqs 3.10-3.12, typed from equations.md.
POSITIONS_PRINTED = (
    (b * s, r0 + b * c),
    (-a * s, r0 - a * c),
    (dx, r0 + dy),
)
# Eqs 3.15-3.17, typed from equations.md: ṙ = d/dt r + ω ẑ × r (3.13).
VELOCITIES_PRINTED = (
    (b * thd * c - omega * (r0 + b * c), -b * thd * s + omega * b * s),
    (-a * thd * c - omega * (r0 - a * c), a * thd * s - omega * a * s),
    (dxd - omega * (r0 + dy), dyd + omega * dx),
)


@pytest.mark.parametrize("i", range(3), ids=("tip-mass", "bus", "balloon"))
def test_positions_equal_eqs_3_10_to_3_12(kin, i):
    L = kin.L
    got = kin.positions[i]
    for comp, e in zip(POSITIONS_PRINTED[i], (L.x, L.y)):
        assert sp.simplify(got.dot(e) - comp) == 0
    assert sp.simplify(got.dot(L.z)) == 0


@pytest.mark.parametrize("i", range(3), ids=("tip-mass", "bus", "balloon"))
def test_frame_kinematics_velocities_equal_eqs_3_15_to_3_17(kin, i):
    """ṙ_i from sympy's frame kinematics (d/dt in N, expressed in L) equals the
    printed inertial velocities, component by component, and has no z part."""
    L = kin.L
    v = kin.velocities[i]
    for comp, e in zip(VELOCITIES_PRINTED[i], (L.x, L.y)):
        assert sp.simplify(v.dot(e) - comp) == 0
    assert sp.simplify(v.dot(L.z)) == 0
    # The point's velocity registered for LagrangesMethod is the same vector.
    assert sp.simplify((kin.points[i].vel(kin.N) - v).magnitude()) == 0


def test_com_moves_along_minus_x_with_omega_z(kin):
    """Frame convention (Eq 3.13, ω ẑ): the COM at (0, r0) has inertial velocity
    (−ω r0, 0), i.e. along −x, although the thesis prose calls +x the ram direction."""
    com = kin.origin.locatenew("COM", r0 * kin.L.y)
    v = com.pos_from(kin.origin).dt(kin.N).express(kin.L)
    assert sp.simplify(v.dot(kin.L.x) + omega * r0) == 0
    assert sp.simplify(v.dot(kin.L.y)) == 0


@pytest.mark.parametrize("j", range(2), ids=("lambda1", "lambda2"))
def test_tether_lengths_equal_eqs_3_41_3_42(tether_length_defs, j):
    x, y, theta = STATE_SYMBOLS[:3]
    printed = (
        sp.sqrt((b * sp.sin(theta) - x) ** 2 + (b * sp.cos(theta) - y) ** 2),  # 3.41
        sp.sqrt((-a * sp.sin(theta) - x) ** 2 + (-a * sp.cos(theta) - y) ** 2),  # 3.42
    )[j]
    assert sp.simplify(tether_length_defs[TETHER_LENGTHS[j]] - printed) == 0


# ---------------------------------------------------------------- gravity


def _balloon_inverse_distances(kin):
    """(binomial 1/|r3| of Eqs 3.20-3.25, exact 1/|r3|) in the plain state symbols."""
    x, y = STATE_SYMBOLS[:2]
    binomial = to_state_symbols(inverse_distance_binomial(kin, 2))
    exact = 1 / sp.sqrt(x**2 + (r0 + y) ** 2)
    return binomial, exact


def test_binomial_inverse_distance_error_leading_term_is_five_halves_dy_cubed(kin):
    """Series in 1/r0: binomial − exact 1/|r3| = (5/2) δy³ / r0⁴ + O(1/r0⁵).

    The 3-term binomial (Eqs 3.20-3.25) is exact through (offset/r0)², so its
    relative error starts at third order: (5/2)(δy/r0)³, which is the P3
    (octupole) Legendre term minus the part of it that β² already holds.
    """
    x, y = STATE_SYMBOLS[:2]
    binomial, exact = _balloon_inverse_distances(kin)
    eps = sp.Symbol("eps", positive=True)
    diff = (binomial - exact).subs(r0, 1 / eps)
    ser = sp.expand(sp.series(diff, eps, 0, 5).removeO())
    assert all(sp.simplify(ser.coeff(eps, n)) == 0 for n in range(4))
    assert sp.simplify(ser.coeff(eps, 4) - sp.Rational(5, 2) * y**3) == 0


def test_binomial_inverse_distance_relative_error_scales_as_offset_over_r0_cubed(kin):
    """mpmath at 60 digits: log10 of |binomial/exact − 1| against log10 of the
    offset has slope 3 (fit over offsets 1 m ... 10 km along a direction 0.7 rad
    from the local vertical), and the error divided by (offset/r0)³ equals the
    leading coefficient (5/2) cos³(0.7) of the series test above."""
    binomial, exact = _balloon_inverse_distances(kin)
    x, y = STATE_SYMBOLS[:2]
    f_bin = sp.lambdify((x, y, r0), binomial, modules="mpmath")
    f_ex = sp.lambdify((x, y, r0), exact, modules="mpmath")
    radius = 6.578e6  # m, the 200 km orbit (docs/sources.md, "The thesis")
    phi = 0.7  # rad from +y; cos φ ≠ 0 so the (δy)³ term is present
    offsets = np.logspace(0, 4, 9)  # 1 m ... 10 km
    rel = []
    with mpmath.workdps(60):
        R = mpmath.mpf(radius)
        for d in offsets:
            X, Y = mpmath.mpf(d * math.sin(phi)), mpmath.mpf(d * math.cos(phi))
            rel.append(abs(f_bin(X, Y, R) / f_ex(X, Y, R) - 1))
        coeff = [float(e / (mpmath.mpf(d) / R) ** 3) for e, d in zip(rel, offsets)]
    slope = np.polyfit(np.log10(offsets), np.log10([float(e) for e in rel]), 1)[0]
    assert slope == pytest.approx(3.0, abs=0.01)
    # Next-order correction is O(offset/r0) <= 1.5e-3 at 10 km.
    assert coeff == pytest.approx([2.5 * math.cos(phi) ** 3] * len(offsets), rel=5e-3)


def test_exact_inverse_distance_rewrites_to_one_over_norm(kin):
    """H(u)/r0 with u = (2 r0 y + y² + x²)/r0² (energy.inverse_distance_exact) is
    exactly 1/|r_i|: its rewritten inverse square equals |r_i|² (Eqs 3.19, 3.22)."""
    for i in range(3):
        inv = inverse_distance_exact(kin, i).rewrite(sp.Pow)
        r = kin.positions[i]
        norm2 = r.dot(kin.L.x) ** 2 + r.dot(kin.L.y) ** 2
        assert sp.simplify(inv ** -2 - norm2) == 0


u = sp.Symbol("u", real=True)
H, G = InverseSqrt(u), InverseCubeMinusOne(u)


@pytest.mark.parametrize("fn", (H, G), ids=("H", "G"))
@pytest.mark.parametrize("order", (1, 2, 3))
def test_exact_gravity_functions_derivative_commutes_with_rewrite(fn, order):
    """fdiff of H(u) = (1+u)^(-1/2) and G(u) = (1+u)^(-3/2) − 1, rewritten as
    powers, equals the derivative of the rewritten closed form (orders 1-3)."""
    lhs = fn.diff(u, order).rewrite(sp.Pow)
    rhs = fn.rewrite(sp.Pow).diff(u, order)
    assert sp.simplify(lhs - rhs) == 0


def test_exact_gravity_closed_forms():
    assert sp.simplify(H.rewrite(sp.Pow) - 1 / sp.sqrt(1 + u)) == 0
    assert sp.simplify(G.rewrite(sp.Pow) - ((1 + u) ** sp.Rational(-3, 2) - 1)) == 0
    # dH/du = −½ (1 + G) (energy.InverseSqrt), itself a closed-form identity.
    assert sp.simplify((H.diff(u) + (1 + G) / 2).rewrite(sp.Pow)) == 0


@pytest.mark.parametrize("value", (1e-12, -3e-9, 3e-6, -1e-3, 0.5))
def test_printed_g_is_expm1_log1p_and_accurate_at_small_u(value):
    """The code printer writes G(u) as expm1(−1.5 log1p(u)), which keeps full
    relative precision where (1+u)^(-3/2) − 1 would cancel (u ~ δy/r0 ~ 1e-6)."""
    code = NumbaPrinter().doprint(G)
    assert code == "math.expm1(-1.5*math.log1p(u))"
    got = eval(code, {"math": math, "u": value})
    with mpmath.workdps(40):
        truth = (1 + mpmath.mpf(value)) ** mpmath.mpf(-1.5) - 1
        # log1p, the product and expm1 each round once (<= 1 ulp): a few ulps.
        assert abs(got - truth) <= 1e-15 * abs(truth)
