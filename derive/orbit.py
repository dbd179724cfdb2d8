"""The free orbit (issue 12): the boom COM's polar coordinates as coordinates.

The thesis holds the reference point on a circular orbit (r0, ω = const,
Eq 3.13).  Here the local frame L turns with the angle ν(t) about z (its y axis
along the radius to the reference point, the boom COM) and r(t) is that point's
distance from Earth's centre, so q = (δx, δy, θ, r, ν) and

    r1 = (b sin θ, r + b cos θ),  r2 = (−a sin θ, r − a cos θ),  r3 = (δx, r + δy)

in L (Eqs 3.10-3.12 with r0 → r(t)); the inertial velocities come from frame
kinematics with L's angular velocity ν̇ ẑ (Eq 3.13 with ω → ν̇).  No body moves
on a prescribed path: the Lagrangian L = T − V of all three bodies (Eqs 3.18-
3.19) yields r̈ and ν̈ together with δẍ, δÿ, θ̈; drag on every body (Eqs 3.32-
3.34, air co-rotating at ω_E ẑ) and the tethers (3.35-3.47) enter through
Eq 3.31 on all five coordinates.

Gravity, per body i with offsets (x_i, y_i) from the reference point and
u_i = (2 r y_i + x_i² + y_i²)/r², so |r_i| = r √(1 + u_i):

* ``binomial``: 1/|r_i| ≈ (1 − u/2 + 3u²/8)/r, the thesis's three binomial
  terms (Eqs 3.20-3.25 with α = r²), then truncated at third degree in the
  offsets.  The point-mass term μ m_i / r is kept exactly in r.  With r = r0,
  μ = ω² r0³ this is exactly the truncation of the planar pipeline (order
  1/r0), so the circular reduction reproduces the ``derived`` model.
* ``exact``: 1/|r_i| = H(u_i)/r, H(u) = (1 + u)^(-1/2) (energy.InverseSqrt).

J2 (equatorial plane, the planar model's orbit is equatorial): potential
energy −μ J2 R_E² / (2 |r_i|³) per unit mass, the φ = 0 value of
+μ J2 R_E² (3 sin²φ − 1)/(2 r³) (geopotential U = μ/r [1 − J2 (R_E/r)² P2(sin φ)],
Vallado Eq 8-21, potential energy −U).  J2 and R_E are parameters; J2 = 0
switches it off.  ``binomial`` truncates (1 + u)^(-3/2) at the same degree.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, Particle, Point, ReferenceFrame, dynamicsymbols

from .energy import InverseSqrt, InverseSqrtMinusOne, kinetic_energy
from .kinematics import Kinematics
from .model import Equations
from .symbols import COORDINATES, PARAMETERS, TETHER_LENGTHS, P, Parameter, t

r_ref, nu = dynamicsymbols("r nu")
FREE_COORDINATES = COORDINATES + (r_ref, nu)
FREE_SPEEDS = tuple(q.diff(t) for q in FREE_COORDINATES)
FREE_ACCELERATIONS = tuple(q.diff(t, 2) for q in FREE_COORDINATES)

# State order of every free-orbit kernel: coordinates, then their rates.
FREE_STATE_NAMES = ("delta_x", "delta_y", "theta", "r", "nu",
                    "delta_x_dot", "delta_y_dot", "theta_dot", "r_dot", "nu_dot")
FREE_STATE_UNITS = ("m", "m", "rad", "m", "rad", "m/s", "m/s", "rad/s", "m/s", "rad/s")
FREE_STATE_SYMBOLS = tuple(sp.Symbol(n, real=True) for n in FREE_STATE_NAMES)
FREE_ACCELERATION_SYMBOLS = tuple(sp.Symbol(f"{n}_ddot", real=True) for n in FREE_STATE_NAMES[:5])
FREE_Q_SYMBOLS = tuple(sp.Symbol(f"Q_{n}", real=True) for n in FREE_STATE_NAMES[:5])

J2_PARAMETER = Parameter("J2", sp.Symbol("J2", nonnegative=True), "1",
                         "Earth's second zonal harmonic (0 switches J2 off)")
RE_PARAMETER = Parameter("R_E", sp.Symbol("R_E", positive=True), "m",
                         "Earth's equatorial radius (J2 term)")
# Parameter vector of the free-orbit kernels: the planar one without r0 and ω
# (the orbit is now state), then J2 and R_E.  Explicit order, as in symbols.py.
FREE_PARAMETERS = tuple(p for p in PARAMETERS if p.name not in ("r0", "omega")) + (
    J2_PARAMETER, RE_PARAMETER)
FREE_PARAMETER_NAMES = tuple(p.name for p in FREE_PARAMETERS)
J2, R_E = J2_PARAMETER.symbol, RE_PARAMETER.symbol


def free_state_substitution() -> dict:
    """Map q̈, q̇, q (functions of t) to plain symbols, highest derivatives first."""
    sub = dict(zip(FREE_ACCELERATIONS, FREE_ACCELERATION_SYMBOLS))
    sub.update(zip(FREE_SPEEDS, FREE_STATE_SYMBOLS[5:]))
    sub.update(zip(FREE_COORDINATES, FREE_STATE_SYMBOLS[:5]))
    return sub


def to_free_symbols(expr):
    """Replace q(t), q̇(t), q̈(t) by the free model's plain state symbols."""
    return sp.sympify(expr).xreplace(free_state_substitution())


