"""C reference of the 'derived' model, generated at run time from the same derivation.

The right-hand side is printed from the *same* cse'd blocks that
derive/codegen.py prints as numba code (same expressions through
``codegen._prepare``, same ``sp.cse(..., numbered_symbols(prefix),
order="canonical")`` call, same tether gating), only with a C printer; the
numba print of each block is checked against ``codegen._block``.  Around it
sit hand-written C ports of the runtime's drivers:

  derivative   the model's own state, tethersim/engine/dynamics.py (the COM orbit of a
               circular run is a closed form, not integrated, as in the engine)
  rk4_run      tethersim/engine/integrators/rk4.py (locate=False path)
  dop853_run   tethersim/engine/integrators/dop853.py with steps.py and switching.py
               (same tableau, error norm, step control, dense output, event
               location and nfev accounting)

Everything is written to bench/_build/ (git-ignored) and built with gcc into a
shared library loaded with ctypes.
"""
from __future__ import annotations

import ctypes
import hashlib
import subprocess
from functools import cache
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.precedence import precedence
from timing import cpu_clock

from derive import codegen
from derive.pipeline import Q_SYMBOLS
from derive.printer import NumbaPrinter
from derive.symbols import PARAMETERS, STATE_NAMES, TETHER_LENGTHS

BUILD = Path(__file__).resolve().parent / "_build"
#: gcc flags of each build of the port: plain -O3 (no fused multiply-adds, the same
#: numbers as numba's loops) and -O3 -march=native (the lean floor)
FLAGS = {"O3": ("-O3",), "native": ("-O3", "-march=native")}
IND = "    "


class CPrinter(C99CodePrinter):
    """C99 printer writing small integer powers as products, as one would by hand."""

    def _print_InverseSqrtMinusOne(self, expr):
        return f"expm1(-0.5*log1p({self._print(expr.args[0])}))"

    def _print_InverseCubeMinusOne(self, expr):
        return f"expm1(-1.5*log1p({self._print(expr.args[0])}))"

    def _print_Pow(self, expr):
        b, e = expr.base, expr.exp
        if e.is_Integer and 2 <= abs(int(e)) <= 4:
            base = self.parenthesize(b, precedence(expr))
            prod = "*".join([base] * abs(int(e)))
            return f"({prod})" if e > 0 else f"(1.0/({prod}))"
        if e == sp.Rational(-1, 2):
            return f"(1.0/sqrt({self._print(b)}))"
        return super()._print_Pow(expr)


def _c_block(targets, exprs, prefix, indent, op="="):
    """C twin of derive.codegen._block: identical cse, C syntax.

    Also returns the numba-printed lines of the same cse, which must equal
    codegen._block's output (checked by check_same_cse): C and numba then
    evaluate the same straight-line code.
    """
    cp, npr = CPrinter(), NumbaPrinter()
    prepared = [codegen._prepare(e) for e in exprs]
    repl, reduced = sp.cse(prepared, symbols=sp.numbered_symbols(prefix), order="canonical")
    c = [f"{indent}const double {s} = {cp.doprint(v)};" for s, v in repl]
    py = [f"{indent}{s} = {npr.doprint(v)}" for s, v in repl]
    for tgt, e in zip(targets, reduced):
        c.append(f"{indent}{tgt} {op} {cp.doprint(e)};")
        py.append(f"{indent}{tgt} {op} {npr.doprint(e)}")
    return c, py, len(repl)


