"""Print a DerivedModel3D as a numba module (cse'd straight-line code).

Kernels, with the planar signatures (derive/codegen.py) and 12-entry states:

``rhs(t, y, p, dydt)``        state derivative
``family_forces(y, p, out)``  out[f, k]: generalized force of family f on q_k, out (7, 6)
``jacobi(y, p)``              Jacobi integral + taut-tether spring energy [J]

No ``jacobian``: the 3-D models' Jacobian is the central differences of rhs
(tethersim/engine/jacobian.py; the roll modes and the 3-D equilibrium use it).

q̈ comes from M q̈ = Q − f: the balloon block is m3·1; the 3×3 attitude block
is solved numerically (Cramer's rule on the symmetric matrix).  Where the
axial inertia J_ax = I1_yaw + I2_yaw is zero (point masses: the boom has no
inertia about its own axis) the ψ row and column of M vanish, ψ is not a
degree of freedom, and the kernels solve the 2×2 (φ, θ) block and set ψ̈ = 0
(docs/three-d.md).  Output is deterministic (explicit orders, fixed cse prefixes).
"""
from __future__ import annotations

import sympy as sp

from ..printer import (
    INDENT,
    NumbaPrinter,
    Printing,
    constant,
    cse_block,
    family_forces_source,
    forces_lines,
    index_tables,
    jacobi_source,
    kernel,
    paragraph,
    unpack_lines,
)
from .forces3d import FAMILY_ORDER
from .pipeline3d import DerivedModel3D
from .symbols3d import (
    N_Q,
    PARAMETERS,
    ROTATION,
    STATE_MEANINGS,
    STATE_NAMES,
    STATE_SYMBOLS,
    STATE_UNITS,
    TETHER_LENGTHS,
    TETHER_REST,
    TRANSLATION,
)

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


UNPACK = unpack_lines(STATE_NAMES, PARAMETERS, ("phi", "theta", "psi"))
JACOBI_DOC = ("Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].", "",
              f"{INDENT}Constant with drag and dampers off; otherwise dh/dt = power of drag and dampers.")


def printing(model: DerivedModel3D) -> Printing:
    """The 3-D models' code names; exactly-zero force components are not printed."""
    return Printing(UNPACK, block, lambda j, indent: _length_line(model, j, indent), N_Q,
                    "N or N m", skip_zero=True)


def _length_line(model: DerivedModel3D, j: int, indent: str) -> str:
    lam = TETHER_LENGTHS[j]
    return f"{indent}{lam} = {NumbaPrinter().doprint(prepare(model.length_defs[lam]))}"


def _mass_block(model: DerivedModel3D, indent) -> list:
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


def rhs_source(model: DerivedModel3D) -> list:
    i1 = INDENT
    head = ['@njit(cache=True, inline="always")', "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; layout in STATE)."""']
    out = []
    qn = [f"Q{k}" for k in range(N_Q)]
    out += forces_lines(printing(model), model.families, qn)
    out.append(f"{i1}# M q'' + f(q, q') = Q (Lagrange, 3.26-3.31 in 3-D)")
    out += [f"{i1}dydt[{k}] = {STATE_NAMES[k + N_Q]}" for k in range(N_Q)]
    rn = [f"R{k}" for k in ROTATION]
    out += block([f"dydt[{N_Q + k}]" for k in TRANSLATION] + rn,
                 [(sp.Symbol(qn[k]) - model.f[k]) / model.mass_matrix[k, k] for k in TRANSLATION]
                 + [sp.Symbol(qn[k]) - model.f[k] for k in ROTATION], "a", i1)
    out += _mass_block(model, i1)
    out += _solve_lines(i1, [f"dydt[{N_Q + k}]" for k in ROTATION], rn, ZERO_AXIAL)
    return kernel(head, UNPACK, out)


def layout_constants() -> list:
    """STATE, PARAMETERS ... tuples (the same in every 3-D module and layout3d)."""
    return [*constant("STATE", STATE_NAMES), *constant("STATE_UNITS", STATE_UNITS),
            *constant("PARAMETERS", tuple(p.name for p in PARAMETERS)),
            *constant("PARAMETER_UNITS", tuple(p.unit for p in PARAMETERS)),
            *constant("FAMILIES", FAMILY_ORDER)]


def geometry_lines() -> list:
    """tether_margins and body_radii of the 3-D models (positions in the local frame L)."""
    from ..geometry import geometry_source
    from .kinematics3d import kinematics_3d
    from .symbols3d import state_substitution

    kin = kinematics_3d()
    sub = state_substitution()
    printer = NumbaPrinter()

    def comps(vec):
        return [printer.doprint(prepare(sp.sympify(c).subs(sub))) for c in kin.components(vec)]

    return geometry_source(list(UNPACK), [comps(v) for v in kin.tether_vectors],
                           [str(_CODE_NAMES[r]) for r in TETHER_REST],
                           [comps(r) for r in kin.positions], " (docs/three-d.md)")


def module_source(model: DerivedModel3D, geometry=()) -> str:
    """Source text of one generated 3-D module.

    Parameters
    ----------
    model : DerivedModel3D
        The derived model.

    Returns
    -------
    str
        Header (index tables, layout tuples), solvers, the three kernels and the
        geometry kernels (``geometry``: tether_margins, body_radii).
    """
    head = ['"""GENERATED FILE - DO NOT EDIT.', "",
            *paragraph(f"Model {model.name!r}: {model.definition.description}."),
            "Produced by `make derive` (python -m derive) from derive/three_d/; regenerate",
            f"instead of editing.  sympy {sp.__version__}.  Conventions: docs/three-d.md.", "",
            *index_tables(STATE_NAMES, STATE_UNITS, PARAMETERS, STATE_MEANINGS), '"""',
            "import math", "", "from numba import njit", "",
            f"MODEL = {model.name!r}", *constant("DESCRIPTION", model.definition.description),
            'GEOMETRY = "3d"  # roll, pitch, yaw and an out-of-plane balloon',
            'ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω',
            *layout_constants()]
    assert tuple(f.name for f in model.families) == FAMILY_ORDER
    lines = head + SOLVERS + ["", ""] + rhs_source(model)
    pr = printing(model)
    lines += ["", ""] + family_forces_source(pr, model.families)
    lines += ["", ""] + jacobi_source(pr, model.families, model.jacobi, JACOBI_DOC)
    if geometry:
        lines += ["", ""] + list(geometry)
    return "\n".join(lines) + "\n"
