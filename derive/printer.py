"""The printer of generated/: everything but the solve for q̈.

Every model's module is printed by the same functions here: the unpacking of y
and p, the summed forces of the rhs (drag, then each tether's families inside
its taut gate), ``family_forces``, ``jacobi``, the header tables and constants,
and the line wrapping.  What a model's printer adds is its :class:`Printing`
record (code names of its symbols) and the step that differs between models,
the solve of M q̈ = Q − f:

* derive/codegen.py: q̈ solved symbolically (M is diagonal for the planar
  circular models), plus the analytic ``jacobian`` that the planar analyses need;
* derive/three_d/codegen3d.py: M block diagonal, the balloon rows divided by m3,
  the 3×3 attitude block by Cramer's rule (2×2 when the axial inertia is zero);
* derive/orbit_codegen.py: M full (the orbit couples every row), an unrolled
  LDLᵀ elimination; used for the planar and the 3-D free-orbit layouts.

A kernel is a header (decorator, signature, docstring), the unpacking of y and p
into named locals, and a body of cse'd straight-line code.  :func:`kernel`
keeps only the unpacking lines the body reads (directly or through another kept
line, e.g. ``sin_theta, cos_theta = sincos(theta)``), found from the body's syntax tree,
so generated code has no unused locals (ruff F841) whatever subset of the state
and parameters a kernel needs.
"""
from __future__ import annotations

import ast
import re
import textwrap
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

INDENT = "    "
WIDTH = 110  # ruff's line-length (pyproject.toml): generated/ is linted as the rest
_STATEMENT = re.compile(r"^(\s*)(return |[^=]*? (?:=|\+=|-=) )(.*)$")


class NumbaPrinter(PythonCodePrinter):
    """Python printer for scalar numba code (math module, no numpy); sin and cos are
    generated/trig.py's ``sincos`` (derive/trig.py says why)."""

    def __init__(self):
        super().__init__({"fully_qualified_modules": True, "standard": "python3"})

    def _print_sin(self, expr):
        return f"sincos({self._print(expr.args[0])})[0]"

    def _print_cos(self, expr):
        return f"sincos({self._print(expr.args[0])})[1]"

    def _print_Heaviside(self, expr):
        # the derivative of a clamp, Max(a, b) (derive/forces.py damper_pull): sympy's
        # H(0) = 1/2 splits the kink's derivative between the two sides
        x = self._print(expr.args[0])
        return f"(1.0 if {x} > 0.0 else 0.5 if {x} == 0.0 else 0.0)"

    def _print_InverseSqrtMinusOne(self, expr):
        return f"math.expm1(-0.5*math.log1p({self._print(expr.args[0])}))"

    def _print_InverseCubeMinusOne(self, expr):
        return f"math.expm1(-1.5*math.log1p({self._print(expr.args[0])}))"


def cse_block(targets, exprs, prefix, indent, op="=", skip_zero=False) -> list:
    """cse a group of (already prepared) expressions; code lines assigning them to targets.

    Parameters
    ----------
    targets : sequence of str
        Left-hand sides (names or ``array[i, j]``).
    exprs : sequence of sympy.Expr
        Their values, in code names.
    prefix : str
        Name prefix of the common subexpressions (fixed: deterministic output).
    indent : str
        Leading whitespace of every line.
    op : str, optional
        ``"="`` or ``"+="``.
    skip_zero : bool, optional
        Drop targets whose expression is exactly zero.

    Returns
    -------
    list of str
    """
    pairs = list(zip(targets, exprs))
    if skip_zero:
        pairs = [(t, e) for t, e in pairs if e != 0]
    if not pairs:
        return []
    printer = NumbaPrinter()
    repl, reduced = sp.cse([e for _, e in pairs], symbols=sp.numbered_symbols(prefix),
                           order="canonical")
    lines = [f"{indent}{s} = {printer.doprint(v)}" for s, v in repl]
    lines += [f"{indent}{t} {op} {printer.doprint(e)}" for (t, _), e in zip(pairs, reduced)]
    return lines


def _loads(source: str) -> set:
    """Names a piece of code reads."""
    tree = ast.parse(textwrap.dedent(source))
    return {n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}


def used_unpacking(unpack, body) -> list:
    """The lines of ``unpack`` (``name = expr`` or ``a, b = expr``, in order) that ``body`` needs.

    A line is kept when the body, or a kept line after it, reads one of its names.
    """
    needed = _loads("\n".join(body))
    kept = []
    for line in reversed(unpack):
        target, value = line.split("=", 1)
        if {name.strip() for name in target.split(",")} & needed:
            kept.append(line)
            needed |= _loads(value)
    return kept[::-1]


