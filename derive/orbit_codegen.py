"""Print a FreeDerivedModel as a numba module (the free-orbit kernels).

Same kernel signatures as the planar modules (derive/codegen.py), on the
free state of the model's layout (:class:`FreeLayout`): 10 floats for the
planar free models (derive/orbit.py FREE_STATE_NAMES), 16 for the 3-D ones
(derive/three_d/free3d.py, layout in derive/three_d/free3d_codegen.py):

``rhs(t, y, p, dydt)``         state derivative (q̇, q̈), q = (offsets, angles, r, ν)
``family_forces(y, p, out)``   out[f, k]: generalized force of family f on q_k
``jacobi(y, p)``               total energy T + V + taut-tether spring energy [J]

The mass matrix couples the orbit (r, ν) with the offsets, so q̈ is not
printed in closed form: the kernel evaluates M (symmetric positive definite,
it is the kinetic energy's Hessian) and the right-hand side Q − f, and solves
with an unrolled LDLᵀ elimination without pivoting (stable for SPD matrices
and invariant to the very different scales of the ν and δ rows).  No
``jacobian`` is printed: the free models use theirs only for the RK4 step
warning, and get it by central differences of rhs (tethersim/engine/jacobian.py).
A layout with an ``axial`` coordinate
(3-D: ψ) replaces its row and column by the identity when the axial inertia
is zero (ψ is then no degree of freedom: ψ̈ = 0, docs/three-d.md).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from .codegen import _block, _prepare
from .orbit import (
    FREE_ACCELERATION_SYMBOLS,
    FREE_PARAMETERS,
    FREE_Q_SYMBOLS,
    FREE_STATE_NAMES,
    FREE_STATE_SYMBOLS,
    FREE_STATE_UNITS,
    FreeDerivedModel,
    printable,
)
from .printer import (
    INDENT,
    NumbaPrinter,
    Printing,
    constant,
    family_forces_source,
    forces_lines,
    index_tables,
    jacobi_source,
    kernel,
    paragraph,
    unpack_lines,
)
from .symbols import TETHER_LENGTHS


@dataclass(frozen=True)
class FreeLayout:
    """What the printer needs to know of a free model's state and printing.

    Attributes
    ----------
    state_names, state_units, state_symbols : tuple
        The state y (coordinates, then rates).
    acceleration_symbols, q_symbols : tuple
        q̈ and the summed generalized forces Q, one per coordinate.
    parameters : tuple of Parameter
        The parameter vector p.
    block : callable
        ``block(targets, exprs, prefix, indent, op)``: cse'd assignment lines.
    prepare : callable
        Code names for parameters and named sin/cos of the angles.
    angles : tuple of str
        Angles whose sine and cosine are unpacked as ``sin_<a>``, ``cos_<a>``.
    geometry : str
        The module's ``GEOMETRY`` line.
    sources : tuple of str
        Header lines naming the derivation's modules.
    axial : tuple or None
        (index of ψ in q, condition on p that the axial inertia is zero).
    force_units : str
        Units of the generalized forces (family_forces' docstring).
    """

    state_names: tuple
    state_units: tuple
    state_symbols: tuple
    acceleration_symbols: tuple
    q_symbols: tuple
    parameters: tuple
    block: Callable
    prepare: Callable
    angles: tuple
    geometry: str
    sources: tuple
    axial: tuple | None = None
    force_units: str = "N, N, N m, N, N m"

    @property
    def n_q(self) -> int:
        return len(self.acceleration_symbols)


PLANAR = FreeLayout(FREE_STATE_NAMES, FREE_STATE_UNITS, FREE_STATE_SYMBOLS,
                    FREE_ACCELERATION_SYMBOLS, FREE_Q_SYMBOLS, FREE_PARAMETERS, _block, _prepare,
                    ("theta",), 'GEOMETRY = "planar"  # (δx, δy, θ) in the orbit plane',
                    ("Produced by `make derive` (python -m derive) from derive/orbit.py and",
                     "derive/orbit_codegen.py; regenerate instead of editing."))
JACOBI_DOC = ("Total energy T + V (orbit and attitude) plus taut-tether spring energy [J].", "",
              f"{INDENT}L = T − V has no explicit t, so this is the Jacobi integral: constant with drag",
              f"{INDENT}and dampers off, otherwise dE/dt = Σ_k (Q_drag + Q_damper)_k q̇_k.")


def _x(lay):
    return tuple(sp.Symbol(f"X{k}", real=True) for k in range(lay.n_q))  # q̈ inside the kernels


def printing(lay, length_defs) -> Printing:
    """The layout's code names, with H(u) printed through expm1/log1p (derive/printer.py)."""
    return Printing(unpack_lines(lay.state_names, lay.parameters, lay.angles),
                    lambda targets, exprs, prefix, indent, op="=": _pblock(lay, targets, exprs,
                                                                           prefix, indent, op),
                    lambda j, indent: _tether_length_line(lay, j, indent, length_defs),
                    lay.n_q, lay.force_units, drag_note=", co-rotating air")


def _pblock(lay, targets, exprs, prefix, indent, op="="):
    return lay.block(targets, [printable(e) for e in exprs], prefix, indent, op)


def _tether_length_line(lay, j: int, indent: str, defs) -> str:
    lam = TETHER_LENGTHS[j]
    return f"{indent}{lam} = {NumbaPrinter().doprint(lay.prepare(defs[lam]))}"


def _mass_matrix_lines(lay, model, indent) -> list:
    """M{i}_{j} (upper triangle) of the Lagrange equations (3.26)."""
    n = lay.n_q
    ij = [(i, j) for i in range(n) for j in range(i, n)]
    return _pblock(lay, [f"M{i}_{j}" for i, j in ij], [model.mass_matrix[i, j] for i, j in ij],
                   "mm", indent)


def _axial_lines(lay, indent, rows) -> list:
    """Zero axial inertia: ψ's row and column of M → identity, its right-hand sides ``rows`` → 0."""
    if lay.axial is None:
        return []
    k, condition = lay.axial
    i2 = indent + INDENT
    out = [f"{indent}if {condition}:  # no inertia about the boom: psi'' = 0 (docs/three-d.md)"]
    out += [f"{i2}M{min(i, k)}_{max(i, k)} = 0.0" for i in range(lay.n_q) if i != k]
    out += [f"{i2}M{k}_{k} = 1.0"] + [f"{i2}{r} = 0.0" for r in rows]
    return out


def _factor_lines(lay, indent) -> list:
    """In-place LDLᵀ of the upper triangle: L{i}_{k} multipliers, M{i}_{j} → U."""
    n, out = lay.n_q, []
    for k in range(n):
        for i in range(k + 1, n):
            out.append(f"{indent}L{i}_{k} = M{k}_{i} / M{k}_{k}")
            out += [f"{indent}M{i}_{j} -= L{i}_{k} * M{k}_{j}" for j in range(i, n)]
    return out


def _solve_lines(lay, b, x, indent) -> list:
    """Forward elimination of the names ``b`` (in place), back substitution into ``x``."""
    n = lay.n_q
    out = [f"{indent}{b[i]} -= L{i}_{k} * {b[k]}" for k in range(n) for i in range(k + 1, n)]
    for i in reversed(range(n)):
        tail = "".join(f" - M{i}_{j} * {x[j]}" for j in range(i + 1, n))
        out.append(f"{indent}{x[i]} = ({b[i]}{tail}) / M{i}_{i}")
    return out


def _accelerations(lay, model, length_defs) -> list:
    """Lines leaving q̈ in X0..X{n-1}: forces, M, factorisation, solve of M q̈ = Q − f."""
    i1, n = INDENT, lay.n_q
    qn = [str(q) for q in lay.q_symbols]
    out = forces_lines(printing(lay, length_defs), model.families, qn)
    out.append(f"{i1}# M q'' = Q - f (Lagrange, Eq 3.26 with r, nu as coordinates)")
    out += _pblock(lay, [f"B{k}" for k in range(n)],
                   [lay.q_symbols[k] - model.f[k] for k in range(n)], "fb", i1)
    out += _mass_matrix_lines(lay, model, i1)
    out += _axial_lines(lay, i1, [f"B{lay.axial[0]}"] if lay.axial else [])
    out += _factor_lines(lay, i1)
    out += _solve_lines(lay, [f"B{k}" for k in range(n)], [str(x) for x in _x(lay)], i1)
    return out


def rhs_source(lay, model: FreeDerivedModel, length_defs) -> list:
    i1, n = INDENT, lay.n_q
    head = ["@njit(cache=True)", "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; y, p as in STATE, PARAMETERS)."""']
    out = _accelerations(lay, model, length_defs)
    out += [f"{i1}dydt[{k}] = {lay.state_names[k + n]}" for k in range(n)]
    out += [f"{i1}dydt[{k + n}] = X{k}" for k in range(n)]
    return kernel(head, printing(lay, length_defs).unpack, out)


def _layout_constants(lay) -> list:
    return [*constant("STATE", lay.state_names), *constant("STATE_UNITS", lay.state_units),
            *constant("PARAMETERS", tuple(p.name for p in lay.parameters)),
            *constant("PARAMETER_UNITS", tuple(p.unit for p in lay.parameters)), "",
            *(f"Y_{n.upper()} = {i}" for i, n in enumerate(lay.state_names)), "",
            *(f"P_{p.name.upper()} = {i}" for i, p in enumerate(lay.parameters))]


def module_source(model: FreeDerivedModel, length_defs, geometry=(), lay: FreeLayout = PLANAR) -> str:
    """Source text of one free-orbit module (kernels, layout, ``CIRCULAR_TWIN``)."""
    twin = model.definition.circular
    lines = ['"""GENERATED FILE - DO NOT EDIT.', "",
             *paragraph(f"Model {model.name!r}: {model.definition.description}."),
             *lay.sources[:-1], f"{lay.sources[-1]}  sympy {sp.__version__}.",
             f"Reduces to the model {twin!r} on a circular orbit.", "",
             *index_tables(lay.state_names, lay.state_units, lay.parameters), '"""',
             "import math", "", "from numba import njit", "",
             f"MODEL = {model.name!r}",
             *constant("DESCRIPTION", model.definition.description),
             lay.geometry,
             'ORBIT = "free"  # r and ν are coordinates: gravity, J2 and drag move the orbit',
             f"CIRCULAR_TWIN = {twin!r}  # the model this one reduces to on a circular orbit",
             f"FAMILIES = {tuple(f.name for f in model.families)!r}",
             *_layout_constants(lay)]
    pr = printing(lay, length_defs)
    lines += ["", ""] + rhs_source(lay, model, length_defs)
    lines += ["", ""] + family_forces_source(pr, model.families)
    lines += ["", ""] + jacobi_source(pr, model.families, model.energy, JACOBI_DOC)
    if geometry:
        lines += ["", ""] + list(geometry)
    return "\n".join(lines) + "\n"


def geometry_lines(kin, sub, lay: FreeLayout = PLANAR, axes=None, note=None) -> list:
    """tether_margins and body_radii on the free state (positions about r, Eqs 3.10-3.12)."""
    from .codegen import _CODE_NAMES
    from .geometry import geometry_source
    from .symbols import TETHER_REST

    printer = NumbaPrinter()
    axes = (kin.L.x, kin.L.y) if axes is None else axes

    def comps(vec):
        return [printer.doprint(lay.prepare(vec.dot(axis).subs(sub))) for axis in axes]

    unpack = list(unpack_lines(lay.state_names, lay.parameters, lay.angles))
    return geometry_source(unpack, [comps(v) for v in kin.tether_vectors],
                           [_CODE_NAMES[r].name for r in TETHER_REST], [comps(r) for r in kin.positions],
                           note or " (Eqs 3.10-3.12 about the orbit radius r)")


def write_free_models(out) -> list:
    """Derive every free-orbit model and write its module into ``out``; the file names."""
    from .orbit import FREE_DEFINITIONS, derive_free, free_kinematics, free_state_substitution

    sub = free_state_substitution()
    kin = free_kinematics()
    length_defs = {lam: d.subs(sub) for lam, d in kin.tether_length_defs.items()}
    geometry = geometry_lines(kin, sub)
    written = []
    for defn in FREE_DEFINITIONS:
        fname = defn.name.replace("-", "_") + ".py"
        (out / fname).write_text(module_source(derive_free(defn), length_defs, geometry))
        written.append(fname)
    return written
