"""Print a FreeDerivedModel as a numba module (the free-orbit kernels).

Same kernel signatures as the planar modules (derive/codegen.py), on the
10-float free state (derive/orbit.py FREE_STATE_NAMES):

``rhs(t, y, p, dydt)``         state derivative (q̇, q̈), q = (δx, δy, θ, r, ν)
``family_forces(y, p, out)``   out[f, k]: generalized force of family f on q_k
``jacobi(y, p)``               total energy T + V + taut-tether spring energy [J]
``jacobian(t, y, p, J)``       ∂(dy/dt)/∂y, 10x10

The 5x5 mass matrix couples the orbit (r, ν) with the offsets, so q̈ is not
printed in closed form: the kernel evaluates M (symmetric positive definite,
it is the kinetic energy's Hessian) and the right-hand side Q − f, and solves
with an unrolled LDLᵀ elimination without pivoting (stable for SPD matrices
and invariant to the very different scales of the ν and δ rows).  The
Jacobian uses the same factors: with R(y, q̈) = M q̈ + f − Q,
∂q̈/∂y = −M⁻¹ ∂R/∂y at the current q̈.
"""
from __future__ import annotations

import sympy as sp

from .codegen import INDENT, _block, _gate, _tether_length_line
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

N_Q = 5
N_Y = 10
_X = tuple(sp.Symbol(f"X{k}", real=True) for k in range(N_Q))  # q̈ inside the kernels


def _unpack(indent) -> list:
    lines = [f"{indent}{n} = y[{i}]" for i, n in enumerate(FREE_STATE_NAMES)]
    lines += [f"{indent}{p.name} = p[{i}]" for i, p in enumerate(FREE_PARAMETERS)]
    lines += [f"{indent}sin_theta = math.sin(theta)", f"{indent}cos_theta = math.cos(theta)"]
    return lines


def _pblock(targets, exprs, prefix, indent, op="="):
    return _block(targets, [printable(e) for e in exprs], prefix, indent, op)


def _sum_families(model: FreeDerivedModel, tether):
    fams = [f for f in model.families if f.tether == tether]
    return tuple(sum(f.Q[k] for f in fams) for k in range(N_Q)), fams


def _forces_lines(model, length_defs, targets, prefix, rows=None) -> list:
    """Summed forces (drag ungated, each tether's families inside its taut gate).

    ``rows`` maps a tuple of 5 expressions to the list actually printed
    (identity for Q itself, ∂Q/∂y rows for the Jacobian).
    """
    rows = rows or (lambda q: list(q))
    i1, i2 = INDENT, INDENT * 2
    drag, fams = _sum_families(model, None)
    out = [f"{i1}# air drag on the three bodies ({fams[0].equation}, co-rotating air)"]
    out += _pblock(targets, rows(drag), f"{prefix}d", i1)
    for j in range(2):
        tq, fams = _sum_families(model, j + 1)
        out.append(_tether_length_line(j, i1, length_defs))
        out.append(f"{i1}if {_gate(j)}:  # tether {j + 1} taut: {', '.join(f.name for f in fams)}")
        out += _pblock(targets, rows(tq), f"{prefix}t{j + 1}_", i2, op="+=")
    return out


def _mass_matrix_lines(model, indent) -> list:
    """M{i}_{j} (upper triangle) of the Lagrange equations (3.26)."""
    ij = [(i, j) for i in range(N_Q) for j in range(i, N_Q)]
    return _pblock([f"M{i}_{j}" for i, j in ij], [model.mass_matrix[i, j] for i, j in ij],
                   "mm", indent)


def _factor_lines(indent) -> list:
    """In-place LDLᵀ of the upper triangle: L{i}_{k} multipliers, M{i}_{j} → U."""
    out = []
    for k in range(N_Q):
        for i in range(k + 1, N_Q):
            out.append(f"{indent}L{i}_{k} = M{k}_{i} / M{k}_{k}")
            out += [f"{indent}M{i}_{j} -= L{i}_{k} * M{k}_{j}" for j in range(i, N_Q)]
    return out


def _solve_lines(b, x, indent) -> list:
    """Forward elimination of the names ``b`` (in place), back substitution into ``x``."""
    out = [f"{indent}{b[i]} -= L{i}_{k} * {b[k]}" for k in range(N_Q) for i in range(k + 1, N_Q)]
    for i in reversed(range(N_Q)):
        tail = "".join(f" - M{i}_{j} * {x[j]}" for j in range(i + 1, N_Q))
        out.append(f"{indent}{x[i]} = ({b[i]}{tail}) / M{i}_{i}")
    return out


def _accelerations(model, length_defs) -> list:
    """Lines leaving q̈ in X0..X4: forces, M, factorisation, solve of M q̈ = Q − f."""
    i1 = INDENT
    qn = [str(q) for q in FREE_Q_SYMBOLS]
    out = _forces_lines(model, length_defs, qn, "")
    out.append(f"{i1}# M q'' = Q - f (Lagrange, Eq 3.26 with r, nu as coordinates)")
    out += _pblock([f"B{k}" for k in range(N_Q)],
                   [FREE_Q_SYMBOLS[k] - model.f[k] for k in range(N_Q)], "fb", i1)
    out += _mass_matrix_lines(model, i1)
    out += _factor_lines(i1)
    out += _solve_lines([f"B{k}" for k in range(N_Q)], [str(x) for x in _X], i1)
    return out


