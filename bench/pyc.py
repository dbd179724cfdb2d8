"""Generated numba kernels printed as C, line by line (the 3-D model's C port).

The generated modules (generated/*.py) are straight-line code: assignments,
``+=``, ``if``/``else`` on the tether gates and the mass-matrix branch, calls to
``sincos`` (generated/trig.py; printed as ``ts_sincos``, :data:`TRIG`: its C twin, the
same operations in the same order, so C and numba take the same steps), ``math.sqrt``, integer powers and
the small ``_solve2``/``_solve3`` Cramer helpers.  :func:`function_to_c` turns one
such function into C with the same operations in the same order (integer literals
become doubles, since Python's ``9/2`` is 4.5; ``x**2``/``x**3`` become products, as
numba emits them), so a C port of any generated model comes from the very code the
engine runs.  It refuses any construct it does not know, rather than printing wrong C.
"""
from __future__ import annotations

import ast
import inspect
import re
import textwrap

_INT = re.compile(r"(?<![\w.\[])(\d+)(?![\w.\]])")
_ASSIGN = re.compile(r"^([A-Za-z_]\w*(?:\[\d+\])?) (=|\+=) (.+)$")
_TUPLE = re.compile(r"^((?:dydt\[\d+\], )+dydt\[\d+\]) = (_solve[23])\((.+)\)$")
_RETURN_TUPLE = re.compile(r"^return \((.+)\)$")
_SINCOS = re.compile(r"^(\w+), (\w+) = sincos\((\w+)\)$")


def _trig_c() -> str:
    """generated/trig.py's ``sincos`` in C: its constants from derive/trig.py (C99 reads
    their hex floats as written), its operations in its order (gcc without -march
    fuses none), libm's sin and cos only where it calls them (|x| >= LIMIT, NaN)."""
    from derive.trig import CONSTANTS
    consts = "\n".join(f"#define TS_{name} {bits}" for name, bits, _ in CONSTANTS)
    return consts + r"""
/* musl __sin (with its tail) and __cos on |y0 + y1| <= pi/4: generated/trig.py _kernels */
static inline void ts_kernels(double y0, double y1, double *sk, double *ck)
{
    const double z = y0 * y0, w = z * z;
    const double rs = (TS_S2 + z * (TS_S3 + z * TS_S4)) + (z * w) * (TS_S5 + z * TS_S6);
    const double v = z * y0;
    *sk = y0 - (((z * (0.5 * y1 - v * rs)) - y1) - v * TS_S1);
    const double rc = z * (TS_C1 + z * (TS_C2 + z * TS_C3))
                      + (w * w) * (TS_C4 + z * (TS_C5 + z * TS_C6));
    const double hz = 0.5 * z, wc = 1.0 - hz;
    *ck = wc + (((1.0 - wc) - hz) + (z * rc - y0 * y1));
}
/* generated/trig.py sincos: the kernels alone below SMALL, the reduction below LIMIT */
static inline void ts_sincos(double x, double *s, double *c)
{
    if (fabs(x) < TS_SMALL) { ts_kernels(x, 0.0, s, c); return; }
    if (!(fabs(x) < TS_LIMIT)) { *s = sin(x); *c = cos(x); return; }
    const double n = ((x * TS_INVPIO2) + TS_TOINT) - TS_TOINT;
    const double t = x - n * TS_PIO2_1;
    double w = n * TS_PIO2_2;
    const double r = t - w;
    w = n * TS_PIO2_2T - ((t - r) - w);
    const double y0 = r - w, y1 = (r - y0) - w;
    double sk, ck;
    ts_kernels(y0, y1, &sk, &ck);
    const double m = n - 4.0 * (((0.25 * n) + TS_TOINT) - TS_TOINT);
    const int odd = m == 1.0 || m == -1.0;
    double sv = odd ? ck : sk, cv = odd ? sk : ck;
    *s = (m < 0.0 || m > 1.0) ? -sv : sv;
    *c = (m > 0.0 || m < -1.0) ? -cv : cv;
}
"""


#: the C twin of generated/trig.py's sincos (every C port's sin and cos)
TRIG = _trig_c()

HELPERS = r"""
static inline double ipow2(double x) { return x * x; }
static inline double ipow3(double x) { return x * x * x; }
/* generated _solve3 / _solve2: x of S x = v for a symmetric S (Cramer's rule) */
static inline void solve3(double s00, double s01, double s02, double s11, double s12, double s22,
                          double v0, double v1, double v2, double *x0, double *x1, double *x2)
{
    const double c00 = s11 * s22 - s12 * s12;
    const double c01 = s02 * s12 - s01 * s22;
    const double c02 = s01 * s12 - s02 * s11;
    const double det = s00 * c00 + s01 * c01 + s02 * c02;
    const double c11 = s00 * s22 - s02 * s02;
    const double c12 = s01 * s02 - s00 * s12;
    const double c22 = s00 * s11 - s01 * s01;
    *x0 = (c00 * v0 + c01 * v1 + c02 * v2) / det;
    *x1 = (c01 * v0 + c11 * v1 + c12 * v2) / det;
    *x2 = (c02 * v0 + c12 * v1 + c22 * v2) / det;
}
static inline void solve2(double s00, double s01, double s11, double v0, double v1,
                          double *x0, double *x1)
{
    const double det = s00 * s11 - s01 * s01;
    *x0 = (s11 * v0 - s01 * v1) / det;
    *x1 = (s00 * v1 - s01 * v0) / det;
}
"""


