"""The planar circular models' solve: q̈ in closed form, and the analytic Jacobian.

derive/emit.py prints every model; what is particular to the planar circular
coordinates is here: M is diagonal, so derive.model.derive solves q̈
symbolically and ``rhs`` prints it (:func:`rhs_source`), and the planar
analyses (modes, equilibrium) use an analytic

``jacobian(t, y, p, J)``          ∂(dy/dt)/∂y, 6x6 (:func:`jacobian_source`)

Beside the model modules, ``generated/layout.py`` holds the planar index
tables (:func:`layout_source`).  Code names: :func:`prepare` (also used by the
planar free-orbit models).
"""
from __future__ import annotations

import sympy as sp

from .model import DerivedModel
from .pipeline import Q_SYMBOLS
from .printer import INDENT, Printing, constant, cse_block, forces_lines, gate, index_tables, kernel
from .symbols import PARAMETERS, STATE_NAMES, STATE_SYMBOLS, STATE_UNITS

_SIN, _COS = sp.Symbol("sin_theta", real=True), sp.Symbol("cos_theta", real=True)
_CODE_NAMES = {p.symbol: sp.Symbol(p.name, positive=True) for p in PARAMETERS}


def prepare(expr):
    """Code names for parameters, named sin θ / cos θ.

    sin 2θ and cos 2θ (the solved q̈ and the Jacobian carry them) are written
    2 sin θ cos θ and cos²θ − sin²θ: the kernel evaluates no second pair of
    transcendental functions beside sin θ, cos θ, and cse shares the products.
    """
    th = STATE_SYMBOLS[2]
    e = sp.sympify(expr).xreplace(_CODE_NAMES)
    return e.xreplace({sp.sin(2 * th): 2 * _SIN * _COS, sp.cos(2 * th): _COS**2 - _SIN**2,
                       sp.sin(th): _SIN, sp.cos(th): _COS})


_prepare = prepare  # the name bench/cref.py mirrors


def _block(targets, exprs, prefix, indent, op="="):
    """cse a group of expressions; return code lines assigning them to targets."""
    return cse_block(targets, [_prepare(e) for e in exprs], prefix, indent, op)


def _sum_families(model: DerivedModel, tether):
    fams = [f for f in model.families if f.tether == tether]
    return tuple(sum(f.Q[k] for f in fams) for k in range(3)), fams


def rhs_source(model: DerivedModel, pr: Printing) -> list:
    """``rhs(t, y, p, dydt)``: the summed forces, then q̈ in closed form."""
    i1 = INDENT
    head = ["@njit(cache=True, inline=\"always\")", "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; layout in generated/layout.py)."""']
    out = forces_lines(pr, model.families, [str(q) for q in Q_SYMBOLS])
    acc = [_prepare(e) for e in model.qdd]
    out.append(f"{i1}# accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)")
    out += [f"{i1}dydt[{k}] = {STATE_NAMES[k + 3]}" for k in range(3)]
    out += _block([f"dydt[{k + 3}]" for k in range(3)], acc, "a", i1)
    return kernel(head, pr.unpack, out)


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


def jacobian_source(model: DerivedModel, pr: Printing) -> list:
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
    rows = _d_dy(drag, model.length_defs)
    out += _block([dq[k][j] for k in range(3) for j in range(6)],
                  [rows[k][j] for k in range(3) for j in range(6)], "jd", i1)
    for j in range(2):
        tq, _ = _sum_families(model, j + 1)
        rows = _d_dy(tq, model.length_defs)
        out.append(pr.length_line(j, i1))
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
    return kernel(head, pr.unpack, out)


def extra_kernels(model: DerivedModel, pr: Printing) -> tuple:
    """Kernels printed after jacobi: the analytic Jacobian."""
    return (jacobian_source(model, pr),)


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
