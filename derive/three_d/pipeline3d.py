"""Energies → Lagrange → truncation for the 3-D model.

The equations are M(q) q̈ + f(q, q̇) = Σ Q_family (Eqs 3.26-3.31), with

  M_kl = ∂²T/∂q̇_k∂q̇_l,
  f_k  = Σ_l ∂²T/∂q̇_k∂q_l q̇_l − ∂T/∂q_k + ∂V/∂q_k,

i.e. Lagrange's equations d/dt(∂L/∂q̇_k) − ∂L/∂q_k with the q̈ terms split off
(T has no explicit time dependence in the local frame).  M is block diagonal:
m3·1 for the balloon and a 3×3 attitude block, because the boom turns about the
fixed COM point (as in the planar model).  Unlike derive/pipeline.py, q̈ is not
solved symbolically: the generated kernels solve the 3×3 attitude block
numerically (derive/three_d/codegen3d.py), which keeps `make derive` fast.

Truncation: the thesis keeps terms up to O(1/r0) in the equations (Eqs
3.28-3.30).  Truncation commutes with ∂/∂q and d/dt (q carries no r0) and T
is a polynomial in r0, so truncating V first gives the same equations.
"""
from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy as sp

from ..pipeline import truncate_inverse_r0
from .energy3d import box_potential, exact_potential_for_jacobi, kinetic_energy, point_potential
from .kinematics3d import Kinematics3D, kinematics_3d
from .symbols3d import (
    ACCELERATION_SYMBOLS,
    N_Q,
    PARAMETERS,
    ROTATION,
    STATE_SYMBOLS,
    TETHER_LENGTHS,
    TRANSLATION,
    P,
    to_state_symbols,
)

Q_SYMBOLS = tuple(sp.Symbol(f"Q_{s}", real=True) for s in
                  ("delta_x", "delta_y", "delta_z", "phi", "theta", "psi"))


@dataclass(frozen=True)
class ModelDefinition3D:
    """One 3-D model variant.

    Attributes
    ----------
    name, description : str
        Model name (``3d`` ...) and one line for the generated header.
    power : callable
        ``power(kin, i, n)`` → |r_i|^(2n), binomial (thesis) or exact.
    truncation : int or None
        Highest power of 1/r0 kept in the equations, or None.
    families : callable
        Kinematics3D → tuple of ForceFamily in FAMILY_ORDER.
    """

    name: str
    description: str
    power: Callable
    truncation: int | None
    families: Callable


@dataclass(frozen=True)
class DerivedModel3D:
    """M q̈ + f = Σ Q in the plain state symbols (derive.three_d.symbols3d).

    Attributes
    ----------
    mass_matrix : sympy.Matrix
        6×6, depends on φ, ψ and the inertias only.
    f : tuple
        The six non-acceleration terms (Coriolis, centrifugal, gravity) [N, N m].
    families : tuple of ForceFamily
        Generalized forces (6 components each), λ1, λ2 as symbols.
    jacobi : sympy.Expr
        h = Σ q̇ ∂L/∂q̇ − L without state-free constants [J].
    length_defs : dict
        λ1, λ2 → 3-D tether lengths in the state symbols.
    """

    definition: ModelDefinition3D
    mass_matrix: sp.Matrix
    f: tuple
    families: tuple
    jacobi: object
    length_defs: dict

    @property
    def name(self) -> str:
        return self.definition.name


def _speed_symbols():
    return STATE_SYMBOLS[N_Q:]


def lagrange_terms(T, V, V_unexpanded=0, state=STATE_SYMBOLS) -> tuple:
    """(M, f) of M q̈ + f for T, V in the plain state symbols.

    Parameters
    ----------
    T, V : sympy.Expr
        Kinetic energy and the potential to expand with it [J].
    V_unexpanded : sympy.Expr, optional
        Potential terms differentiated but not expanded [J].
    state : tuple of sympy.Symbol, optional
        Coordinates then their rates (default the 3-D state; the free orbit's
        adds r, ν).

    Returns
    -------
    (sympy.Matrix, tuple)
        The n×n mass matrix and the n f_k [N or N m], n = len(state)/2.

    Notes
    -----
    The T and V parts of f are expanded together so that the O(r0) centrifugal
    and gravity terms cancel symbolically; ``V_unexpanded`` (exact-gravity box
    terms, O(ω² I) with no such cancellation) is differentiated but not expanded.
    """
    n = len(state) // 2
    q, qd = state[:n], state[n:]
    p = [sp.diff(T, s) for s in qd]
    M = sp.Matrix(n, n, lambda k, m: sp.diff(p[k], qd[m]))
    f = []
    for k in range(n):
        e = sum(sp.diff(p[k], q[m]) * qd[m] for m in range(n)) - sp.diff(T, q[k])
        f.append(sp.expand(e + sp.diff(V, q[k])) + sp.diff(V_unexpanded, q[k]))
    return M, tuple(f)


