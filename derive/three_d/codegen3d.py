"""The 3-D circular models' solve of M q̈ = Q − f (derive/emit.py prints the rest).

q̈ comes from M q̈ = Q − f: the balloon block is m3·1; the 3×3 attitude block
is solved numerically (Cramer's rule on the symmetric matrix, the helper
kernels :data:`SOLVERS` printed before ``rhs``).  Where the axial inertia
J_ax = I1_yaw + I2_yaw is zero (point masses: the boom has no inertia about
its own axis) the ψ row and column of M vanish, ψ is not a degree of freedom,
and the kernels solve the 2×2 (φ, θ) block and set ψ̈ = 0 (docs/three-d.md).
No ``jacobian``: the 3-D models' Jacobian is the central differences of rhs
(tethersim/engine/jacobian.py; the roll modes and the 3-D equilibrium use it).
Code names: :func:`prepare` (also used by the 3-D free-orbit models).
"""
from __future__ import annotations

import sympy as sp

from ..model import DerivedModel
from ..printer import INDENT, Printing, cse_block, forces_lines, kernel
from .symbols3d import N_Q, PARAMETERS, ROTATION, STATE_NAMES, STATE_SYMBOLS, TRANSLATION

_CODE_NAMES = {p.symbol: sp.Symbol(p.name, real=True) for p in PARAMETERS}
_ANGLES = STATE_SYMBOLS[3:6]
_TRIG = {}
for _a in _ANGLES:
    _TRIG[sp.sin(_a)] = sp.Symbol(f"sin_{_a}", real=True)
    _TRIG[sp.cos(_a)] = sp.Symbol(f"cos_{_a}", real=True)
_M = {(k, m): f"M{k}{m}" for k in ROTATION for m in ROTATION if m >= k}

SOLVERS = '''

@njit(cache=True, inline="always")
def _solve3(s00, s01, s02, s11, s12, s22, v0, v1, v2):
    """x of S x = v for the symmetric 3x3 S (Cramer's rule)."""
    c00 = s11 * s22 - s12 * s12
    c01 = s02 * s12 - s01 * s22
    c02 = s01 * s12 - s02 * s11
    det = s00 * c00 + s01 * c01 + s02 * c02
    c11 = s00 * s22 - s02 * s02
    c12 = s01 * s02 - s00 * s12
    c22 = s00 * s11 - s01 * s01
    return ((c00 * v0 + c01 * v1 + c02 * v2) / det,
            (c01 * v0 + c11 * v1 + c12 * v2) / det,
            (c02 * v0 + c12 * v1 + c22 * v2) / det)


@njit(cache=True, inline="always")
def _solve2(s00, s01, s11, v0, v1):
    """x of S x = v for the symmetric 2x2 S."""
    det = s00 * s11 - s01 * s01
    return (s11 * v0 - s01 * v1) / det, (s00 * v1 - s01 * v0) / det'''.splitlines()


def prepare(expr):
    """Code names for parameters; sin/cos of the three angles as named symbols."""
    return sp.sympify(expr).xreplace(_CODE_NAMES).xreplace(_TRIG)


def block(targets, exprs, prefix, indent, op="=", skip_zero=False):
    """cse a group of expressions; code lines assigning them to targets."""
    return cse_block(targets, [prepare(e) for e in exprs], prefix, indent, op, skip_zero)


def _mass_block(model: DerivedModel, indent) -> list:
    M = model.mass_matrix
    return block(list(_M.values()), [M[k, m] for k, m in _M], "mm", indent)


def _solve_lines(indent, targets, rhs, zero_axial) -> list:
    """Attitude solve: 3×3, or the (φ, θ) 2×2 with ψ̈ = 0 when J_ax = 0."""
    i2 = indent + INDENT
    args3 = ", ".join(_M[k] for k in _M)
    args2 = ", ".join(_M[k] for k in ((3, 3), (3, 4), (4, 4)))
    return [f"{indent}if {zero_axial}:",
            f"{i2}{targets[0]}, {targets[1]} = _solve2({args2}, {rhs[0]}, {rhs[1]})",
            f"{i2}{targets[2]} = 0.0",
            f"{indent}else:",
            f"{i2}{', '.join(targets)} = _solve3({args3}, {', '.join(rhs)})"]


ZERO_AXIAL = "I1_yaw + I2_yaw == 0.0"


def rhs_source(model: DerivedModel, pr: Printing) -> list:
    """``rhs(t, y, p, dydt)``: the summed forces, the balloon rows, the attitude solve."""
    i1 = INDENT
    head = ['@njit(cache=True, inline="always")', "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; layout in STATE)."""']
    out = []
    qn = [f"Q{k}" for k in range(N_Q)]
    out += forces_lines(pr, model.families, qn)
    out.append(f"{i1}# M q'' + f(q, q') = Q (Lagrange, 3.26-3.31 in 3-D)")
    out += [f"{i1}dydt[{k}] = {STATE_NAMES[k + N_Q]}" for k in range(N_Q)]
    rn = [f"R{k}" for k in ROTATION]
    out += block([f"dydt[{N_Q + k}]" for k in TRANSLATION] + rn,
                 [(sp.Symbol(qn[k]) - model.f[k]) / model.mass_matrix[k, k] for k in TRANSLATION]
                 + [sp.Symbol(qn[k]) - model.f[k] for k in ROTATION], "a", i1)
    out += _mass_block(model, i1)
    out += _solve_lines(i1, [f"dydt[{N_Q + k}]" for k in ROTATION], rn, ZERO_AXIAL)
    return kernel(head, pr.unpack, out)
