"""Print a DerivedModel (planar, circular orbit) as a numba module: the symbolic solve.

The shared parts come from derive/printer.py; here: q̈ in closed form (M is
diagonal) and the analytic Jacobian.  Each generated module holds these kernels
with plain float-array signatures:

``rhs(t, y, p, dydt)``            state derivative (δẋ, δẏ, θ̇, δẍ, δÿ, θ̈)
``family_forces(y, p, out)``      out[f, k]: generalized force of family f on q_k
``jacobi(y, p)``                  Jacobi integral + spring energy [J]
``jacobian(t, y, p, J)``          ∂(dy/dt)/∂y, 6x6

and, beside them, ``generated/layout.py`` holds the index tables shared by all
models.  Output is deterministic: orders come from explicit tuples, cse
symbols from fixed prefixes, and the header has no timestamp.
"""
from __future__ import annotations

import sympy as sp

from .geometry import geometry_source
from .lanes import lanes_source
from .pipeline import Q_SYMBOLS, DerivedModel
from .printer import (
    INDENT,
    NumbaPrinter,
    Printing,
    constant,
    cse_block,
    family_forces_source,
    forces_lines,
    gate,
    index_tables,
    jacobi_source,
    kernel,
    paragraph,
    unpack_lines,
)
from .symbols import (
    PARAMETERS,
    STATE_NAMES,
    STATE_SYMBOLS,
    STATE_UNITS,
    TETHER_LENGTHS,
    TETHER_REST,
    state_substitution,
)

_SIN, _COS = sp.Symbol("sin_theta", real=True), sp.Symbol("cos_theta", real=True)
_CODE_NAMES = {p.symbol: sp.Symbol(p.name, positive=True) for p in PARAMETERS}


def _prepare(expr):
    """Code names for parameters, named sin θ / cos θ."""
    th = STATE_SYMBOLS[2]
    e = sp.sympify(expr).xreplace(_CODE_NAMES)
    return e.xreplace({sp.sin(th): _SIN, sp.cos(th): _COS})


def _block(targets, exprs, prefix, indent, op="="):
    """cse a group of expressions; return code lines assigning them to targets."""
    return cse_block(targets, [_prepare(e) for e in exprs], prefix, indent, op)


UNPACK = unpack_lines(STATE_NAMES, PARAMETERS, ("theta",))
JACOBI_DOC = ("Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].", "",
              f"{INDENT}Constant with drag and dampers off; otherwise dh/dt = power of drag and dampers.")


def _tether_length_line(j: int, indent: str, defs) -> str:
    lam = TETHER_LENGTHS[j]
    return f"{indent}{lam} = {NumbaPrinter().doprint(_prepare(defs[lam]))}"


def printing(length_defs) -> Printing:
    """The planar circular models' code names (derive/printer.py)."""
    return Printing(UNPACK, _block, lambda j, indent: _tether_length_line(j, indent, length_defs),
                    3, "N, N, N m")


def _sum_families(model: DerivedModel, tether):
    fams = [f for f in model.families if f.tether == tether]
    return tuple(sum(f.Q[k] for f in fams) for k in range(3)), fams


def rhs_source(model: DerivedModel, length_defs) -> list:
    i1 = INDENT
    head = ["@njit(cache=True, inline=\"always\")", "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; layout in generated/layout.py)."""']
    out = forces_lines(printing(length_defs), model.families, [str(q) for q in Q_SYMBOLS])
    acc = [_prepare(e) for e in model.qdd]
    out.append(f"{i1}# accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)")
    out += [f"{i1}dydt[{k}] = {STATE_NAMES[k + 3]}" for k in range(3)]
    out += _block([f"dydt[{k + 3}]" for k in range(3)], acc, "a", i1)
    return kernel(head, UNPACK, out)


def _d_dy(exprs, length_defs):
    """Rows of ∂expr/∂y (6 columns), with λ_j differentiated through Eqs 3.41-3.42.

    The result is written back in terms of the λ symbols so the generated code
    reuses the tether lengths computed for the taut/slack gate.
    """
    y = STATE_SYMBOLS
    back = {v: k for k, v in length_defs.items()}
    rows = []
    for e in exprs:
        full = sp.sympify(e).xreplace(length_defs)
        rows.append([sp.sympify(full.diff(s)).xreplace(back) for s in y])
    return rows


def jacobian_source(model: DerivedModel, length_defs) -> list:
    """J = ∂(dy/dt)/∂y (6x6), taut/slack branches as in rhs.

    q̈ = M⁻¹(Q − f) is linear in Q, so ∂q̈/∂y = ∂q̈/∂y|_Q + Σ_k ∂q̈/∂Q_k ∂Q_k/∂y;
    the ∂Q/∂y of each family block is accumulated inside its gate.
    """
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True)", "def jacobian(t, y, p, J):",
            f'{i1}"""J[i, j] = ∂(dy_i/dt)/∂y_j of model {model.name!r} (units of y_i/s per y_j)."""']
    out = []
    dq = [[f"dQ{k}_{j}" for j in range(6)] for k in range(3)]
    drag, _ = _sum_families(model, None)
    rows = _d_dy(drag, length_defs)
    out += _block([dq[k][j] for k in range(3) for j in range(6)],
                  [rows[k][j] for k in range(3) for j in range(6)], "jd", i1)
    for j in range(2):
        tq, _ = _sum_families(model, j + 1)
        rows = _d_dy(tq, length_defs)
        out.append(_tether_length_line(j, i1, length_defs))
        out.append(f"{i1}if {gate(j)}:")
        out += _block([dq[k][c] for k in range(3) for c in range(6)],
                      [rows[k][c] for k in range(3) for c in range(6)], f"jt{j + 1}_", i2, op="+=")
    out.append(f"{i1}J[:, :] = 0.0")
    out += [f"{i1}J[{k}, {k + 3}] = 1.0" for k in range(3)]
    exprs, targets = [], []
    qsyms = sp.symbols("dQ0_0:6 dQ1_0:6 dQ2_0:6", real=True)
    for k, acc in enumerate(model.qdd):
        for c, ys in enumerate(STATE_SYMBOLS):
            e = sp.diff(acc, ys) + sum(sp.diff(acc, Q_SYMBOLS[m]) * qsyms[6 * m + c]
                                       for m in range(3))
            exprs.append(e)
            targets.append(f"J[{k + 3}, {c}]")
    out += _block(targets, exprs, "ja", i1)
    return kernel(head, UNPACK, out)