def rhs_c_body(model, length_defs):
    """Body of ``rhs6`` in C, mirroring codegen.rhs_source block for block.

    Returns (C lines, [(block args, numba-printed lines)], number of cse temporaries).
    """
    i1, i2 = IND, IND * 2
    cp = CPrinter()
    c = [f"{i1}const double {n} = y[{i}];" for i, n in enumerate(STATE_NAMES)]
    c += [f"{i1}const double {p.name} = p[{i}];" for i, p in enumerate(PARAMETERS)]
    c += [f"{i1}double sin_theta, cos_theta;", f"{i1}ts_sincos(theta, &sin_theta, &cos_theta);"]
    qnames = [str(q) for q in Q_SYMBOLS]
    blocks, n_tmp = [], 0
    drag, _ = codegen._sum_families(model, None)
    c.append(f"{i1}double {', '.join(qnames)};")
    bc, bp, n = _c_block(qnames, drag, "d", i1)
    c += bc
    blocks.append(((qnames, drag, "d", i1, "="), bp))
    n_tmp += n
    for j in range(2):
        tq, _ = codegen._sum_families(model, j + 1)
        lam = TETHER_LENGTHS[j]
        c.append(f"{i1}const double {lam} = {cp.doprint(codegen._prepare(length_defs[lam]))};")
        c.append(f"{i1}if ({codegen.gate(j)}) {{")
        bc, bp, n = _c_block(qnames, tq, f"t{j + 1}_", i2, op="+=")
        c += bc + [f"{i1}}}"]
        blocks.append(((qnames, tq, f"t{j + 1}_", i2, "+="), bp))
        n_tmp += n
    c += [f"{i1}dydt[{k}] = {STATE_NAMES[k + 3]};" for k in range(3)]
    acc = [codegen._prepare(e) for e in model.qdd]
    targets = [f"dydt[{k + 3}]" for k in range(3)]
    bc, bp, n = _c_block(targets, acc, "a", i1)
    c += bc
    blocks.append(((targets, acc, "a", i1, "="), bp))
    n_tmp += n
    return c, blocks, n_tmp


def check_same_cse(blocks) -> None:
    """Each block's numba print of our cse equals derive.codegen._block's output."""
    for (targets, exprs, prefix, indent, op), ours in blocks:
        theirs = codegen._block(targets, exprs, prefix, indent, op=op)
        if ours != theirs:
            raise AssertionError(f"cse of block {prefix!r} differs from derive.codegen._block")


def generated_is_current(model, length_defs, generated_file: Path) -> bool:
    """Is generated/derived.py's rhs the one derive/codegen.py prints now?"""
    from derive.emit import printing
    src = "\n".join(codegen.rhs_source(model, printing(model)))
    return src in generated_file.read_text()


def _carr(name, arr) -> str:
    arr = np.asarray(arr, dtype=np.float64)
    if arr.ndim == 1:
        return f"static const double {name}[{arr.size}] = {{{', '.join(repr(float(v)) for v in arr)}}};"
    rows = ",\n    ".join("{" + ", ".join(repr(float(v)) for v in r) + "}" for r in arr)
    return f"static const double {name}[{arr.shape[0]}][{arr.shape[1]}] = {{\n    {rows}}};"


