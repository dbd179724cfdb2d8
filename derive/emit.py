"""The one printer: a DerivedModel → the source of its generated/ module.

Every model, whatever its coordinates, is printed by :func:`module_source`
from the same pieces: the header (what it models, index tables, layout
constants), ``rhs``, ``family_forces``, ``jacobi`` and the geometry kernels
``tether_margins`` and ``body_radii`` (derive/printer.py, derive/geometry.py).
The one step that differs between coordinates is the solve of M q̈ = Q − f
inside ``rhs``, a :class:`Solve`:

* planar, circular orbit: q̈ in closed form (M is diagonal), plus the analytic
  ``jacobian`` the planar analyses use (derive/codegen.py);
* 3-D, circular orbit: balloon rows divided by m3, the attitude block by
  Cramer's rule (derive/three_d/codegen3d.py);
* free orbit (planar or 3-D): M full, an unrolled LDLᵀ (derive/orbit_codegen.py).

The rest of a :class:`Style` is data: code names (parameters, sin/cos of the
angles) and the header's lines.  Output is deterministic: orders come from
explicit tuples, cse symbols from fixed prefixes, and the header has no timestamp.
"""
from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from . import codegen, orbit_codegen
from .geometry import geometry_source
from .lanes import lanes_constants, lanes_source
from .orbit import printable
from .printer import (
    INDENT,
    NumbaPrinter,
    Printing,
    constant,
    cse_block,
    family_forces_source,
    index_tables,
    jacobi_source,
    paragraph,
    unpack_lines,
)
from .three_d import codegen3d
from .three_d.symbols3d import STATE_MEANINGS
from .trig import CALLED


@dataclass(frozen=True)
class Solve:
    """The per-coordinates step: q̈ from M q̈ = Q − f inside ``rhs``.

    ``rhs(model, pr)`` → lines of the rhs kernel; ``preamble``: helper kernels
    printed before it; ``extra(model, pr)`` → further kernels (lists of lines);
    ``lanes``: also print the rhs and family_forces on K points at once
    (derive/lanes.py), where the rhs's libm calls read only the state and parameters.
    """

    rhs: Callable
    preamble: tuple = ()
    extra: Callable = lambda model, pr: ()
    lanes: bool = False


@dataclass(frozen=True)
class Style:
    """How one set of coordinates is printed.

    Attributes
    ----------
    solve : Solve
    prepare : callable
        Expression → code names (parameters; sin/cos of the angles as symbols).
    angles : tuple of str
        Angles whose sine and cosine are unpacked as ``sin_<a>``, ``cos_<a>``.
    sources : tuple of str
        Header lines naming the derivation (``{sympy}``: sympy's version).
    geometry_line, orbit_line : str
        The module's ``GEOMETRY`` and ``ORBIT`` lines.
    force_units : str
        Units of the generalized forces (family_forces' docstring).
    geometry_note : str
        Where body_radii's positions come from.
    meanings : tuple or None
        A meaning per state entry for the header's table.
    skip_zero : bool
        Print no assignment of an exactly-zero force component.
    drag_note : str
        Appended to the drag block's comment.
    """

    solve: Solve
    prepare: Callable
    angles: tuple
    sources: tuple
    geometry_line: str
    orbit_line: str
    force_units: str
    geometry_note: str
    meanings: tuple | None = None
    skip_zero: bool = False
    drag_note: str = ""


_GEOMETRY = {"planar": 'GEOMETRY = "planar"  # (δx, δy, θ) in the orbit plane',
             "3d": 'GEOMETRY = "3d"  # roll, pitch, yaw and an out-of-plane balloon'}
_FREE_ORBIT = 'ORBIT = "free"  # r and ν are coordinates: gravity, J2 and drag move the orbit'
_FREE = Solve(orbit_codegen.rhs_source)

STYLES = {
    ("planar", "circular"): Style(
        Solve(codegen.rhs_source, extra=codegen.extra_kernels, lanes=True), codegen.prepare,
        ("theta",),
        ("Produced by `make derive` (python -m derive) from derive/; regenerate instead",
         "of editing.  sympy {sympy}."),
        'GEOMETRY = "planar"  # (δx, δy, θ): the thesis plane',
        'ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω (Eq 3.14)',
        "N, N, N m", " (Eqs 3.10-3.12)"),
    ("3d", "circular"): Style(
        Solve(codegen3d.rhs_source, preamble=codegen3d.SOLVERS), codegen3d.prepare,
        ("phi", "theta", "psi"),
        ("Produced by `make derive` (python -m derive) from derive/three_d/; regenerate",
         "instead of editing.  sympy {sympy}.  Conventions: docs/three-d.md."),
        _GEOMETRY["3d"], 'ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω',
        "N or N m", " (docs/three-d.md)", STATE_MEANINGS, skip_zero=True),
    ("planar", "free"): Style(
        _FREE, codegen.prepare, ("theta",),
        ("Produced by `make derive` (python -m derive) from derive/orbit.py and",
         "derive/orbit_codegen.py; regenerate instead of editing.  sympy {sympy}."),
        _GEOMETRY["planar"], _FREE_ORBIT, "N, N, N m, N, N m",
        " (Eqs 3.10-3.12 about the orbit radius r)", drag_note=", co-rotating air"),
    ("3d", "free"): Style(
        _FREE, codegen3d.prepare, ("phi", "theta", "psi"),
        ("Produced by `make derive` (python -m derive) from derive/three_d/free3d.py and",
         "derive/orbit_codegen.py; regenerate instead of editing.  docs/three-d.md, "
         "docs/orbit.md.  sympy {sympy}."),
        _GEOMETRY["3d"], _FREE_ORBIT, "N, N, N, N m, N m, N m, N, N m",
        " (docs/three-d.md, about the orbit radius r)", drag_note=", co-rotating air"),
}
JACOBI_DOC = {
    "circular": ("Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].", "",
                 f"{INDENT}Constant with drag and dampers off; otherwise dh/dt = power of drag "
                 "and dampers."),
    "free": ("Total energy T + V (orbit and attitude) plus taut-tether spring energy [J].", "",
             f"{INDENT}L = T − V has no explicit t, so this is the Jacobi integral: constant with drag",
             f"{INDENT}and dampers off, otherwise dE/dt = Σ_k (Q_drag + Q_damper)_k q̇_k."),
}