def header(model: DerivedModel) -> list:
    return [
        '"""GENERATED FILE - DO NOT EDIT.',
        "",
        *paragraph(f"Model {model.name!r}: {model.definition.description}."),
        "Produced by `make derive` (python -m derive) from derive/; regenerate instead",
        f"of editing.  sympy {sp.__version__}.",
        "",
        *index_tables(STATE_NAMES, STATE_UNITS, PARAMETERS),
        '"""',
        "import math",
        "",
        "from numba import njit",
        "",
        f"MODEL = {model.name!r}",
        *constant("DESCRIPTION", model.definition.description),
        'GEOMETRY = "planar"  # (δx, δy, θ): the thesis plane',
        'ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω (Eq 3.14)',
        *constant("STATE", STATE_NAMES),
        *constant("STATE_UNITS", STATE_UNITS),
        *constant("PARAMETERS", tuple(p.name for p in PARAMETERS)),
        *constant("PARAMETER_UNITS", tuple(p.unit for p in PARAMETERS)),
        *constant("FAMILIES", tuple(f.name for f in model.families)),
    ]


def planar_geometry_source(kin) -> list:
    """tether_margins and body_radii of the planar models (Eqs 3.10-3.12, 3.37-3.42)."""
    sub = state_substitution()
    printer = NumbaPrinter()

    def comps(vec):
        return [printer.doprint(_prepare(vec.dot(axis).subs(sub))) for axis in (kin.L.x, kin.L.y)]

    return geometry_source(list(UNPACK), [comps(v) for v in kin.tether_vectors],
                           [_CODE_NAMES[r].name for r in TETHER_REST],
                           [comps(r) for r in kin.positions], " (Eqs 3.10-3.12)")


def module_source(model: DerivedModel, length_defs, kin) -> str:
    pr = printing(length_defs)
    rhs = rhs_source(model, length_defs)
    lines = header(model) + ["", ""] + rhs
    if lanes := lanes_source(rhs):  # the rhs on K sweep points at once (derive/lanes.py)
        lines += ["", ""] + lanes
    lines += ["", ""] + family_forces_source(pr, model.families)
    lines += ["", ""] + jacobi_source(pr, model.families, model.jacobi, JACOBI_DOC)
    lines += ["", ""] + jacobian_source(model, length_defs)
    lines += ["", ""] + planar_geometry_source(kin)
    return "\n".join(lines) + "\n"


def layout_source(families) -> str:
    """generated/layout.py: the index -> symbol -> unit tables and index constants."""
    lines = ['"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/symbols.py.',
             "", *index_tables(STATE_NAMES, STATE_UNITS, PARAMETERS)]
    lines += ['"""', "", *constant("STATE", STATE_NAMES), *constant("STATE_UNITS", STATE_UNITS),
              *constant("PARAMETERS", tuple(p.name for p in PARAMETERS)),
              *constant("PARAMETER_UNITS", tuple(p.unit for p in PARAMETERS)),
              *constant("FAMILIES", tuple(families)), ""]
    lines += [f"Y_{n.upper()} = {i}" for i, n in enumerate(STATE_NAMES)]
    lines += [""] + [f"P_{p.name.upper()} = {i}" for i, p in enumerate(PARAMETERS)]
    return "\n".join(lines) + "\n"
