"""Kinetic and potential energy of the 3-D model (Eqs 3.18-3.25 extended).

Gravity of the end bodies: point mass plus MacCullagh's term of each box,
V_i = −μ m_i/|r_i| − μ (tr I_i − 3 r̂_i·I_i·r̂_i)/(2 |r_i|³), evaluated at the
body's centre (exact to quadrupole order in the body's own size).  The thesis
form expands each inverse power of |r_i| in three binomial terms (Eq 3.20 with
n = −1/2, −3/2, −5/2); the exact form uses H(u) and G(u) of derive/energy.py.
"""
from __future__ import annotations

import sympy as sp

from ..energy import InverseCubeMinusOne, InverseSqrt, InverseSqrtMinusOne
from .kinematics3d import Kinematics3D
from .symbols3d import P


def kinetic_energy(kin: Kinematics3D) -> sp.Expr:
    """T = ½ Σ m_i ṙ_i·ṙ_i + ½ ω_B·(I_1 + I_2)·ω_B, inertial ω_B (Eq 3.18) [J]."""
    w = kin.B.ang_vel_in(kin.N)
    rot = sum(w.dot(box.dot(w)) for box in kin.box_inertias) / 2
    return sum(p.kinetic_energy(kin.N) for p in kin.particles) + rot


def _beta(kin: Kinematics3D, i: int):
    """β = |r_i|² − r0² = 2 r0 y + x² + y² + z² from the COM point (Eq 3.22).

    r0 is ``kin.radius`` (r(t) on a free orbit).
    """
    x, y, z = kin.components(kin.positions[i])
    y = y - kin.radius
    return 2 * kin.radius * y + x**2 + y**2 + z**2


def series_power(kin: Kinematics3D, i: int, n, order: int) -> sp.Expr:
    """|r_i|^(2n) = (α + β)^n to the β^order term, α = |G|² (Eq 3.20 for order 2).

    Σ_{k ≤ order} C(n, k) α^(n−k) β^k: ``order`` 2 is the thesis's three binomial
    terms, 3 the Taylor series derive/orbit.py keeps for the J2 term.
    """
    r0, beta = kin.radius, _beta(kin, i)  # α^m written r0^(2m): r(t) is real, not positive
    return sum(sp.binomial(n, k) * r0 ** (2 * (n - k)) * beta**k for k in range(order + 1))


def binomial_power(kin: Kinematics3D, i: int, n) -> sp.Expr:
    """|r_i|^(2n) = (α + β)^n to three binomial terms, α = r0² (Eq 3.20).

    Parameters
    ----------
    kin : Kinematics3D
        The geometry.
    i : int
        Body index (0 tip-mass, 1 bus, 2 balloon).
    n : sympy.Rational
        Exponent: −1/2, −3/2 or −5/2.

    Returns
    -------
    sympy.Expr
        The truncated series [m^(2n)].
    """
    return series_power(kin, i, n, 2)


def exact_power(kin: Kinematics3D, i: int, n) -> sp.Expr:
    """|r_i|^(2n) exactly for n = −1/2, −3/2, −5/2 through H(u), G(u), u = β/r0².

    Parameters and returns as :func:`binomial_power`; (1 + u)^(−5/2) is written
    (1 + G(u))/(1 + u) so that only the printable H and G appear.
    """
    r0 = kin.radius
    u = _beta(kin, i) / r0**2
    if n == sp.Rational(-1, 2):
        return InverseSqrt(u) / r0
    if n == sp.Rational(-3, 2):
        return (1 + InverseCubeMinusOne(u)) / r0**3
    if n == sp.Rational(-5, 2):
        return (1 + InverseCubeMinusOne(u)) / ((1 + u) * r0**5)
    raise ValueError(n)


def _mu(mu):
    """μ = ω² r0³ (Eq 3.14) unless given (the free orbit's parameter μ)."""
    return P["omega"] ** 2 * P["r0"] ** 3 if mu is None else mu


def point_potential(kin: Kinematics3D, power, mu=None) -> sp.Expr:
    """V_points = −Σ_i μ m_i |r_i|⁻¹ over the three bodies (Eq 3.19) [J].

    μ = ω² r0³ (Eq 3.14), as in derive/energy.py, unless ``mu`` is given.
    ``power(kin, i, n)`` gives |r_i|^(2n) (binomial or exact).
    """
    mu = _mu(mu)
    masses = (P["m1"], P["m2"], P["m3"])
    return -sum(mu * m * power(kin, i, sp.Rational(-1, 2)) for i, m in enumerate(masses))


def box_potential(kin: Kinematics3D, power, mu=None) -> sp.Expr:
    """V_boxes = −Σ_i μ/2 (tr I_i |r_i|⁻³ − 3 r_i·I_i·r_i |r_i|⁻⁵), i = tip-mass, bus [J].

    MacCullagh's formula at each end body's centre; the balloon has no box term.
    μ as in :func:`point_potential`.
    """
    mu = _mu(mu)
    h = sp.Rational(1, 2)
    V = sp.S.Zero
    for i, box in enumerate(kin.box_inertias):
        r = kin.positions[i]
        trace = sum(P[f"I{i + 1}_{ax}"] for ax in ("roll", "pitch", "yaw"))
        rho = r.dot(box.dot(r))
        V -= mu * h * (trace * power(kin, i, -3 * h) - 3 * rho * power(kin, i, -5 * h))
    return V


def exact_potential_for_jacobi(V):
    """V with H(u) = 1 + (H(u) − 1), so the constant −μ m/r0 drops out exactly."""
    return V.replace(InverseSqrt, lambda u: 1 + InverseSqrtMinusOne(u))