def free_kinematics() -> Kinematics:
    """Eqs 3.10-3.17 with r0 → r(t) and the frame angle ωt → ν(t)."""
    dx, dy, th = COORDINATES
    a, b = P["a"], P["b"]
    N = ReferenceFrame("N")
    L = N.orientnew("L", "Axis", [nu, N.z])  # angular velocity ν̇ ẑ
    O = Point("O")
    O.set_vel(N, 0)
    r = (
        b * sp.sin(th) * L.x + (r_ref + b * sp.cos(th)) * L.y,  # 3.10 tip-mass
        -a * sp.sin(th) * L.x + (r_ref - a * sp.cos(th)) * L.y,  # 3.11 main bus
        dx * L.x + (r_ref + dy) * L.y,  # 3.12 balloon
    )
    points, particles, vels = [], [], []
    for name, ri, m in zip(("P1", "P2", "P3"), r, (P["m1"], P["m2"], P["m3"])):
        pt = O.locatenew(name, ri)
        v = pt.pos_from(O).dt(N).express(L)
        pt.set_vel(N, v)
        points.append(pt)
        vels.append(v)
        particles.append(Particle(f"m_{name}", pt, m))
    tether_vectors = (r[0] - r[2], r[1] - r[2])
    defs = {lam: sp.sqrt(vec.dot(L.x) ** 2 + vec.dot(L.y) ** 2)  # 3.41-3.42
            for lam, vec in zip(TETHER_LENGTHS, tether_vectors)}
    return Kinematics(N, L, O, tuple(points), tuple(particles), r, tuple(vels),
                      tether_vectors, defs, speeds=FREE_SPEEDS)


def offset_ratio(kin: Kinematics, i: int, scale=1):
    """u_i = (2 r y_i + x_i² + y_i²)/r² with the offsets multiplied by ``scale``."""
    x = scale * kin.positions[i].dot(kin.L.x)
    y = scale * (kin.positions[i].dot(kin.L.y) - r_ref)
    return (2 * r_ref * y + x**2 + y**2) / r_ref**2


def _truncate_degree(expr, eps, degree: int):
    """Keep the terms of ``expr`` (a polynomial in eps) up to eps**degree, eps → 1."""
    # term by term (c eps^k → c): what Poly(expr, eps).terms() gives, without building a
    # polynomial ring over every other symbol of the expression (the 3-D free potential's
    # ~10^4 terms took most of that model's derivation)
    kept = []
    for term in sp.Add.make_args(sp.expand(expr)):
        c, k = term.as_coeff_exponent(eps)
        if k <= degree:
            kept.append(c)
    return sp.Add(*kept)


