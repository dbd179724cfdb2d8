"""The free-orbit models' solve of M q̈ = Q − f (derive/emit.py prints the rest).

The mass matrix couples the orbit (r, ν) with the offsets, so q̈ is not
printed in closed form: ``rhs`` evaluates M (symmetric positive definite, it
is the kinetic energy's Hessian) and the right-hand side Q − f, and solves
with an unrolled LDLᵀ elimination without pivoting (stable for SPD matrices
and invariant to the very different scales of the ν and δ rows).  The same
solve serves the planar (10 states, derive/orbit.py) and the 3-D (16 states,
derive/three_d/free3d.py) free models.  No ``jacobian`` is printed: the free
models use theirs only for the RK4 step warning, and get it by central
differences of rhs (tethersim/engine/jacobian.py).  With an axial coordinate
(3-D: ψ) its row and column are replaced by the identity when the axial
inertia is zero (ψ is then no degree of freedom: ψ̈ = 0, docs/three-d.md).
"""
from __future__ import annotations

from .model import DerivedModel
from .printer import INDENT, Printing, forces_lines, kernel
from .three_d.codegen3d import ZERO_AXIAL


def _mass_matrix_lines(pr: Printing, model, indent) -> list:
    """M{i}_{j} (upper triangle) of the Lagrange equations (3.26)."""
    n = pr.n_q
    ij = [(i, j) for i in range(n) for j in range(i, n)]
    return pr.block([f"M{i}_{j}" for i, j in ij], [model.mass_matrix[i, j] for i, j in ij], "mm", indent)


def _axial_lines(n: int, axial, indent, rows) -> list:
    """Zero axial inertia: ψ's row and column of M → identity, its right-hand sides ``rows`` → 0."""
    if axial is None:
        return []
    k, condition = axial
    i2 = indent + INDENT
    out = [f"{indent}if {condition}:  # no inertia about the boom: psi'' = 0 (docs/three-d.md)"]
    out += [f"{i2}M{min(i, k)}_{max(i, k)} = 0.0" for i in range(n) if i != k]
    out += [f"{i2}M{k}_{k} = 1.0"] + [f"{i2}{r} = 0.0" for r in rows]
    return out


def _factor_lines(n: int, indent) -> list:
    """In-place LDLᵀ of the upper triangle: L{i}_{k} multipliers, M{i}_{j} → U."""
    out = []
    for k in range(n):
        for i in range(k + 1, n):
            out.append(f"{indent}L{i}_{k} = M{k}_{i} / M{k}_{k}")
            out += [f"{indent}M{i}_{j} -= L{i}_{k} * M{k}_{j}" for j in range(i, n)]
    return out


def _solve_lines(n: int, b, x, indent) -> list:
    """Forward elimination of the names ``b`` (in place), back substitution into ``x``."""
    out = [f"{indent}{b[i]} -= L{i}_{k} * {b[k]}" for k in range(n) for i in range(k + 1, n)]
    for i in reversed(range(n)):
        tail = "".join(f" - M{i}_{j} * {x[j]}" for j in range(i + 1, n))
        out.append(f"{indent}{x[i]} = ({b[i]}{tail}) / M{i}_{i}")
    return out


def rhs_source(model: DerivedModel, pr: Printing) -> list:
    """``rhs(t, y, p, dydt)``: forces, M, factorisation, solve of M q̈ = Q − f into X0..X{n-1}."""
    i1, co = INDENT, model.coordinates
    n = co.n_q
    names = co.state_names
    axial = (names.index("psi"), ZERO_AXIAL) if "psi" in names else None
    head = ["@njit(cache=True)", "def rhs(t, y, p, dydt):",
            f'{i1}"""State derivative dy/dt of model {model.name!r} (SI; y, p as in STATE, PARAMETERS)."""']
    out = forces_lines(pr, model.families, [str(q) for q in co.q_symbols])
    out.append(f"{i1}# M q'' = Q - f (Lagrange, Eq 3.26 with r, nu as coordinates)")
    out += pr.block([f"B{k}" for k in range(n)], [co.q_symbols[k] - model.f[k] for k in range(n)],
                    "fb", i1)
    out += _mass_matrix_lines(pr, model, i1)
    out += _axial_lines(n, axial, i1, [f"B{axial[0]}"] if axial else [])
    out += _factor_lines(n, i1)
    out += _solve_lines(n, [f"B{k}" for k in range(n)], [f"X{k}" for k in range(n)], i1)
    out += [f"{i1}dydt[{k}] = {names[k + n]}" for k in range(n)]
    out += [f"{i1}dydt[{k + n}] = X{k}" for k in range(n)]
    return kernel(head, pr.unpack, out)
