"""One pipeline for every model: energies → Lagrange → truncation → solve.

A model is a :class:`ModelDefinition` (bodies, potential, truncation, force
families).  :func:`derive` turns it into a :class:`DerivedModel`, a frozen
record of plain sympy expressions in the state symbols, ready for codegen.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy as sp
from sympy.physics.mechanics import LagrangesMethod

from .energy import InverseSqrt, InverseSqrtMinusOne, kinetic_energy, potential_energy
from .kinematics import Kinematics
from .symbols import (
    ACCELERATION_SYMBOLS,
    COORDINATES,
    PARAMETERS,
    SPEEDS,
    STATE_SYMBOLS,
    TETHER_LENGTHS,
    P,
    state_substitution,
)


@dataclass(frozen=True)
class ModelDefinition:
    """What distinguishes one model variant from another.

    name: model name used by the runtime (``derived``, ``printed`` ...).
    kinematics: builds bodies and frames (a :class:`Kinematics`).
    inverse_distance: 1/|r_i| law for the gravity potential (Eq 3.19).
    truncation: highest power of 1/r0 kept in the Lagrange equations, or None.
    families: force families from the kinematics (or transcribed).
    lhs_override: Lagrange left-hand sides to use instead of the derived ones
      (only the printed model, to simulate exactly what the thesis printed).
    """

    name: str
    description: str
    kinematics: Callable[[], Kinematics]
    inverse_distance: Callable
    truncation: int | None
    families: Callable[[Kinematics], tuple]
    lhs_override: tuple | None = None


@dataclass(frozen=True)
class DerivedModel:
    """Equations of motion M q̈ + f(q, q̇) = Σ Q_family, in state symbols.

    ``lhs``: M q̈ + f, the Lagrange left-hand sides (after truncation).
    ``qdd``: q̈ as functions of the state and the summed forces Q_SYMBOLS.
    ``lhs_untruncated``: the same before truncation (for tests and docs).
    """

    definition: ModelDefinition
    lhs: tuple
    lhs_untruncated: tuple
    mass_matrix: sp.Matrix
    f: tuple
    families: tuple
    qdd: tuple
    jacobi: object

    @property
    def name(self) -> str:
        return self.definition.name


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


def jacobi_integral(kin: Kinematics, defn: ModelDefinition):
    """h = Σ q̇_k ∂L/∂q̇_k − L of the model's (truncated) Lagrangian [J].

    Truncation commutes with ∂/∂q (q does not involve r0), so the truncated
    equations derive from V truncated to the same order; h is then their
    exact first integral without drag and dampers.  Terms free of the state
    (such as −μ m/r0) are dropped: they are constants of size 1e9 J.
    """
    T = kinetic_energy(kin)
    V = potential_energy(kin, defn.inverse_distance)
    V = V.replace(InverseSqrt, lambda u: 1 + InverseSqrtMinusOne(u))
    h = sum(qd * sp.diff(T, qd) for qd in SPEEDS) - T
    h = sp.expand(to_state_symbols(h)) + sp.expand(to_state_symbols(V))
    if defn.truncation is not None:
        h = truncate_inverse_r0(h, defn.truncation)
    state = set(STATE_SYMBOLS)
    return sp.Add(*[term for term in sp.Add.make_args(sp.expand(h))
                    if term.free_symbols & state])


def derive(defn: ModelDefinition) -> DerivedModel:
    """Run the pipeline for one model definition."""
    kin = defn.kinematics()
    raw = lagrange_lhs(kin, defn.inverse_distance)
    if defn.lhs_override is not None:
        lhs = tuple(sp.expand(e) for e in defn.lhs_override)
    elif defn.truncation is not None:
        lhs = tuple(truncate_inverse_r0(e, defn.truncation) for e in raw)
    else:
        lhs = raw
    acc = sp.Matrix(ACCELERATION_SYMBOLS)
    lhs_m = sp.Matrix(lhs)
    M = sp.simplify(lhs_m.jacobian(acc))
    zero = {s: 0 for s in ACCELERATION_SYMBOLS}
    f = tuple(sp.expand(e.subs(zero)) for e in lhs)
    families = tuple(
        replace(fam, Q=tuple(to_state_symbols(q) for q in fam.Q),
                potential=None if fam.potential is None else to_state_symbols(fam.potential))
        for fam in defn.families(kin))
    qdd = M.LUsolve(sp.Matrix(Q_SYMBOLS) - sp.Matrix(f))
    qdd = tuple(sp.expand(sp.simplify(e)) for e in qdd)
    _check_symbols(defn.name, lhs + f + qdd + tuple(q for fam in families for q in fam.Q))
    jacobi = jacobi_integral(kin, defn)
    return DerivedModel(defn, lhs, raw, M, f, families, qdd, jacobi)


def _check_symbols(name: str, exprs) -> None:
    """Fail at generation time if an expression uses a symbol with no slot."""
    allowed = (set(STATE_SYMBOLS) | set(ACCELERATION_SYMBOLS) | set(Q_SYMBOLS)
               | {p.symbol for p in PARAMETERS} | set(TETHER_LENGTHS))
    for e in exprs:
        extra = sp.sympify(e).free_symbols - allowed
        if extra:
            raise ValueError(f"model {name!r}: symbols without a slot: {sorted(map(str, extra))}")