C_TEMPLATE = r"""/* GENERATED by bench/cref.py at benchmark time - do not edit, not committed.
 * C reference of model 'derived': the cse'd right-hand side printed from the same
 * derivation as generated/derived.py, plus C ports of the runtime integrators. */
#include <math.h>
#include <stdint.h>
#include <string.h>

@TRIG@

#define NA @NA@   /* the model's own state */
#define NS NA     /* the integrated state: the model's own, as the engine's */
#define N_STAGES 12
#define N_K 16

@TABLEAU@

@RHS_FUNCTION@

/* tethersim/engine/dynamics.py:derivative (uniform density): the model's rhs */
static inline void derivative(double t, const double *y, const double *p, double *dydt)
{
    rhs6(t, y, p, dydt);
}

@MARGINS_FUNCTION@

void c_rhs6(const double *y, const double *p, double *dydt) { rhs6(0.0, y, p, dydt); }
void c_derivative(double t, const double *y, const double *p, double *dydt) { derivative(t, y, p, dydt); }

/* n calls with a tiny explicit-Euler feedback so no call can be hoisted or skipped */
double c_rhs6_loop(double *y, const double *p, long n, double eps)
{
    double dydt[NA], acc = 0.0;
    for (long i = 0; i < n; i++) {
        rhs6(0.0, y, p, dydt);
        for (int k = 0; k < NA; k++) y[k] += eps * dydt[k];
        acc += dydt[NA - 1];
    }
    return acc;
}

double c_derivative_loop(double *y, const double *p, long n, double eps)
{
    double dydt[NS], acc = 0.0;
    for (long i = 0; i < n; i++) {
        derivative(0.0, y, p, dydt);
        for (int k = 0; k < NS; k++) y[k] += eps * dydt[k];
        acc += dydt[NA - 1];
    }
    return acc;
}

/* ---------------- RK4: tethersim/engine/integrators/steps.py:rk4_step, rk4.py:rk4_run */
static void rk4_step(double t, const double *y, double h, const double *p,
                     double work[5][NS], double *y_new)
{
    double *k1 = work[0], *k2 = work[1], *k3 = work[2], *k4 = work[3], *ys = work[4];
    derivative(t, y, p, k1);
    for (int i = 0; i < NS; i++) ys[i] = y[i] + 0.5 * h * k1[i];
    derivative(t + 0.5 * h, ys, p, k2);
    for (int i = 0; i < NS; i++) ys[i] = y[i] + 0.5 * h * k2[i];
    derivative(t + 0.5 * h, ys, p, k3);
    for (int i = 0; i < NS; i++) ys[i] = y[i] + h * k3[i];
    derivative(t + h, ys, p, k4);
    for (int i = 0; i < NS; i++)
        y_new[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

int c_rk4_run(double t0, double *y, double h, long n_steps, long stride, const double *p,
              double *out_t, double *out_y, long row0, long *rows)
{
    double work[5][NS], y_new[NS];
    long row = row0;
    for (long k = 1; k <= n_steps; k++) {
        const double t = t0 + (k - 1) * h;
        rk4_step(t, y, h, p, work, y_new);
        memcpy(y, y_new, sizeof y_new);
        if (k % stride == 0) {
            out_t[row] = t0 + k * h;
            memcpy(out_y + row * NS, y, NS * sizeof(double));
            row++;
        }
        for (int i = 0; i < NS; i++)
            if (!isfinite(y[i])) { *rows = row - row0; return 1; }
    }
    *rows = row - row0;
    return 0;
}

/* ---------------- DOP853: tethersim/engine/integrators/steps.py, dop853.py, switching.py */
#define SAFETY 0.9
#define MIN_FACTOR 0.2
#define MAX_FACTOR 10.0
#define ERROR_EXPONENT (-1.0 / 8.0)
#define RTOL_TAU 1e-12
#define MAX_ITER 60

static void dop853_step(double t, const double *y, const double *f, double h, const double *p,
                        double K[][NS], double *ys, double *y_new)
{
    memcpy(K[0], f, NS * sizeof(double));
    for (int s = 1; s < N_STAGES; s++) {
        for (int i = 0; i < NS; i++) {
            double acc = 0.0;
            for (int j = 0; j < s; j++) acc += A_[s][j] * K[j][i];
            ys[i] = y[i] + h * acc;
        }
        derivative(t + C_[s] * h, ys, p, K[s]);
    }
    for (int i = 0; i < NS; i++) {
        double acc = 0.0;
        for (int j = 0; j < N_STAGES; j++) acc += B_[j] * K[j][i];
        y_new[i] = y[i] + h * acc;
    }
    derivative(t + h, y_new, p, K[N_STAGES]);
}

static double dop853_error_norm(double K[][NS], double h, const double *y, const double *y_new,
                                double rtol, double atol)
{
    double e5 = 0.0, e3 = 0.0;
    for (int i = 0; i < NS; i++) {
        const double scale = atol + fmax(fabs(y[i]), fabs(y_new[i])) * rtol;
        double s5 = 0.0, s3 = 0.0;
        for (int j = 0; j < N_STAGES + 1; j++) {
            s5 += E5_[j] * K[j][i];
            s3 += E3_[j] * K[j][i];
        }
        e5 += (s5 / scale) * (s5 / scale);
        e3 += (s3 / scale) * (s3 / scale);
    }
    if (e5 == 0.0 && e3 == 0.0) return 0.0;
    return fabs(h) * e5 / sqrt((e5 + 0.01 * e3) * NS);
}

static void dop853_dense(double t, const double *y, const double *y_new, double h, const double *p,
                         double K[][NS], double *ys, double F[7][NS])
{
    for (int s = N_STAGES + 1; s < N_K; s++) {
        for (int i = 0; i < NS; i++) {
            double acc = 0.0;
            for (int j = 0; j < s; j++) acc += A_[s][j] * K[j][i];
            ys[i] = y[i] + h * acc;
        }
        derivative(t + C_[s] * h, ys, p, K[s]);
    }
    for (int i = 0; i < NS; i++) {
        const double dy = y_new[i] - y[i];
        F[0][i] = dy;
        F[1][i] = h * K[0][i] - dy;
        F[2][i] = 2.0 * dy - h * (K[N_STAGES][i] + K[0][i]);
        for (int r = 0; r < 4; r++) {
            double acc = 0.0;
            for (int j = 0; j < N_K; j++) acc += D_[r][j] * K[j][i];
            F[3 + r][i] = h * acc;
        }
    }
}

static void dop853_interpolate(double F[7][NS], const double *y, double x, double *out)
{
    for (int i = 0; i < NS; i++) {
        double acc = 0.0;
        for (int k = 0; k < 7; k++) {
            acc += F[6 - k][i];
            acc *= (k % 2 == 0) ? x : 1.0 - x;
        }
        out[i] = acc + y[i];
    }
}

static double initial_step(double t0, const double *y0, const double *f0, const double *p,
                           double rtol, double atol, double t_end)
{
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, y1[NS], f1[NS];
    for (int i = 0; i < NS; i++) {
        const double sc = atol + fabs(y0[i]) * rtol;
        d0 += (y0[i] / sc) * (y0[i] / sc);
        d1 += (f0[i] / sc) * (f0[i] / sc);
    }
    d0 = sqrt(d0 / NS);
    d1 = sqrt(d1 / NS);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0 = fmin(h0, t_end - t0);
    for (int i = 0; i < NS; i++) y1[i] = y0[i] + h0 * f0[i];
    derivative(t0 + h0, y1, p, f1);
    for (int i = 0; i < NS; i++) {
        const double sc = atol + fabs(y0[i]) * rtol;
        d2 += ((f1[i] - f0[i]) / sc) * ((f1[i] - f0[i]) / sc);
    }
    d2 = sqrt(d2 / NS) / h0;
    double h1;
    if (d1 <= 1e-15 && d2 <= 1e-15) h1 = fmax(1e-6, h0 * 1e-3);
    else h1 = pow(0.01 / fmax(d1, d2), 1.0 / 9.0);
    return fmin(fmin(100 * h0, h1), t_end - t0);
}

static int crossed(const double *g0, const double *g1)
{
    for (int j = 0; j < 2; j++)
        if ((g0[j] > 0.0) != (g1[j] > 0.0)) return j;
    return -1;
}

static void trial(double t, const double *y, const double *f, double tau, const double *p,
                  double K[][NS], double *ys, double *y_new, double *g)
{
    dop853_step(t, y, f, tau, p, K, ys, y_new);
    tether_margins(y_new, p, g);
}

static double locate_switch(double t, const double *y, const double *f, double h, const double *p,
                            double K[][NS], double *ys, double *y_new, const double *g0, double *g1)
{
    double tau_best = h, g[2] = {g1[0], g1[1]};
    for (int j = 0; j < 2; j++) {
        if ((g0[j] > 0.0) == (g1[j] > 0.0)) continue;
        double lo = 0.0, hi = tau_best, f_lo = g0[j];
        trial(t, y, f, hi, p, K, ys, y_new, g);
        double f_hi = g[j];
        if ((f_hi > 0.0) == (f_lo > 0.0)) continue;
        int side = 0;
        for (int it = 0; it < MAX_ITER; it++) {
            if (hi - lo <= RTOL_TAU * h) break;
            double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            if (!(lo < mid && mid < hi)) mid = 0.5 * (lo + hi);
            trial(t, y, f, mid, p, K, ys, y_new, g);
            const double f_mid = g[j];
            if ((f_mid > 0.0) == (f_lo > 0.0)) {
                lo = mid; f_lo = f_mid;
                if (side == -1) f_hi *= 0.5;
                side = -1;
            } else {
                hi = mid; f_hi = f_mid;
                if (side == 1) f_lo *= 0.5;
                side = 1;
            }
        }
        tau_best = hi;
    }
    trial(t, y, f, tau_best, p, K, ys, y_new, g1);
    return tau_best;
}

/* res[0] = t reached, res[1] = next step, res[2] = next output index; returns status */
int c_dop853_run(double t0, double t_end, double *y, double h, const double *p, double rtol,
                 double atol, int locate, const double *out_t, long n_out, double *out_y,
                 long i_out, long max_steps, int64_t *counters, double *res)
{
    double K[N_K][NS], ys[NS], y_new[NS], f[NS], F[7][NS], g0[2], g1[2];
    double t = t0, h_next = 0.0;
    int status = 0;
    derivative(t, y, p, f);
    counters[0] += 1;
    if (h <= 0.0) {
        h = initial_step(t, y, f, p, rtol, atol, t_end);
        counters[0] += 1;
    }
    long steps = 0;
    while (t < t_end) {
        if (steps >= max_steps) { status = 3; goto done; }
        steps++;
        const double min_step = 10.0 * fabs(nextafter(t, INFINITY) - t);
        int rejected = 0;
        double h_try;
        for (;;) {
            if (h < min_step) { status = 2; goto done; }
            h_try = fmin(h, t_end - t);
            dop853_step(t, y, f, h_try, p, K, ys, y_new);
            counters[0] += 12;
            const double err = dop853_error_norm(K, h_try, y, y_new, rtol, atol);
            if (err < 1.0) {
                double factor = err == 0.0 ? MAX_FACTOR
                                           : fmin(MAX_FACTOR, SAFETY * pow(err, ERROR_EXPONENT));
                if (rejected) factor = fmin(1.0, factor);
                h_next = h_try * factor;
                break;
            }
            h = h_try * fmax(MIN_FACTOR, SAFETY * pow(err, ERROR_EXPONENT));
            rejected = 1;
            counters[2] += 1;
        }
        if (locate) {
            tether_margins(y, p, g0);
            tether_margins(y_new, p, g1);
            if (crossed(g0, g1) >= 0) {
                h_try = locate_switch(t, y, f, h_try, p, K, ys, y_new, g0, g1);
                counters[3] += 1;
            }
        }
        counters[1] += 1;
        const double t_new = t + h_try;
        if (i_out < n_out && out_t[i_out] <= t_new) {
            /* the 3 extra stages of the interpolant only when an output falls in the step */
            dop853_dense(t, y, y_new, h_try, p, K, ys, F);
            counters[0] += 3;
        }
        while (i_out < n_out && out_t[i_out] <= t_new) {
            dop853_interpolate(F, y, (out_t[i_out] - t) / h_try, out_y + i_out * NS);
            i_out++;
        }
        memcpy(y, y_new, sizeof y_new);
        memcpy(f, K[N_STAGES], sizeof f);
        t = t_new;
        h = h_next;
        for (int i = 0; i < NS; i++)
            if (!isfinite(y[i])) { status = 1; goto done; }
    }
    counters[4] += steps;
done:
    res[0] = t;
    res[1] = h;
    res[2] = (double)i_out;
    return status;
}
"""


