"""The 3-D model on a free orbit (issue 12 item 1): r(t), ν(t) as coordinates.

The 3-D kinematics of derive/three_d/kinematics3d.py with the COM point G at
distance r(t) from Earth's centre and the local frame L turned by ν(t) about
z (the planar free model's convention, derive/orbit.py: in N, G = r (−sin ν,
cos ν, 0); L turns at ν̇ ẑ).  q = (δx, δy, δz, φ, θ, ψ, r, ν), 16 states.  No
body moves on a prescribed path: the Lagrangian of the three bodies (point
masses plus the boxes' rotational energy, Eq 3.18) gives r̈ and ν̈ together
with the offsets' and angles' accelerations; drag in co-rotating air (Eqs
3.32-3.34 in 3-D) and the tethers (3.35-3.47 in 3-D) enter through Eq 3.31
on all eight coordinates (derive/three_d/forces3d.py, over ``kin.speeds``).

What the coordinates impose: G stays in the equatorial plane z = 0 (r and ν
are planar), as the 3-D circular model holds G on its circle.  The boom turns
about G; the out-of-plane translation of the boom's centre that the
balloon's δz tether pull would cause (m3 δz/(m1 + m2) of the offset) is not a
coordinate.  The constraint keeps G's velocity in the plane, so its reaction
does no work and T + V is still the Jacobi integral.

Gravity, per body i, with |r_i|² = r² (1 + u_i), u_i = (2 r y_i + x_i² + y_i² +
z_i²)/r² and (x_i, y_i, z_i) its offset from G in L:

* point mass −μ m_i/|r_i| (Eq 3.19), MacCullagh's term of the tip-mass and bus
  boxes −μ (tr I − 3 r̂·I·r̂)/(2|r_i|³) (derive/three_d/energy3d.py);
* J2 with the body's own latitude, sin φ_i = z_i/|r_i| (z is Earth's axis,
  N.z = L.z): −μ m_i J2 R_E² (1 − 3 sin²φ_i)/(2 |r_i|³) (Vallado Eq 8-21,
  potential energy −m U), the point-mass part only (J2 acting on the boxes'
  quadrupoles, ~J2 I/(m r²) ≈ 1e-16 of the J2 force, is dropped);
* ``3d-free``, ``3d-free-objective-damper``: |r_i|⁻¹ by the thesis's three
  binomial terms, |r_i|⁻³ and |r_i|⁻⁵ by their Taylor series to u³ (as
  derive/orbit.py does for J2), then V truncated at third degree in the
  offsets, counting the boxes' inertias as degree 2 (I ~ m·size²).  With r =
  r0, μ = ω² r0³ this is exactly the 3-D circular model's O(1/r0) truncation;
  with the out-of-plane state and the inertias zero it is the planar free
  model's potential.  The z-dependent J2 term 3 μ m J2 R_E² z²/(2 r⁵) is kept
  to that degree (z² and z² y/r).
* no exact-gravity twin: a definition with ``exact_power`` and no truncation derives one
  (|r_i|^(2n) through H(u), G(u)), but its printed kernels are ~19 000 lines
  (Jacobian of the unexpanded H, G terms in 16 states) and it alone adds
  ~3 minutes to ``make derive``; not emitted (docs/orbit.md).
"""
from __future__ import annotations

import functools

import sympy as sp

from ..model import Equations
from ..orbit import FREE_PARAMETERS, J2, R_E, _truncate_degree, nu, r_ref
from .energy3d import binomial_power, box_potential, kinetic_energy, point_potential, series_power
from .kinematics3d import Kinematics3D, kinematics_3d
from .pipeline3d import lagrange_terms
from .symbols3d import COORDINATE_NAMES, COORDINATE_UNITS, COORDINATES, INERTIAS, P, t

FREE3D_COORDINATES = COORDINATES + (r_ref, nu)
FREE3D_SPEEDS = tuple(q.diff(t) for q in FREE3D_COORDINATES)
FREE3D_ACCELERATIONS = tuple(q.diff(t, 2) for q in FREE3D_COORDINATES)
_NAMES = COORDINATE_NAMES + ("r", "nu")
FREE3D_STATE_NAMES = _NAMES + tuple(f"{n}_dot" for n in _NAMES)
FREE3D_STATE_UNITS = (COORDINATE_UNITS + ("m", "rad", "m/s", "m/s", "m/s")
                      + ("rad/s",) * 3 + ("m/s", "rad/s"))