def _powers(expr: str) -> str:
    """``base**n`` (n = 2, 3; base a name, number or parenthesised group) -> ipown(base)."""
    while (i := expr.find("**")) >= 0:
        m = re.match(r"\*\*(\d+)", expr[i:])
        if not m or m.group(1) not in ("2", "3"):
            raise ValueError(f"power {expr[i:i + 8]!r}: only **2 and **3 are printed")
        j = i
        if expr[j - 1] == ")":
            depth = 0
            while True:
                j -= 1
                depth += {")": 1, "(": -1}.get(expr[j], 0)
                if depth == 0:
                    break
            base = expr[j:i]
        else:
            while j > 0 and (expr[j - 1].isalnum() or expr[j - 1] in "_."):
                j -= 1
            base = expr[j:i]
        expr = f"{expr[:j]}ipow{m.group(1)}({base}){expr[i + len(m.group(0)):]}"
    return expr


def expression(expr: str) -> str:
    """One Python expression of a generated kernel as C."""
    expr = re.sub(r"\bmax\(", "fmax(", expr.replace("math.", ""))  # the line's clamp
    if re.search(r"[^\w\s+\-*/().,<>=\[\]]", expr) or re.search(r"\b(and|or|not|if)\b", expr):
        raise ValueError(f"cannot print {expr!r} as C")
    return _INT.sub(r"\1.0", _powers(expr))


def _logical(lines: list) -> list:
    """Physical lines joined into statements (derive/printer.py wraps long ones in parentheses)."""
    out, depth = [], 0
    for raw in lines:
        if depth > 0:
            joint = "" if out[-1].endswith("(") else " "
            out[-1] += joint + raw.strip()
        else:
            out.append(raw)
        depth += raw.count("(") - raw.count(")")
    return out


def function_to_c(fn, name: str, signature: str) -> str:
    """C text of a generated kernel ``fn`` (a numba dispatcher or a function)."""
    src = textwrap.dedent(inspect.getsource(getattr(fn, "py_func", fn)))
    body = ast.parse(src).body[0]
    lines = src.splitlines()[body.body[0].lineno - 1:]
    if isinstance(body.body[0], ast.Expr):  # the docstring
        lines = src.splitlines()[body.body[1].lineno - 1:]
    lines = _logical(lines)
    out = [f"static inline {signature.replace('NAME', name)}", "{"]
    declared, depth_stack = set(), [4]
    for raw in lines:
        if not raw.strip():
            continue
        indent = len(raw) - len(raw.lstrip())
        line, _, comment = raw.strip().partition("  # ")
        if line.startswith("#"):
            out.append(" " * indent + "/* " + line[1:].strip() + " */")
            continue
        while indent < depth_stack[-1]:
            depth_stack.pop()
            if not line.startswith("else:"):
                out.append(" " * depth_stack[-1] + "}")
        pad = " " * indent
        note = f"  /* {comment} */" if comment else ""
        if line.startswith("if ") and line.endswith(":"):
            out.append(f"{pad}if ({expression(line[3:-1])}) {{{note}")
            depth_stack.append(indent + 4)
        elif line == "else:":
            out.append(f"{pad}}} else {{")
            depth_stack.append(indent + 4)
        elif m := _SINCOS.match(line):
            sin_name, cos_name, angle = m.groups()
            declared |= {sin_name, cos_name}
            out.append(f"{pad}double {sin_name}, {cos_name};")
            out.append(f"{pad}ts_sincos({angle}, &{sin_name}, &{cos_name});")
        elif m := _TUPLE.match(line):
            targets = [f"&{t.strip()}" for t in m.group(1).split(",")]
            args = expression(m.group(3))
            out.append(f"{pad}{m.group(2)[1:]}({args}, {', '.join(targets)});")
        elif m := _ASSIGN.match(line):
            target, op, rhs = m.groups()
            decl = ""
            if "[" not in target and op == "=" and target not in declared:
                declared.add(target)
                decl = "double "
            out.append(f"{pad}{decl}{target} {op} {expression(rhs)};{note}")
        else:
            raise ValueError(f"cannot print line {line!r} of {name} as C")
    while len(depth_stack) > 1:
        depth_stack.pop()
        out.append(" " * depth_stack[-1] + "}")
    out.append("}")
    return "\n".join(out)