DERIVED_MARGINS = """static inline void tether_margins(const double *y, const double *p, double *g)
{
    double s, c;
    ts_sincos(y[2], &s, &c);
    const double a = p[@P_A@], b = p[@P_B@];
    g[0] = hypot(b * s - y[0], b * c - y[1]) - p[@P_L10@];
    g[1] = hypot(-a * s - y[0], -a * c - y[1]) - p[@P_L20@];
}"""


def _fill(rhs_function: str, margins_function: str, na: int) -> str:
    import pyc

    from tethersim.engine.integrators import dop853_tableau as tab

    tableau = "\n".join([_carr("C_", tab.C), _carr("A_", tab.A), _carr("B_", tab.B),
                         _carr("E3_", tab.E3), _carr("E5_", tab.E5), _carr("D_", tab.D)])
    src = C_TEMPLATE
    for key, val in (("@TRIG@", pyc.TRIG), ("@TABLEAU@", tableau), ("@RHS_FUNCTION@", rhs_function),
                     ("@MARGINS_FUNCTION@", margins_function), ("@NA@", str(na))):
        src = src.replace(key, val)
    return src


def c_source(model, length_defs) -> tuple[str, dict]:
    """The C file's text and facts about it (cse temporaries; same-cse check done)."""
    from tethersim.generated import layout

    body, blocks, n_tmp = rhs_c_body(model, length_defs)
    check_same_cse(blocks)
    rhs = ("/* model 'derived', same cse blocks as generated/derived.py:rhs */\n"
           "static inline void rhs6(double t, const double *y, const double *p, double *dydt)\n"
           "{\n" + "\n".join(body) + "\n}")
    margins = DERIVED_MARGINS
    for key, val in (("@P_A@", layout.P_A), ("@P_B@", layout.P_B), ("@P_L10@", layout.P_L10),
                     ("@P_L20@", layout.P_L20)):
        margins = margins.replace(key, str(val))
    return _fill(rhs, margins, 6), {"cse_temporaries": n_tmp, "same_cse_as_codegen": True}