def rhs_source(model: FreeDerivedModel, length_defs) -> list:
    i1 = INDENT
    out = ["@njit(cache=True)", "def rhs(t, y, p, dydt):",
           f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; y and p as in STATE, PARAMETERS)."""']
    out += _unpack(i1) + _accelerations(model, length_defs)
    out += [f"{i1}dydt[{k}] = {FREE_STATE_NAMES[k + N_Q]}" for k in range(N_Q)]
    out += [f"{i1}dydt[{k + N_Q}] = X{k}" for k in range(N_Q)]
    return out


def family_forces_source(model: FreeDerivedModel, length_defs) -> list:
    i1, i2 = INDENT, INDENT * 2
    out = ["@njit(cache=True)", "def family_forces(y, p, out):",
           f'{i1}"""out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N m, N, N m)."""']
    out += _unpack(i1)
    out += [_tether_length_line(j, i1, length_defs) for j in range(2)]
    out.append(f"{i1}out[:, :] = 0.0")
    for f_idx, fam in enumerate(model.families):
        targets = [f"out[{f_idx}, {k}]" for k in range(N_Q)]
        out.append(f"{i1}# {fam.name}: {fam.meaning} ({fam.equation})")
        if fam.tether is None:
            out += _pblock(targets, fam.Q, f"f{f_idx}_", i1)
        else:
            out.append(f"{i1}if {_gate(fam.tether - 1)}:")
            out += _pblock(targets, fam.Q, f"f{f_idx}_", i2)
    return out


def jacobi_source(model: FreeDerivedModel, length_defs) -> list:
    i1, i2 = INDENT, INDENT * 2
    out = ["@njit(cache=True)", "def jacobi(y, p):",
           f'{i1}"""Total energy T + V (orbit and attitude) plus taut-tether spring energy [J].',
           "",
           f"{i1}L = T − V has no explicit t, so this is the Jacobi integral: constant with drag",
           f"{i1}and dampers off, otherwise dE/dt = Σ_k (Q_drag + Q_damper)_k q̇_k.",
           f'{i1}"""']
    out += _unpack(i1)
    out += _pblock(["h"], [model.energy], "e", i1)
    for j in range(2):
        pots = [f.potential for f in model.families if f.tether == j + 1 and f.potential is not None]
        if pots:
            out.append(_tether_length_line(j, i1, length_defs))
            out.append(f"{i1}if {_gate(j)}:")
            out += _pblock(["h"], [sum(pots)], f"u{j + 1}_", i2, op="+=")
    out.append(f"{i1}return h")
    return out


def _d_dy(exprs, length_defs):
    """Rows ∂expr/∂y (10 columns), λ_j differentiated through Eqs 3.41-3.42."""
    back = {v: k for k, v in length_defs.items()}
    rows = []
    for e in exprs:
        full = sp.sympify(e).xreplace(length_defs)
        rows.append([sp.sympify(full.diff(s)).xreplace(back) for s in FREE_STATE_SYMBOLS])
    return rows


def jacobian_source(model: FreeDerivedModel, length_defs) -> list:
    """J = ∂(dy/dt)/∂y (10x10): ∂q̈/∂y = −M⁻¹ (∂(M q̈ + f)/∂y − ∂Q/∂y) at the current q̈."""
    i1 = INDENT
    out = ["@njit(cache=True)", "def jacobian(t, y, p, J):",
           f'{i1}"""J[i, j] = ∂(dy_i/dt)/∂y_j of model {model.name!r} (units of y_i/s per y_j)."""']
    out += _unpack(i1) + _accelerations(model, length_defs)
    dq = [f"dQ{k}_{c}" for k in range(N_Q) for c in range(N_Y)]

    def flat(q):
        rows = _d_dy(q, length_defs)
        return [rows[k][c] for k in range(N_Q) for c in range(N_Y)]

    out += _forces_lines(model, length_defs, dq, "j", rows=flat)
    acc = dict(zip(FREE_ACCELERATION_SYMBOLS, _X))
    lhs_rows = _d_dy([e.xreplace(acc) for e in model.lhs], length_defs)
    dq_syms = sp.symbols(" ".join(dq), real=True)
    dR = [lhs_rows[k][c] - dq_syms[N_Y * k + c] for k in range(N_Q) for c in range(N_Y)]
    out += _pblock([f"R{c}_{k}" for k in range(N_Q) for c in range(N_Y)], dR, "jr", i1)
    out.append(f"{i1}J[:, :] = 0.0")
    out += [f"{i1}J[{k}, {k + N_Q}] = 1.0" for k in range(N_Q)]
    for c in range(N_Y):
        b = [f"R{c}_{k}" for k in range(N_Q)]
        x = [f"Z{c}_{k}" for k in range(N_Q)]
        out += _solve_lines(b, x, i1)
        out += [f"{i1}J[{k + N_Q}, {c}] = -Z{c}_{k}" for k in range(N_Q)]
    return out