def style(model) -> Style:
    """The :class:`Style` of the model's coordinates."""
    return STYLES[(model.definition.geometry, model.definition.orbit)]


def printing(model) -> Printing:
    """The model's code names for derive/printer.py's kernels."""
    st, co = style(model), model.coordinates

    def block(targets, exprs, prefix, indent, op="="):
        return cse_block(targets, [st.prepare(printable(e)) for e in exprs], prefix, indent, op)

    def length_line(j, indent):
        lam = co.tether_lengths[j]
        return f"{indent}{lam} = {NumbaPrinter().doprint(st.prepare(model.length_defs[lam]))}"

    return Printing(unpack_lines(co.state_names, co.parameters, st.angles), block, length_line,
                    co.n_q, st.force_units, st.skip_zero, st.drag_note)


def header(model) -> list:
    """The module docstring (index tables), imports and layout constants."""
    st, co, d = style(model), model.coordinates, model.definition
    lines = ['"""GENERATED FILE - DO NOT EDIT.', "",
             *paragraph(f"Model {model.name!r}: {d.description}."),
             *(s.format(sympy=sp.__version__) for s in st.sources)]
    if d.circular:
        lines.append(f"Reduces to the model {d.circular!r} on a circular orbit.")
    lines += ["", *index_tables(co.state_names, co.state_units, co.parameters, st.meanings), '"""',
              "import math", "", "from numba import njit", "", f"MODEL = {model.name!r}",
              *constant("DESCRIPTION", d.description), st.geometry_line, st.orbit_line]
    families = constant("FAMILIES", tuple(f.name for f in model.families))
    tables = [*constant("STATE", co.state_names), *constant("STATE_UNITS", co.state_units),
              *constant("PARAMETERS", tuple(p.name for p in co.parameters)),
              *constant("PARAMETER_UNITS", tuple(p.unit for p in co.parameters))]
    if not d.circular:
        return lines + tables + families
    return (lines + [f"CIRCULAR_TWIN = {d.circular!r}  # the model this one reduces to on a "
                     "circular orbit", *families, *tables, ""]
            + [f"Y_{n.upper()} = {i}" for i, n in enumerate(co.state_names)] + [""]
            + [f"P_{p.name.upper()} = {i}" for i, p in enumerate(co.parameters)])


def geometry_kernels(model) -> list:
    """tether_margins and body_radii from the derived positions (derive/geometry.py)."""
    st, co = style(model), model.coordinates
    printer = NumbaPrinter()

    def comps(vec):
        return [printer.doprint(st.prepare(c)) for c in vec]

    rests = [p.name for p in co.parameters if p.name in ("l10", "l20")]
    return geometry_source(list(unpack_lines(co.state_names, co.parameters, st.angles)),
                           [comps(v) for v in model.tether_vectors], rests,
                           [comps(r) for r in model.positions], st.geometry_note)


def module_source(model) -> str:
    """Source text of one generated module."""
    st, pr = style(model), printing(model)
    rhs = st.solve.rhs(model, pr)
    forces = family_forces_source(pr, model.families)
    lines = header(model) + list(st.solve.preamble) + ["", ""] + rhs
    geometry = geometry_kernels(model)
    lanes = ([lanes_source(rhs), lanes_source(forces, "family_forces"),
              lanes_source(geometry, "tether_margins")] if st.solve.lanes else [])
    if lanes and lanes[0][0]:  # a lane rhs: the lanes' constants and every lane form
        lines += ["", ""] + lanes_constants(max(n for _, n in lanes))
        for src, _ in lanes:
            lines += ["", ""] + src if src else []
    lines += ["", ""] + forces
    lines += ["", ""] + jacobi_source(pr, model.families, model.energy,
                                      JACOBI_DOC[model.definition.orbit])
    for kernel_lines in st.solve.extra(model, pr):
        lines += ["", ""] + kernel_lines
    lines += ["", ""] + geometry
    return "\n".join(_trig_import(lines)) + "\n"


def _trig_import(lines: list) -> list:
    """``lines`` with ``from .trig import ...`` (the functions they call) after numba's import."""
    text = "\n".join(lines)
    used = sorted(f for f in CALLED if re.search(rf"(?<![\w.]){f}\(", text))
    if not used:
        return lines
    at = lines.index("from numba import njit") + 1
    return lines[:at] + ["", f"from .trig import {', '.join(used)}"] + lines[at:]