def potential(kin: Kinematics3D, defn: ModelDefinition3D) -> tuple:
    """(V to expand, V not to expand) in state symbols, truncated as the definition says."""
    Vp = to_state_symbols(point_potential(kin, defn.power))
    Vb = to_state_symbols(box_potential(kin, defn.power))
    if defn.truncation is not None:
        return truncate_inverse_r0(Vp + Vb, defn.truncation), sp.S.Zero
    return Vp, Vb


def jacobi_integral(T, V, V_boxes, truncation):
    """h = Σ q̇ ∂T/∂q̇ − T + V with state-free terms dropped [J]."""
    h = sum(s * sp.diff(T, s) for s in _speed_symbols()) - T
    h = sp.expand(h) + sp.expand(exact_potential_for_jacobi(V)) + V_boxes
    if truncation is not None:
        h = truncate_inverse_r0(h, truncation)
    state = set(STATE_SYMBOLS)
    return sp.Add(*[term for term in sp.Add.make_args(sp.expand(h)) if term.free_symbols & state])


@functools.cache
def _lagrange(power, truncation) -> tuple:
    """(M, f, jacobi) for one gravity law (shared by variants that differ in forces only)."""
    kin = kinematics_3d()
    T = to_state_symbols(kinetic_energy(kin))
    defn = ModelDefinition3D("", "", power, truncation, None)
    V, V_boxes = potential(kin, defn)
    M, f = lagrange_terms(T, V, V_boxes)
    M = M.applyfunc(lambda e: sp.factor_terms(sp.expand(sp.trigsimp(e))))
    _check_block_diagonal(M)
    return M, f, jacobi_integral(T, V, V_boxes, truncation)


def derive3d(defn: ModelDefinition3D) -> DerivedModel3D:
    """Run the 3-D pipeline for one definition.

    Parameters
    ----------
    defn : ModelDefinition3D
        Gravity law, truncation and force families of the variant.

    Returns
    -------
    DerivedModel3D
        M, f, families, Jacobi integral and tether lengths in the state symbols.
    """
    kin = kinematics_3d()
    M, f, jac = _lagrange(defn.power, defn.truncation)
    fams = tuple(replace(fam, Q=tuple(to_state_symbols(q) for q in fam.Q),
                         potential=None if fam.potential is None
                         else to_state_symbols(fam.potential))
                 for fam in defn.families(kin))
    defs = {lam: to_state_symbols(d) for lam, d in kin.tether_length_defs.items()}
    _check_symbols(defn.name, list(M) + list(f) + [q for fam in fams for q in fam.Q] + [jac])
    return DerivedModel3D(defn, M, f, fams, jac, defs)


def _check_block_diagonal(M) -> None:
    """M = diag(m3·1, attitude block) (the boom turns about a fixed point)."""
    for k in TRANSLATION:
        for m in range(N_Q):
            want = P["m3"] if k == m else 0
            if sp.simplify(M[k, m] - want) != 0 or sp.simplify(M[m, k] - want) != 0:
                raise ValueError(f"mass matrix not block diagonal at {k}, {m}")
    assert all(M[k, m] == M[m, k] for k in ROTATION for m in ROTATION)


def _check_symbols(name: str, exprs) -> None:
    """Fail at generation time if an expression uses a symbol with no slot."""
    allowed = (set(STATE_SYMBOLS) | set(ACCELERATION_SYMBOLS) | set(Q_SYMBOLS)
               | {p.symbol for p in PARAMETERS} | set(TETHER_LENGTHS))
    for e in exprs:
        extra = sp.sympify(e).free_symbols - allowed
        if extra:
            raise ValueError(f"model {name!r}: symbols without a slot: {sorted(map(str, extra))}")