def wrap_statement(line: str) -> list:
    """``line`` as it is, or its right-hand side in parentheses over lines of at most WIDTH.

    Breaks fall between the printed terms (at spaces; sympy prints ``a + b``,
    ``a*b``), and, for a product too long for one line, after a ``*``.
    """
    if len(line) <= WIDTH:
        return [line]
    m = _STATEMENT.match(line)
    if m is None:
        raise ValueError(f"cannot wrap generated line: {line[:60]}...")
    indent, lhs, rhs = m.groups()
    if _enclosed(rhs):  # a tuple (body_radii): break inside its own parentheses
        rhs = rhs[1:-1]
    inner = indent + 2 * INDENT
    # a break may follow a space or a single * (never split **)
    words = rhs.replace("**", "\0").replace("*", "* ").replace("\0", "**")
    chunks = textwrap.wrap(words, WIDTH - len(inner) - 1, break_long_words=False,
                           break_on_hyphens=False)
    chunks = [c.replace("* ", "*") for c in chunks]
    return [f"{indent}{lhs}("] + [inner + c for c in chunks[:-1]] + [f"{inner}{chunks[-1]})"]


def _enclosed(text: str) -> bool:
    """Whether ``text`` is one parenthesised group, ``(...)``."""
    if not text.startswith("("):
        return False
    depth = 0
    for i, ch in enumerate(text):
        depth += (ch == "(") - (ch == ")")
        if depth == 0:
            return i == len(text) - 1
    return False


def kernel(head, unpack, body) -> list:
    """Lines of one kernel: ``head`` (decorator, def, docstring), the unpacking it needs, ``body``.

    Statements longer than WIDTH are wrapped (:func:`wrap_statement`).
    """
    return list(head) + [w for line in used_unpacking(unpack, body) + list(body)
                         for w in wrap_statement(line)]


def constant(name: str, value, comment: str = "") -> list:
    """``name = value`` (a module constant: str or tuple of str) within WIDTH.

    A long tuple is written one row of items per line, a long string as adjacent
    literals in parentheses (the pieces join to ``value`` exactly).
    """
    tail = f"  # {comment}" if comment else ""
    line = f"{name} = {value!r}{tail}"
    if len(line) <= WIDTH:
        return [line]
    rows, width = [], WIDTH - len(INDENT)
    if isinstance(value, tuple):
        row = ""
        for item in (repr(v) + "," for v in value):
            if row and len(row) + 1 + len(item) > width:
                rows.append(row)
                row = ""
            row = f"{row} {item}" if row else item
        rows.append(row)
    else:
        piece = ""
        for word in re.split(r"(?<= )", value):  # words with their trailing space
            if piece and len(repr(piece + word)) > width:
                rows.append(repr(piece))
                piece = ""
            piece += word
        rows.append(repr(piece))
    return [f"{name} = ({tail}"] + [INDENT + r for r in rows] + [")"]


def paragraph(text: str, indent: str = "") -> list:
    """``text`` as docstring lines of at most WIDTH characters."""
    return textwrap.wrap(text, WIDTH - len(indent), initial_indent=indent, subsequent_indent=indent,
                         break_long_words=False, break_on_hyphens=False)


# --- the kernels every model has: what differs between models is the Printing record
@dataclass(frozen=True)
class Printing:
    """How one model's expressions become code: everything but the solve for q̈.

    Attributes
    ----------
    unpack : tuple of str
        Lines (indented once) binding the state, the parameters and the sines and
        cosines of the angles; each kernel keeps those it reads (:func:`kernel`).
    block : callable
        ``block(targets, exprs, prefix, indent, op="=")``: the model's code names,
        then :func:`cse_block`.
    length_line : callable
        ``length_line(j, indent)``: the line computing λ_j (Eqs 3.41-3.42).
    n_q : int
        Number of generalized coordinates.
    units : str
        Units of the generalized forces, for family_forces' docstring.
    skip_zero : bool
        Print no assignment of an exactly-zero force component (the 3-D models'
        out-of-plane zeros; ``out`` is zeroed first).
    drag_note : str
        Appended to the drag block's comment.
    """

    unpack: tuple
    block: Callable
    length_line: Callable
    n_q: int
    units: str
    skip_zero: bool = False
    drag_note: str = ""


def gate(j: int) -> str:
    """Condition that tether j+1 is taut, λ_j > l_j0 (Eqs 3.39-3.40)."""
    return f"lambda{j + 1} > l{j + 1}0"


def _summed(families, tether, n_q: int):
    fams = [f for f in families if f.tether == tether]
    return tuple(sum(f.Q[k] for f in fams) for k in range(n_q)), fams


