"""What every printer of generated/ shares: the numba code printer, cse blocks, kernels.

A kernel is a header (decorator, signature, docstring), the unpacking of y and p
into named locals, and a body of cse'd straight-line code.  :func:`kernel`
keeps only the unpacking lines the body reads (directly or through another kept
line, e.g. ``sin_theta = math.sin(theta)``), found from the body's syntax tree,
so generated code has no unused locals (ruff F841) whatever subset of the state
and parameters a kernel needs.
"""
from __future__ import annotations

import ast
import re
import textwrap

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

INDENT = "    "
WIDTH = 110  # ruff's line-length (pyproject.toml): generated/ is linted as the rest
_STATEMENT = re.compile(r"^(\s*)(return |[^=]*? (?:=|\+=|-=) )(.*)$")


class NumbaPrinter(PythonCodePrinter):
    """Python printer for scalar numba code (math module, no numpy)."""

    def __init__(self):
        super().__init__({"fully_qualified_modules": True, "standard": "python3"})

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
    """The lines of ``unpack`` (``name = expr``, in order) that ``body`` needs.

    A line is kept when the body, or a kept line after it, reads its name.
    """
    needed = _loads("\n".join(body))
    kept = []
    for line in reversed(unpack):
        target, value = line.split("=", 1)
        if target.strip() in needed:
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
    inner = indent + 2 * INDENT
    words = rhs.replace("*", "* ").replace("* * ", "** ").split(" ")
    chunks = textwrap.wrap(" ".join(words), WIDTH - len(inner) - 1, break_long_words=False,
                           break_on_hyphens=False)
    chunks = [c.replace("* ", "*").replace("** ", "**") for c in chunks]
    return [f"{indent}{lhs}("] + [inner + c for c in chunks[:-1]] + [f"{inner}{chunks[-1]})"]


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