@cache
def derived_model() -> tuple:
    """(model, tether length definitions) of the 'derived' model, derived once a process
    (derive/, as make derive does)."""
    from derive.kinematics import planar_kinematics
    from derive.model import derive
    from derive.models import BY_NAME
    from derive.pipeline import to_state_symbols

    length_defs = {lam: to_state_symbols(d)
                   for lam, d in planar_kinematics().tether_length_defs.items()}
    return derive(BY_NAME["derived"]), length_defs


@cache
def derived_source() -> tuple[str, dict]:
    """c_source of the 'derived' model, once a process."""
    return c_source(*derived_model())


@cache
def port(tag: str = "O3") -> CRef:
    """The C port of the 'derived' model built with FLAGS[tag], once a process (the
    library itself is cached on disk by build)."""
    return CRef(build(derived_source()[0], FLAGS[tag], tag))


def timed_dop853(lib: CRef, y0, p, t_end: float, n_out: int, rtol: float, atol: float,
                 locate: bool = True) -> tuple:
    """One C dop853_run from t = 0 to ``t_end`` on n_out equal output steps, as the
    bench's numba runs; (thread CPU seconds, counters, final state, output rows)."""
    out_t = np.linspace(0.0, t_end, n_out + 1)[1:]
    out_y = np.empty((n_out, len(y0)))
    y = np.array(y0, dtype=float)
    cnt = np.zeros(5, dtype=np.int64)
    p = np.asarray(p, dtype=float)
    t0 = cpu_clock()
    st = lib.dop853_run(0.0, t_end, y, 0.0, p, rtol, atol, locate, out_t, out_y, 0, 10**9,
                        cnt)[3]
    dt = cpu_clock() - t0
    assert st == 0, st
    return dt, cnt, y, out_y