FREE3D_STATE_SYMBOLS = tuple(sp.Symbol(n, real=True) for n in FREE3D_STATE_NAMES)
FREE3D_ACCELERATION_SYMBOLS = tuple(sp.Symbol(f"{n}_ddot", real=True) for n in _NAMES)
FREE3D_Q_SYMBOLS = tuple(sp.Symbol(f"Q_{n}", real=True) for n in _NAMES)
# the planar free vector (indices 0-21: no r0, ω; J2, R_E), then the six box inertias
FREE3D_PARAMETERS = FREE_PARAMETERS + INERTIAS
MU = P["mu"]
TRUNCATION_DEGREE = 3  # highest degree in the offsets kept in V (derive/orbit.py)


def free3d_substitution() -> dict:
    """Map q̈, q̇, q (functions of t) to plain symbols, highest derivatives first."""
    sub = dict(zip(FREE3D_ACCELERATIONS, FREE3D_ACCELERATION_SYMBOLS))
    sub.update(zip(FREE3D_SPEEDS, FREE3D_STATE_SYMBOLS[8:]))
    sub.update(zip(FREE3D_COORDINATES, FREE3D_STATE_SYMBOLS[:8]))
    return sub


def to_free3d_symbols(expr):
    """Replace q(t), q̇(t), q̈(t) by the plain state symbols."""
    return sp.sympify(expr).xreplace(free3d_substitution())


@functools.cache
def free3d_kinematics() -> Kinematics3D:
    """The 3-D geometry about G = r(t) L.y, L turned by ν(t) (Eqs 3.10-3.17, r0 → r, ωt → ν)."""
    return kinematics_3d(radius=r_ref, angle=nu, speeds=FREE3D_SPEEDS)


def taylor_power(kin: Kinematics3D, i: int, n) -> sp.Expr:
    """|r_i|^(2n): the thesis's three binomial terms for n = −1/2, else the Taylor series to u³."""
    return binomial_power(kin, i, n) if n == sp.Rational(-1, 2) else series_power(kin, i, n, 3)


def j2_potential(kin: Kinematics3D, power) -> sp.Expr:
    """−Σ μ m_i J2 R_E² (|r_i|⁻³ − 3 z_i² |r_i|⁻⁵)/2: J2 at each body's latitude [J]."""
    V = sp.S.Zero
    for i, m in enumerate((P["m1"], P["m2"], P["m3"])):
        z = kin.positions[i].dot(kin.L.z)
        V -= MU * m * J2 * R_E**2 / 2 * (power(kin, i, sp.Rational(-3, 2))
                                          - 3 * z**2 * power(kin, i, sp.Rational(-5, 2)))
    return V


def truncate_offsets(expr, degree: int):
    """Keep the terms of degree ≤ ``degree`` in the offsets (δ, a, b; the inertias count 2)."""
    eps = sp.Dummy("eps")
    y = FREE3D_STATE_SYMBOLS
    scale = {s: eps * s for s in (y[0], y[1], y[2], P["a"], P["b"])}
    scale.update({p.symbol: eps**2 * p.symbol for p in INERTIAS})
    return _truncate_degree(sp.sympify(expr).xreplace(scale), eps, degree)


def free3d_potential(kin: Kinematics3D, power, truncation) -> sp.Expr:
    """V = points + boxes + J2 in the state symbols, truncated at degree ``truncation`` [J]."""
    V = (point_potential(kin, power, MU) + box_potential(kin, power, MU)
         + j2_potential(kin, power))
    V = to_free3d_symbols(V)
    return V if truncation is None else truncate_offsets(V, truncation)


@functools.cache
def _lagrange(power, truncation) -> tuple:
    """(M, f, T + V) for one gravity law (variants that differ in forces share it)."""
    kin = free3d_kinematics()
    T = to_free3d_symbols(kinetic_energy(kin))
    V = free3d_potential(kin, power, truncation)
    M, f = lagrange_terms(T, V, 0, FREE3D_STATE_SYMBOLS)
    M = M.applyfunc(lambda e: sp.factor_terms(sp.expand(sp.trigsimp(e))))
    return M, f, sp.expand(T) + V


def equations(defn, kin=None) -> Equations:
    """Lagrange's equations (3.26) of the 8-coordinate model (``defn.potential``: |r_i|^(2n) about r)."""
    return Equations(*_lagrange(defn.potential, defn.truncation))
