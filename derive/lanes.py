"""The lane form of a printed kernel: K points at once, for SIMD across sweep points.

``lanes_source`` rewrites the lines of a printed scalar ``rhs(t, y, p, dydt)``
(codegen.rhs_source) into ``rhs_lanes(t, y, p, dydt, s)`` over structure-of-arrays
inputs: K = len(t) points; row i of y (state), p (parameters), dydt and a scratch s
(N_TRANSCENDENTAL rows) sits at [i*LANES, i*LANES + K) of its flat array, LANES = 8 a
constant.  ``family_forces(y, p, out)`` (printer.family_forces_source) becomes
``family_forces_lanes(K, y, p, out, s)`` the same way, out[f, q] at row f*n_q + q: a
sweep's force peaks take K samples of a run at once.  The body is the scalar body,
statement for statement, inside ``for k in range(K)``, so every lane does the same IEEE
operations in the same order as the scalar kernel (no fast-math: the results are equal
bit for bit) and LLVM can vectorise the loop across lanes.  It cannot vectorise a loop
holding a call to libm (numba's build has no vector versions, ``numba -s``: SVML not
available), so:

* sin and cos (generated/trig.py's ``sincos``: polynomials, libm only for |x| ≥
  trig.LIMIT) stay in the vector loop as ``sincos_lane(x, s[j], s[j + 1])``; a first,
  scalar loop stores libm's values for the lanes beyond the limit in s[j], s[j + 1]
  (``sincos_beyond``), so each lane still equals the scalar ``sincos(x)`` bit for bit;
* any other libm call (exp, log, ...) is hoisted into that first loop, which writes
  it into s; the vector loop reads s.

A call qualifies when its argument reads only the state and the parameters (the
unpacked names); a model with any other such call gets no lane form (the caller then
runs the scalar rhs).  sqrt, the arithmetic and the taut/slack branches (if-converted
into selects) stay in the vector loop.
"""
from __future__ import annotations

import re

from .printer import wrap_statement

# libm calls with no vector version in numba's default build; sqrt, fabs are LLVM
# intrinsics that vectorise
TRANSCENDENTAL = re.compile(
    r"math\.(sin|cos|tan|exp|expm1|log|log1p|atan2|atan|asin|acos|hypot|pow|sinh|cosh|tanh)\(")
# generated/trig.py's sincos: group 2, a call the vector loop keeps
CALL = re.compile(TRANSCENDENTAL.pattern + r"|(?<![\w.])(sincos)\(")
# the lane arrays' row stride, a compile-time constant: with it LLVM sees every row of y,
# p, s and dydt at a constant offset from the array's start, so the few run-time alias
# checks it needs to vectorise fit its budget (with a run-time row stride it gives up)
LANES = 8
_UNPACK = re.compile(r"^\s+(\w+) = ([yp])\[(\d+)\]$")
_OUT = re.compile(r"\bout\[(\d+), (\d+)\]")  # family_forces' out[f, q]
# the kernels with a lane form: scalar name -> (lane signature, the lane count K, its doc)
KERNELS = {
    "rhs": ("rhs_lanes(t, y, p, dydt, s)", "t.shape[0]",
            ("rhs on K = len(t) <= LANES lanes: row i of y, p, dydt and of the",
             "scratch s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K).")),
    "family_forces": ("family_forces_lanes(K, y, p, out, s)", "K",
                      ("family_forces on K <= LANES lanes: row i of y, p and of the scratch",
                       "s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K), out[f, q] is",
                       "row f*n_q + q of out.")),
    # not bit for bit: a filter (_APPROXIMATE)
    "tether_margins": ("tether_margins_lanes(K, y, p, g, s)", "K",
                       ("tether_margins on K <= LANES lanes: row i of y, p and of the scratch",
                        "s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K), g[j] is row j",
                        "of g.")),
}
# kernels whose lane form may differ from the scalar one in the last bits: the tether
# margins take sqrt(x**2 + y**2) for the scalar kernel's math.hypot(x, y), which has no
# vector version (within 2 ulp of the length against hypot's 1).  The adaptive lanes
# (tethersim/experiments/sweep/lanes853.py) use them only to see that no event can have
# fired in a step, with a margin far above that difference, and evaluate the scalar
# kernel where one may have
_APPROXIMATE = {"tether_margins": (re.compile(r"math\.hypot\(([^,()]*), ([^,()]*)\)"),
                                   r"math.sqrt((\1)**2 + (\2)**2)")}
_NAME = re.compile(r"[A-Za-z_]\w*")