def c_source_of_generated(name: str) -> str:
    """The C file of a registered circular-orbit model, printed from its generated module
    (bench/pyc.py: the same straight-line code the engine runs, in C)."""
    import pyc

    from tethersim.model.registry import get_model

    m = get_model(name)
    if m.orbit != "circular":
        raise ValueError(f"model {name!r}: the C drivers port the circular-orbit loops only")
    rhs = pyc.HELPERS + "\n" + pyc.function_to_c(
        m.module.rhs, "rhs6", "void NAME(double t, const double *y, const double *p, double *dydt)")
    margins = pyc.function_to_c(m.module.tether_margins, "tether_margins",
                                "void NAME(const double *y, const double *p, double *g)")
    return _fill(rhs, margins, m.n_state)


_D = ctypes.POINTER(ctypes.c_double)
_L = ctypes.POINTER(ctypes.c_long)
_I64 = ctypes.POINTER(ctypes.c_int64)


def build(src: str, flags=("-O3",), tag="O3") -> Path:
    """Write the C file and build a shared library with gcc (cached on content + flags)."""
    BUILD.mkdir(parents=True, exist_ok=True)
    key = hashlib.sha256((src + " ".join(flags)).encode()).hexdigest()[:12]
    c_file = BUILD / f"cref_{tag}.c"
    c_file.write_text(src)
    lib = BUILD / f"libcref_{tag}_{key}.so"
    if not lib.exists():
        tmp = lib.with_suffix(".tmp.so")
        cmd = ["gcc", *flags, "-shared", "-fPIC", "-o", str(tmp), str(c_file), "-lm"]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
        tmp.replace(lib)
    for old in BUILD.glob(f"libcref_{tag}_*.so"):  # builds of older derivations
        if old != lib:
            old.unlink(missing_ok=True)
    return lib