def forces_lines(pr: Printing, families, targets) -> list:
    """Σ Q into ``targets``: the drag block, then each tether's families inside its taut gate."""
    i1, i2 = INDENT, INDENT * 2
    drag, fams = _summed(families, None, pr.n_q)
    out = [f"{i1}# air drag on the three bodies ({fams[0].equation}{pr.drag_note})"]
    out += pr.block(targets, drag, "d", i1)  # every target, zero or not: the tethers add to it
    for j in range(2):
        tq, fams = _summed(families, j + 1, pr.n_q)
        out.append(pr.length_line(j, i1))
        out.append(f"{i1}if {gate(j)}:  # tether {j + 1} taut: {', '.join(f.name for f in fams)}")
        out += _skipping(pr, targets, tq, f"t{j + 1}_", i2, op="+=") or [f"{i2}pass"]
    return out


def _skipping(pr: Printing, targets, exprs, prefix, indent, op="=") -> list:
    if pr.skip_zero:
        kept = [(t, e) for t, e in zip(targets, exprs) if e != 0]
        targets, exprs = [t for t, _ in kept], [e for _, e in kept]
        if not kept:
            return []
    return pr.block(targets, exprs, prefix, indent, op)


def family_forces_source(pr: Printing, families) -> list:
    """``family_forces(y, p, out)``: out[f, k] = generalized force of family f on q_k."""
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True)", "def family_forces(y, p, out):",
            f'{i1}"""out[f, k] = generalized force of family FAMILIES[f] on q_k ({pr.units})."""']
    out = [pr.length_line(j, i1) for j in range(2)]
    out.append(f"{i1}out[:, :] = 0.0")
    for f_idx, fam in enumerate(families):
        targets = [f"out[{f_idx}, {k}]" for k in range(pr.n_q)]
        out.append(f"{i1}# {fam.name}: {fam.meaning} ({fam.equation})")
        if fam.tether is None:
            out += _skipping(pr, targets, fam.Q, f"f{f_idx}_", i1)
        else:
            out.append(f"{i1}if {gate(fam.tether - 1)}:")
            out += _skipping(pr, targets, fam.Q, f"f{f_idx}_", i2) or [f"{i2}pass"]
    return kernel(head, pr.unpack, out)


def jacobi_source(pr: Printing, families, energy, doc) -> list:
    """``jacobi(y, p)``: ``energy`` (the Jacobi integral) plus the taut tethers' spring energy.

    ``doc`` is the docstring's lines (indented, without the quotes).
    """
    i1, i2 = INDENT, INDENT * 2
    head = ["@njit(cache=True)", "def jacobi(y, p):", f'{i1}"""{doc[0]}', *doc[1:], f'{i1}"""']
    out = pr.block(["h"], [energy], "e", i1)
    for j in range(2):
        pots = [f.potential for f in families if f.tether == j + 1 and f.potential is not None]
        if pots:
            out.append(pr.length_line(j, i1))
            out.append(f"{i1}if {gate(j)}:")
            out += pr.block(["h"], [sum(pots)], f"u{j + 1}_", i2, op="+=")
    out.append(f"{i1}return h")
    return kernel(head, pr.unpack, out)


def unpack_lines(state_names, parameters, angles) -> tuple:
    """y[i] and p[i] into their names, then sin_<a>, cos_<a> of each angle (indented once)."""
    lines = [f"{INDENT}{n} = y[{i}]" for i, n in enumerate(state_names)]
    lines += [f"{INDENT}{p.name} = p[{i}]" for i, p in enumerate(parameters)]
    for a in angles:
        lines.append(f"{INDENT}sin_{a}, cos_{a} = sincos({a})")
    return tuple(lines)


def index_tables(state_names, state_units, parameters, state_meanings=None) -> list:
    """index → name → unit (→ meaning) tables of y and p, for a generated module's docstring."""
    w = max(len(n) for n in tuple(state_names) + tuple(p.name for p in parameters))
    if state_meanings is None:
        lines = ["State vector y (index, name, unit):"]
        lines += [f"  {i:2d}  {n:<{w}}  {u}" for i, (n, u) in enumerate(zip(state_names, state_units))]
    else:
        lines = ["State vector y (index, name, unit, meaning):"]
        lines += [f"  {i:2d}  {n:<{w}}  {u:<8}  {m}" for i, (n, u, m)
                  in enumerate(zip(state_names, state_units, state_meanings))]
    lines += ["", "Parameter vector p (index, name, unit, meaning):"]
    lines += [f"  {i:2d}  {p.name:<{w}}  {p.unit:<8}  {p.meaning}" for i, p in enumerate(parameters)]
    return lines


def module_filename(name: str) -> str:
    """Model name → module file name ('3d-exact-gravity' → 'three_d_exact_gravity.py')."""
    return name.replace("3d", "three_d").replace("-", "_") + ".py"
