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
    """β = |r_i|² − r0² = 2 r0 y + x² + y² + z² from the COM point (Eq 3.22)."""
    x, y, z = kin.components(kin.positions[i])
    y = y - P["r0"]
    return 2 * P["r0"] * y + x**2 + y**2 + z**2


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
    alpha, beta = P["r0"] ** 2, _beta(kin, i)
    return (alpha**n + n * alpha ** (n - 1) * beta
            + sp.Rational(1, 2) * n * (n - 1) * alpha ** (n - 2) * beta**2)


def exact_power(kin: Kinematics3D, i: int, n) -> sp.Expr:
    """|r_i|^(2n) exactly for n = −1/2, −3/2, −5/2 through H(u), G(u), u = β/r0².

    Parameters and returns as :func:`binomial_power`; (1 + u)^(−5/2) is written
    (1 + G(u))/(1 + u) so that only the printable H and G appear.
    """
    u = _beta(kin, i) / P["r0"] ** 2
    r0 = P["r0"]
    if n == sp.Rational(-1, 2):
        return InverseSqrt(u) / r0
    if n == sp.Rational(-3, 2):
        return (1 + InverseCubeMinusOne(u)) / r0**3
    if n == sp.Rational(-5, 2):
        return (1 + InverseCubeMinusOne(u)) / ((1 + u) * r0**5)
    raise ValueError(n)


def point_potential(kin: Kinematics3D, power) -> sp.Expr:
    """V_points = −Σ_i μ m_i |r_i|⁻¹ over the three bodies (Eq 3.19) [J].

    μ = ω² r0³ (Eq 3.14), as in derive/energy.py.  ``power(kin, i, n)`` gives
    |r_i|^(2n) (binomial or exact).
    """
    mu = P["omega"] ** 2 * P["r0"] ** 3
    masses = (P["m1"], P["m2"], P["m3"])
    return -sum(mu * m * power(kin, i, sp.Rational(-1, 2)) for i, m in enumerate(masses))


def box_potential(kin: Kinematics3D, power) -> sp.Expr:
    """V_boxes = −Σ_i μ/2 (tr I_i |r_i|⁻³ − 3 r_i·I_i·r_i |r_i|⁻⁵), i = tip-mass, bus [J].

    MacCullagh's formula at each end body's centre; the balloon has no box term.
    """
    mu = P["omega"] ** 2 * P["r0"] ** 3
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