class CRef:
    """ctypes front end of the built library; numpy arrays in, like the numba kernels."""

    def __init__(self, lib_path: Path, na: int = 6):
        self.path, self.na, self.ns = lib_path, na, na
        lib = ctypes.CDLL(str(lib_path))
        lib.c_rhs6.argtypes = [_D, _D, _D]
        lib.c_derivative.argtypes = [ctypes.c_double, _D, _D, _D]
        for fn in (lib.c_rhs6_loop, lib.c_derivative_loop):
            fn.argtypes = [_D, _D, ctypes.c_long, ctypes.c_double]
            fn.restype = ctypes.c_double
        lib.c_rk4_run.argtypes = [ctypes.c_double, _D, ctypes.c_double, ctypes.c_long,
                                  ctypes.c_long, _D, _D, _D, ctypes.c_long, _L]
        lib.c_rk4_run.restype = ctypes.c_int
        lib.c_dop853_run.argtypes = [ctypes.c_double, ctypes.c_double, _D, ctypes.c_double, _D,
                                     ctypes.c_double, ctypes.c_double, ctypes.c_int, _D,
                                     ctypes.c_long, _D, ctypes.c_long, ctypes.c_long, _I64, _D]
        lib.c_dop853_run.restype = ctypes.c_int
        self.lib = lib

    @staticmethod
    def _d(a):
        assert a.dtype == np.float64 and a.flags.c_contiguous
        return a.ctypes.data_as(_D)

    def rhs6(self, y, p):
        out = np.empty(self.na)
        self.lib.c_rhs6(self._d(np.ascontiguousarray(y)), self._d(p), self._d(out))
        return out

    def derivative(self, t, y, p):
        out = np.empty(self.ns)
        self.lib.c_derivative(t, self._d(np.ascontiguousarray(y)), self._d(p), self._d(out))
        return out

    def rhs6_loop(self, y, p, n, eps):
        return self.lib.c_rhs6_loop(self._d(y), self._d(p), n, eps)

    def derivative_loop(self, y, p, n, eps):
        return self.lib.c_derivative_loop(self._d(y), self._d(p), n, eps)

    def rk4_run(self, t0, y, h, n_steps, stride, p, out_t, out_y, row0):
        rows = ctypes.c_long(0)
        st = self.lib.c_rk4_run(t0, self._d(y), h, n_steps, stride, self._d(p), self._d(out_t),
                                self._d(out_y), row0, ctypes.byref(rows))
        return rows.value, 0, st

    def dop853_run(self, t0, t_end, y, h, p, rtol, atol, locate, out_t, out_y, i_out,
                   max_steps, counters):
        res = np.zeros(3)
        assert counters.dtype == np.int64
        st = self.lib.c_dop853_run(t0, t_end, self._d(y), h, self._d(p), rtol, atol, int(locate),
                                   self._d(out_t), out_t.shape[0], self._d(out_y), i_out,
                                   max_steps, counters.ctypes.data_as(_I64), self._d(res))
        return res[0], res[1], int(res[2]), st
