"""The Lagrange step of the planar circular models: energies → Lagrange → truncation.

derive.model.derive calls :func:`equations` for every model on the planar
circular coordinates (derive/coordinates.py); the truncation in 1/r0 and the
Jacobi integral of the truncated Lagrangian are defined here.
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import LagrangesMethod

from .energy import InverseSqrt, InverseSqrtMinusOne, kinetic_energy, potential_energy
from .kinematics import Kinematics
from .model import Equations
from .symbols import (
    ACCELERATION_SYMBOLS,
    COORDINATES,
    SPEEDS,
    STATE_SYMBOLS,
    P,
    state_substitution,
)

Q_SYMBOLS = tuple(sp.Symbol(f"Q_{n}", real=True) for n in ("delta_x", "delta_y", "theta"))


def to_state_symbols(expr):
    """Replace q(t), q̇(t), q̈(t) by plain symbols (highest derivatives first)."""
    return sp.sympify(expr).xreplace(state_substitution())


def lagrange_lhs(kin: Kinematics, inverse_distance) -> tuple:
    """d/dt(∂L/∂q̇_k) − ∂L/∂q_k with L = T − V (Eqs 3.26-3.27), no forces."""
    L = kinetic_energy(kin) - potential_energy(kin, inverse_distance)
    lm = LagrangesMethod(L, list(COORDINATES), frame=kin.N)
    eom = lm.form_lagranges_equations()
    return tuple(sp.expand(to_state_symbols(e)) for e in eom)


def truncate_inverse_r0(expr, order: int):
    """Drop every term of order (1/r0)^(order+1) and beyond.

    With μ = ω² r0³ the binomial-expanded Lagrange equations are a Laurent
    polynomial in r0: an O(r0) centrifugal-gravity balance that cancels, the
    Hill terms O(1), corrections O(1/r0) and remainders O(1/r0²).  The thesis's
    printed left-hand sides 3.28-3.30 are exactly the terms up to O(1/r0)
    (order=1); this step reproduces them.  Caveat (docs/errata.md, N2): the
    three-term binomial is itself incomplete at O(1/r0) in the δy and θ
    equations (the exact potential gives +3 m3 ω² δy²/r0 where 3.29 has
    −9/2), so those kept 1/r0 terms are not the true gravity terms; the
    exact-gravity model has them right.  They are ~1e-5 of the Hill terms.
    """
    eps = sp.Dummy("eps", positive=True)
    e = sp.expand(sp.sympify(expr).subs(P["r0"], 1 / eps))
    kept = sp.S.Zero
    for term in sp.Add.make_args(e):
        coeff, power = term.as_coeff_exponent(eps)
        if power <= order:
            kept += term
    return sp.expand(kept.subs(eps, 1 / P["r0"]))


def jacobi_integral(kin: Kinematics, defn):
    """h = Σ q̇_k ∂L/∂q̇_k − L of the model's (truncated) Lagrangian [J].

    Truncation commutes with ∂/∂q (q does not involve r0), so the truncated
    equations derive from V truncated to the same order; h is then their
    exact first integral without drag and dampers.  Terms free of the state
    (such as −μ m/r0) are dropped: they are constants of size 1e9 J.
    """
    T = kinetic_energy(kin)
    V = potential_energy(kin, defn.potential)
    V = V.replace(InverseSqrt, lambda u: 1 + InverseSqrtMinusOne(u))
    h = sum(qd * sp.diff(T, qd) for qd in SPEEDS) - T
    h = sp.expand(to_state_symbols(h)) + sp.expand(to_state_symbols(V))
    if defn.truncation is not None:
        h = truncate_inverse_r0(h, defn.truncation)
    state = set(STATE_SYMBOLS)
    return sp.Add(*[term for term in sp.Add.make_args(sp.expand(h))
                    if term.free_symbols & state])


def equations(defn, kin: Kinematics) -> Equations:
    """The Lagrange step of the planar circular models (Eqs 3.26-3.30).

    The left-hand sides are truncated in 1/r0 (or replaced by the printed
    ones, ``defn.lhs_override``); M is diagonal, so derive.model.derive solves
    q̈ in closed form.
    """
    raw = lagrange_lhs(kin, defn.potential)
    if defn.lhs_override is not None:
        lhs = tuple(sp.expand(e) for e in defn.lhs_override)
    elif defn.truncation is not None:
        lhs = tuple(truncate_inverse_r0(e, defn.truncation) for e in raw)
    else:
        lhs = raw
    M = sp.simplify(sp.Matrix(lhs).jacobian(sp.Matrix(ACCELERATION_SYMBOLS)))
    zero = {s: 0 for s in ACCELERATION_SYMBOLS}
    f = tuple(sp.expand(e.subs(zero)) for e in lhs)
    return Equations(M, f, jacobi_integral(kin, defn), lhs, raw)