def _call_end(text: str, open_at: int) -> int:
    """Index just past the parenthesis that closes the one at text[open_at]."""
    depth = 0
    for i in range(open_at, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return i + 1
    raise ValueError("unbalanced parentheses in a printed rhs")


def _index_names(line: str, n_q: int = 0, time: bool = True) -> str:
    """y[i] -> y[i*LANES + k] (and p, dydt), out[f, q] -> out[(f*n_q + q)*LANES + k],
    t -> t[k] (``time``: the lane form takes the times t), in a line's code (not its
    comment)."""
    code, hash_, comment = line.partition("#")
    code = re.sub(r"\b(y|p|dydt|g)\[(\d+)\]", r"\1[\2*LANES + k]", code)
    code = _OUT.sub(lambda m: f"out[{int(m[1]) * n_q + int(m[2])}*LANES + k]", code)
    if time:
        code = re.sub(r"\bt\b", "t[k]", code)
    return code + hash_ + comment


def _rows(first: int, n: int) -> str:
    """Rows first .. first + n - 1 of the lane scratch s, lane k: ``s[j*LANES + k], ...``."""
    return ", ".join(f"s[{first + i}*LANES + k]" for i in range(n))


def _logical_lines(lines: list) -> list:
    """The printed lines with each statement wrapped over several lines joined into one
    (wrap_statement rewraps it at the lane body's deeper indent)."""
    out, depth = [], 0
    for line in lines:
        if depth > 0:
            piece = line.strip()
            out[-1] += piece if out[-1].endswith(("*", "(")) else " " + piece
        else:
            out.append(line)
        code = line.partition("#")[0]
        depth += code.count("(") - code.count(")")
    return out


def lanes_source(lines: list, name: str = "rhs", indent: str = "    ") -> tuple:
    """(The lines of the lane form of the printed scalar kernel ``name`` (KERNELS) from
    its lines, the scratch rows it needs), or ([], 0) when one of its libm calls reads an
    intermediate (module docstring)."""
    signature, count, doc = KERNELS[name]
    start = next(i for i, line in enumerate(lines) if line.startswith(f"def {name}("))
    doc_end = next(i for i in range(start + 1, len(lines))
                   if lines[i].rstrip().endswith('"""'))
    end = next((i for i in range(doc_end + 1, len(lines))
                if lines[i].startswith(("@", "def "))), len(lines))  # the next kernel
    body = [line for line in lines[doc_end + 1:end] if line.strip()]
    outs = [(int(f), int(q)) for f, q in _OUT.findall("\n".join(body))]
    n_q = 1 + max(q for _, q in outs) if outs else 0
    zero = [f"{indent}out[{f}, {q}] = 0.0" for f in range(1 + max(f for f, _ in outs))
            for q in range(n_q)] if outs else []  # out[:, :] = 0.0, lane by lane
    body = [z for line in body for z in (zero if line.strip() == "out[:, :] = 0.0" else [line])]
    unpack = {}  # name -> its unpacking line
    for line in body:
        if m := _UNPACK.match(line):
            unpack[m.group(1)] = line
    text = "\n".join(_logical_lines(body))
    if name in _APPROXIMATE:
        pattern, replacement = _APPROXIMATE[name]
        text = pattern.sub(replacement, text)
    stored = {}  # (what the first loop stores, rows of s) -> its first row, in order of first use
    out, pos = [], 0
    for m in CALL.finditer(text):
        if m.start() < pos:
            continue  # nested inside a call already hoisted
        end = _call_end(text, m.end() - 1)
        call, arg = text[m.start():end], text[m.end():end - 1]
        if not set(_NAME.findall(arg)) - {"math"} <= set(unpack) or "\n" in call:
            return [], 0
        trig = m.group(2) is not None
        if trig and TRANSCENDENTAL.search(arg):
            return [], 0
        entry = (f"sincos_beyond({arg})", 2) if trig else (call, 1)
        stored.setdefault(entry, sum(n for _, n in stored))
        rows = _rows(stored[entry], entry[1])
        out.append(text[pos:m.start()] + (f"sincos_lane({arg}, {rows})" if trig else rows))
        pos = end
    out.append(text[pos:])
    vector_body = "".join(out).split("\n")
    i1, i2 = indent, indent * 2
    needed = set().union(*(set(_NAME.findall(c)) for c, _ in stored))
    src = ["@njit(cache=True, inline=\"always\")",
           f"def {signature}:",
           f'{i1}"""{doc[0]}', *(f"{i1}{d}" for d in doc[1:]),
           "",
           *([f"{i1}Each lane is {name}'s value to a few ulps (sqrt for its hypot,",
              f"{i1}derive/lanes.py); libm's values come first, lane by lane."]
             if name in _APPROXIMATE else
             [f"{i1}Each lane equals {name} bit for bit (derive/lanes.py); libm's values",
              f"{i1}come first, lane by lane, so that the second loop vectorises."]),
           f'{i1}"""',
           f"{i1}for k in range({count}):"]
    time = "(t," in signature
    src += [_index_names(unpack[n], 0, time).replace(i1, i2, 1) for n in unpack if n in needed]
    src += [f"{i2}{_rows(first, n)} = {c}" for (c, n), first in stored.items()]
    if not stored:
        src.append(f"{i2}pass")
    src.append(f"{i1}for k in range({count}):")
    for line in vector_body:
        src += wrap_statement(i1 + _index_names(line, n_q, time)) if line.strip() else [line]
    return src, sum(n for _, n in stored)


def lanes_constants(rows: int) -> list:
    """The lane forms' module constants: their scratch rows (the most any needs) and the
    row stride."""
    return [f"N_TRANSCENDENTAL = {max(1, rows)}",
            f"LANES = {LANES}  # row stride of the lane arrays: the most lanes (AVX-512)"]