def _index_tables() -> list:
    w = max(len(n) for n in FREE_STATE_NAMES + tuple(p.name for p in FREE_PARAMETERS))
    lines = ["State vector y (index, name, unit):"]
    lines += [f"  {i:2d}  {n:<{w}}  {u}"
              for i, (n, u) in enumerate(zip(FREE_STATE_NAMES, FREE_STATE_UNITS))]
    lines += ["", "Parameter vector p (index, name, unit, meaning):"]
    lines += [f"  {i:2d}  {p.name:<{w}}  {p.unit:<8}  {p.meaning}"
              for i, p in enumerate(FREE_PARAMETERS)]
    return lines


def _layout_constants() -> list:
    return [f"STATE = {FREE_STATE_NAMES!r}", f"STATE_UNITS = {FREE_STATE_UNITS!r}",
            f"PARAMETERS = {tuple(p.name for p in FREE_PARAMETERS)!r}",
            f"PARAMETER_UNITS = {tuple(p.unit for p in FREE_PARAMETERS)!r}", "",
            *(f"Y_{n.upper()} = {i}" for i, n in enumerate(FREE_STATE_NAMES)), "",
            *(f"P_{p.name.upper()} = {i}" for i, p in enumerate(FREE_PARAMETERS))]


def module_source(model: FreeDerivedModel, length_defs, geometry=()) -> str:
    lines = ['"""GENERATED FILE - DO NOT EDIT.', "",
             f"Model {model.name!r}: {model.definition.description}.",
             "Produced by `make derive` (python -m derive) from derive/orbit.py and",
             f"derive/orbit_codegen.py; regenerate instead of editing.  sympy {sp.__version__}.",
             f"Reduces to the planar model {model.definition.circular!r} on a circular orbit.", "",
             *_index_tables(), '"""', "import math", "", "from numba import njit", "",
             f"MODEL = {model.name!r}",
             f"DESCRIPTION = {model.definition.description!r}",
             'GEOMETRY = "planar"  # (δx, δy, θ) in the orbit plane',
             'ORBIT = "free"  # r and ν are coordinates: gravity, J2 and drag move the orbit',
             f"FAMILIES = {tuple(f.name for f in model.families)!r}",
             *_layout_constants()]
    for part in (rhs_source, family_forces_source, jacobi_source, jacobian_source):
        lines += ["", ""] + part(model, length_defs)
    if geometry:
        lines += ["", ""] + list(geometry)
    return "\n".join(lines) + "\n"


def geometry_lines(kin, sub) -> list:
    """tether_margins and body_radii on the free state (positions about r, Eqs 3.10-3.12)."""
    from .codegen import _CODE_NAMES, NumbaPrinter, _prepare
    from .geometry import geometry_source
    from .symbols import TETHER_REST

    printer = NumbaPrinter()

    def comps(vec):
        return [printer.doprint(_prepare(vec.dot(axis).subs(sub))) for axis in (kin.L.x, kin.L.y)]

    return geometry_source(_unpack(INDENT), [comps(v) for v in kin.tether_vectors],
                           [_CODE_NAMES[r].name for r in TETHER_REST], [comps(r) for r in kin.positions],
                           " (Eqs 3.10-3.12 about the orbit radius r)")


def dispatch_source(definitions) -> str:
    """generated/free_dispatch.py: one jitted entry point per kernel, model index first."""
    mods = [d.name.replace("-", "_") for d in definitions]
    lines = ['"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/orbit_codegen.py.',
             "", "Free-orbit models (state and parameter layout in each module's STATE, PARAMETERS).",
             '"""', "from numba import njit", "",
             *(f"from . import {m}" for m in mods), "",
             f"MODEL_NAMES = {tuple(d.name for d in definitions)!r}",
             f"STATE = {mods[0]}.STATE", f"PARAMETERS = {mods[0]}.PARAMETERS", ""]
    for fn, args in (("rhs", "t, y, p, dydt"), ("family_forces", "y, p, out"),
                     ("jacobi", "y, p"), ("jacobian", "t, y, p, J")):
        lines += ["", "@njit(cache=True)", f"def {fn}(model, {args}):",
                  f'    """{fn} of free model MODEL_NAMES[model]."""']
        ret = "return " if fn == "jacobi" else ""
        for i, m in enumerate(mods):
            lines += [f"    {'if' if i == 0 else 'elif'} model == {i}:", f"        {ret}{m}.{fn}({args})"]
        if ret:
            lines += ["    return 0.0"]
    return "\n".join(lines) + "\n"


def write_free_models(out) -> list:
    """Derive every free-orbit model and write its module and free_dispatch.py into ``out``."""
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
    (out / "free_dispatch.py").write_text(dispatch_source(FREE_DEFINITIONS))
    return written
