"""Kinetic and potential energy of the three point masses (Eqs 3.18-3.25)."""
from __future__ import annotations

import sympy as sp

from .kinematics import Kinematics
from .symbols import P


def kinetic_energy(kin: Kinematics) -> sp.Expr:
    """T = ½ Σ m_i ṙ_i·ṙ_i with inertial velocities (Eq 3.18), in J."""
    return sum(p.kinetic_energy(kin.N) for p in kin.particles)


def _offsets(kin: Kinematics, i: int) -> tuple:
    """(x_i, y_i) of body i from the COM point (0, r0): placeholders of Eq 3.22."""
    x = kin.positions[i].dot(kin.L.x)
    y = kin.positions[i].dot(kin.L.y) - P["r0"]
    return x, y


def inverse_distance_binomial(kin: Kinematics, i: int) -> sp.Expr:
    """1/|r_i| to three binomial terms (Eqs 3.20-3.25).

    (α + β)^n ≈ α^n + n α^(n-1) β + ½ n (n-1) α^(n-2) β², n = -½,
    α = r0², β = 2 r0 y + y² + x² (Eqs 3.21-3.22).
    """
    x, y = _offsets(kin, i)
    alpha, beta, n = P["r0"] ** 2, 2 * P["r0"] * y + y**2 + x**2, sp.Rational(-1, 2)
    return (alpha**n + n * alpha ** (n - 1) * beta
            + sp.Rational(1, 2) * n * (n - 1) * alpha ** (n - 2) * beta**2)


class InverseCubeMinusOne(sp.Function):
    """G(u) = (1 + u)^(-3/2) − 1, printed as expm1(−1.5 log1p(u)).

    Evaluating the "− 1" symbolically is what lets the O(r0) gravity and
    centrifugal terms of the exact-gravity model cancel exactly, instead of
    to ~1e-16 of 9.2 m/s² in floating point.
    """

    def fdiff(self, argindex=1):
        u = self.args[0]
        return sp.Rational(-3, 2) * (InverseCubeMinusOne(u) + 1) / (1 + u)

    def _eval_rewrite_as_Pow(self, u, **kwargs):
        return (1 + u) ** sp.Rational(-3, 2) - 1


class InverseSqrt(sp.Function):
    """H(u) = (1 + u)^(-1/2), with dH/du = −½ (1 + G(u))."""

    def fdiff(self, argindex=1):
        return -sp.Rational(1, 2) * (1 + InverseCubeMinusOne(self.args[0]))

    def _eval_rewrite_as_Pow(self, u, **kwargs):
        return (1 + u) ** sp.Rational(-1, 2)


class InverseSqrtMinusOne(sp.Function):
    """H(u) − 1 = (1 + u)^(-1/2) − 1, printed as expm1(−0.5 log1p(u)).

    Used in the Jacobi integral so the huge constant −μ m/r0 drops out exactly.
    """

    def fdiff(self, argindex=1):
        return -sp.Rational(1, 2) * (1 + InverseCubeMinusOne(self.args[0]))

    def _eval_rewrite_as_Pow(self, u, **kwargs):
        return (1 + u) ** sp.Rational(-1, 2) - 1


def inverse_distance_exact(kin: Kinematics, i: int) -> sp.Expr:
    """1/|r_i| = H(u)/r0 exactly, u = β/r0² (no expansion; Eqs 3.21-3.22 for β)."""
    x, y = _offsets(kin, i)
    u = (2 * P["r0"] * y + y**2 + x**2) / P["r0"] ** 2
    return InverseSqrt(u) / P["r0"]


def exact_gravity_as_powers(expr):
    """Replace H and G by their closed forms (for checks against mpmath)."""
    return expr.rewrite(sp.Pow)


def potential_energy(kin: Kinematics, inverse_distance) -> sp.Expr:
    """V = -Σ μ m_i /|r_i| (Eq 3.19), with μ = ω² r0³ (Eq 3.14), in J.

    Writing μ through ω makes the orbit rate in the kinetic energy and the
    gravity of the potential one consistent circular-orbit model, the form in
    which the thesis prints Eqs 3.28-3.30.
    """
    mu = P["omega"] ** 2 * P["r0"] ** 3
    masses = (P["m1"], P["m2"], P["m3"])
    return -sum(mu * m * inverse_distance(kin, i) for i, m in enumerate(masses))
