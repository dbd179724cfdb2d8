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

import sympy as sp

from ..model import Equations
from ..pipeline import truncate_inverse_r0
from .energy3d import box_potential, exact_potential_for_jacobi, kinetic_energy, point_potential
from .kinematics3d import Kinematics3D, kinematics_3d
from .symbols3d import (
    N_Q,
    ROTATION,
    STATE_SYMBOLS,
    TRANSLATION,
    P,
    to_state_symbols,
)

Q_SYMBOLS = tuple(sp.Symbol(f"Q_{s}", real=True) for s in
                  ("delta_x", "delta_y", "delta_z", "phi", "theta", "psi"))


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


def potential(kin: Kinematics3D, power, truncation) -> tuple:
    """(V to expand, V not to expand) in state symbols, truncated at 1/r0**truncation."""
    Vp = to_state_symbols(point_potential(kin, power))
    Vb = to_state_symbols(box_potential(kin, power))
    if truncation is not None:
        return truncate_inverse_r0(Vp + Vb, truncation), sp.S.Zero
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
    V, V_boxes = potential(kin, power, truncation)
    M, f = lagrange_terms(T, V, V_boxes)
    M = M.applyfunc(lambda e: sp.factor_terms(sp.expand(sp.trigsimp(e))))
    _check_block_diagonal(M)
    return M, f, jacobi_integral(T, V, V_boxes, truncation)


def equations(defn, kin=None) -> Equations:
    """The Lagrange step of the 3-D circular models (``defn.potential`` gives |r_i|^(2n))."""
    return Equations(*_lagrange(defn.potential, defn.truncation))


def _check_block_diagonal(M) -> None:
    """M = diag(m3·1, attitude block) (the boom turns about a fixed point)."""
    for k in TRANSLATION:
        for m in range(N_Q):
            want = P["m3"] if k == m else 0
            if sp.simplify(M[k, m] - want) != 0 or sp.simplify(M[m, k] - want) != 0:
                raise ValueError(f"mass matrix not block diagonal at {k}, {m}")
    assert all(M[k, m] == M[m, k] for k in ROTATION for m in ROTATION)
