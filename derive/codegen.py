"""Print a DerivedModel as a numba module: cse'd straight-line code.

Each generated module holds two kernels with plain float-array signatures:

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
from .pipeline import Q_SYMBOLS, DerivedModel
from .printer import INDENT, NumbaPrinter, constant, cse_block, kernel, paragraph
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


def _unpack(indent) -> list:
    lines = [f"{indent}{n} = y[{i}]" for i, n in enumerate(STATE_NAMES)]
    lines += [f"{indent}{p.name} = p[{i}]" for i, p in enumerate(PARAMETERS)]
    lines += [f"{indent}sin_theta = math.sin(theta)", f"{indent}cos_theta = math.cos(theta)"]
    return lines


def _tether_length_line(j: int, indent: str, defs) -> str:
    lam = TETHER_LENGTHS[j]
    return f"{indent}{lam} = {NumbaPrinter().doprint(_prepare(defs[lam]))}"


def _gate(j: int) -> str:
    return f"{TETHER_LENGTHS[j]} > {_CODE_NAMES[TETHER_REST[j]]}"


def _sum_families(model: DerivedModel, tether):
    fams = [f for f in model.families if f.tether == tether]
    return tuple(sum(f.Q[k] for f in fams) for k in range(3)), fams


def rhs_source(model: DerivedModel, length_defs) -> list:
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True, inline=\"always\")", "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; layout in generated/layout.py)."""']
    out = []
    qnames = [str(q) for q in Q_SYMBOLS]
    drag, fams = _sum_families(model, None)
    out.append(f"{i1}# air drag on the three bodies ({fams[0].equation})")
    out += _block(qnames, drag, "d", i1)
    for j in range(2):
        tq, fams = _sum_families(model, j + 1)
        names = ", ".join(f.name for f in fams)
        out.append(_tether_length_line(j, i1, length_defs))
        out.append(f"{i1}if {_gate(j)}:  # tether {j + 1} taut: {names}")
        out += _block(qnames, tq, f"t{j + 1}_", i2, op="+=")
    acc = [_prepare(e) for e in model.qdd]
    out.append(f"{i1}# accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)")
    out += [f"{i1}dydt[{k}] = {STATE_NAMES[k + 3]}" for k in range(3)]
    out += _block([f"dydt[{k + 3}]" for k in range(3)], acc, "a", i1)
    return kernel(head, _unpack(i1), out)


def family_forces_source(model: DerivedModel, length_defs) -> list:
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True)", "def family_forces(y, p, out):",
            f'{i1}"""out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N m)."""']
    out = []
    out += [_tether_length_line(j, i1, length_defs) for j in range(2)]
    out.append(f"{i1}out[:, :] = 0.0")
    for f_idx, fam in enumerate(model.families):
        targets = [f"out[{f_idx}, {k}]" for k in range(3)]
        out.append(f"{i1}# {fam.name}: {fam.meaning} ({fam.equation})")
        if fam.tether is None:
            out += _block(targets, fam.Q, f"f{f_idx}_", i1)
        else:
            out.append(f"{i1}if {_gate(fam.tether - 1)}:")
            out += _block(targets, fam.Q, f"f{f_idx}_", i2)
    return kernel(head, _unpack(i1), out)


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
        out.append(f"{i1}if {_gate(j)}:")
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
    return kernel(head, _unpack(i1), out)


def jacobi_source(model: DerivedModel, length_defs) -> list:
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True)", "def jacobi(y, p):",
            f'{i1}"""Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].',
            "",
           f"{i1}Constant with drag and dampers off; otherwise dh/dt = power of drag and dampers.",
           f'{i1}"""']
    out = []
    out += _block(["h"], [model.jacobi], "e", i1)
    for j in range(2):
        pots = [f.potential for f in model.families if f.tether == j + 1 and f.potential is not None]
        if pots:
            out.append(_tether_length_line(j, i1, length_defs))
            out.append(f"{i1}if {_gate(j)}:")
            out += _block(["h"], [sum(pots)], f"u{j + 1}_", i2, op="+=")
    out.append(f"{i1}return h")
    return kernel(head, _unpack(i1), out)


def _index_tables() -> list:
    """index -> symbol -> unit tables of y and p (the same in every generated file)."""
    w = max(len(n) for n in STATE_NAMES + tuple(p.name for p in PARAMETERS))
    lines = ["State vector y (index, name, unit):"]
    lines += [f"  {i:2d}  {n:<{w}}  {u}" for i, (n, u) in enumerate(zip(STATE_NAMES, STATE_UNITS))]
    lines += ["", "Parameter vector p (index, name, unit, meaning):"]
    lines += [f"  {i:2d}  {p.name:<{w}}  {p.unit:<8}  {p.meaning}" for i, p in enumerate(PARAMETERS)]
    return lines


def header(model: DerivedModel) -> list:
    return [
        '"""GENERATED FILE - DO NOT EDIT.',
        "",
        *paragraph(f"Model {model.name!r}: {model.definition.description}."),
        "Produced by `make derive` (python -m derive) from derive/; regenerate instead",
        f"of editing.  sympy {sp.__version__}.",
        "",
        *_index_tables(),
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

    return geometry_source(_unpack(INDENT), [comps(v) for v in kin.tether_vectors],
                           [_CODE_NAMES[r].name for r in TETHER_REST],
                           [comps(r) for r in kin.positions], " (Eqs 3.10-3.12)")


def module_source(model: DerivedModel, length_defs, kin) -> str:
    lines = header(model) + ["", ""] + rhs_source(model, length_defs)
    lines += ["", ""] + family_forces_source(model, length_defs)
    lines += ["", ""] + jacobi_source(model, length_defs)
    lines += ["", ""] + jacobian_source(model, length_defs)
    lines += ["", ""] + planar_geometry_source(kin)
    return "\n".join(lines) + "\n"


def layout_source(families) -> str:
    """generated/layout.py: the index -> symbol -> unit tables and index constants."""
    lines = ['"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/symbols.py.',
             "", *_index_tables()]
    lines += ['"""', "", *constant("STATE", STATE_NAMES), *constant("STATE_UNITS", STATE_UNITS),
              *constant("PARAMETERS", tuple(p.name for p in PARAMETERS)),
              *constant("PARAMETER_UNITS", tuple(p.unit for p in PARAMETERS)),
              *constant("FAMILIES", tuple(families)), ""]
    lines += [f"Y_{n.upper()} = {i}" for i, n in enumerate(STATE_NAMES)]
    lines += [""] + [f"P_{p.name.upper()} = {i}" for i, p in enumerate(PARAMETERS)]
    return "\n".join(lines) + "\n"


def module_filename(name: str) -> str:
    """Model name -> module file name ('3d-exact-gravity' -> 'three_d_exact_gravity.py')."""
    return name.replace("3d", "three_d").replace("-", "_") + ".py"