TRUNCATION_DEGREE = 3  # highest power of the offsets kept in V (= order 1/r0 in 3.28-3.30)


def inverse_powers_binomial(kin: Kinematics, i: int) -> tuple:
    """(1/|r_i|, 1/|r_i|³) truncated at third degree in the offsets.

    1/|r_i| is the thesis's three-term binomial (3.20-3.25), 1/|r_i|³ the
    Taylor series (1 + u)^(-3/2) ≈ 1 − 3u/2 + 15u²/8 − 35u³/16 (J2 term only).
    """
    eps = sp.Dummy("eps")
    u = offset_ratio(kin, i, eps)
    inv1 = (1 - u / 2 + sp.Rational(3, 8) * u**2) / r_ref
    inv3 = (1 - sp.Rational(3, 2) * u + sp.Rational(15, 8) * u**2
            - sp.Rational(35, 16) * u**3) / r_ref**3
    return tuple(_truncate_degree(e, eps, TRUNCATION_DEGREE) for e in (inv1, inv3))


def inverse_powers_exact(kin: Kinematics, i: int) -> tuple:
    """(1/|r_i|, 1/|r_i|³) = (H(u)/r, H(u)³/r³), no expansion."""
    h = InverseSqrt(offset_ratio(kin, i))
    return h / r_ref, h**3 / r_ref**3


def free_potential(kin: Kinematics, inverse_powers) -> sp.Expr:
    """V = −Σ μ m_i [1/|r_i| + J2 R_E²/(2 |r_i|³)] (Eq 3.19 plus equatorial J2), J."""
    V = sp.S.Zero
    for i, m in enumerate((P["m1"], P["m2"], P["m3"])):
        inv1, inv3 = inverse_powers(kin, i)
        V -= P["mu"] * m * (inv1 + J2 * R_E**2 / 2 * inv3)
    return V


def equations(defn, kin: Kinematics) -> Equations:
    """Lagrange's equations (3.26) of the 5-coordinate model (``defn.potential``: 1/|r_i|, 1/|r_i|³)."""
    T = kinetic_energy(kin)
    V = free_potential(kin, defn.potential)
    lm = LagrangesMethod(T - V, list(FREE_COORDINATES), frame=kin.N)
    lhs = tuple(sp.expand(to_free_symbols(e)) for e in lm.form_lagranges_equations())
    acc = FREE_ACCELERATION_SYMBOLS
    M = sp.Matrix(lhs).jacobian(acc).applyfunc(sp.expand)
    zero = {s: 0 for s in acc}
    f = tuple(sp.expand(e.xreplace(zero)) for e in lhs)
    return Equations(M, f, sp.expand(to_free_symbols(T)) + to_free_symbols(V), lhs)


def printable(expr):
    """H(u) → 1 + InverseSqrtMinusOne(u), the form codegen prints (expm1/log1p)."""
    return sp.sympify(expr).replace(InverseSqrt, lambda u: 1 + InverseSqrtMinusOne(u))


def circular_substitution() -> dict:
    """The thesis's prescribed orbit: r = r0, ṙ = r̈ = 0, ν̇ = ω, ν̈ = 0, μ = ω² r0³, J2 = 0."""
    s = {n: sp.Symbol(n, real=True) for n in ("r", "r_dot", "r_ddot", "nu_dot", "nu_ddot")}
    return {s["r_ddot"]: 0, s["nu_ddot"]: 0, s["r_dot"]: 0, s["nu_dot"]: P["omega"],
            s["r"]: P["r0"], P["mu"]: P["omega"] ** 2 * P["r0"] ** 3, J2: 0}
