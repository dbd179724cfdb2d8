"""What people use instead: sympy.lambdify + numpy, PyDy's generated code, scipy solve_ivp.

All three are built from the same DerivedModel as the numba kernels:

* lambdify: the full 6-state right-hand side as one sympy expression per
  component (Q of drag + Piecewise-gated tether families, λ_j substituted,
  plugged into model.qdd), ``sympy.lambdify(..., modules="numpy")``, default
  options (no cse).
* PyDy: ``pydy.codegen.ode_function_generators.generate_ode_function`` in the
  form M(q) u' = F(q, u), q' = u with M = model.mass_matrix and
  F = Q - f (model.f).  The forcing is the *taut-branch* forcing (both tether
  families always on, no Piecewise/Heaviside): valid for runs where both
  tethers stay taut, which the benchmark checks (no switch located by the
  numba run and λ_j > l_j0 at every output sample).
* solve_ivp: a Python function of (t, y) for the 6-state system the engine
  integrates (the COM orbit of a circular run is a closed form, not integrated).
"""
from __future__ import annotations

import importlib.util

import numpy as np
import sympy as sp

from derive.pipeline import Q_SYMBOLS
from derive.symbols import COORDINATES, PARAMETERS, STATE_SYMBOLS, TETHER_LENGTHS, TETHER_REST

PARAM_SYMBOLS = [p.symbol for p in PARAMETERS]


def forces(model, length_defs, gated=True):
    """Total generalized forces (3 exprs in state symbols), λ_j substituted."""
    Q = [sum((f.Q[k] for f in model.families if f.tether is None), sp.S.Zero) for k in range(3)]
    for j in range(2):
        tq = [sum((f.Q[k] for f in model.families if f.tether == j + 1), sp.S.Zero)
              for k in range(3)]
        lam, rest = TETHER_LENGTHS[j], TETHER_REST[j]
        for k in range(3):
            Q[k] += sp.Piecewise((tq[k], lam > rest), (0, True)) if gated else tq[k]
    subs = {lam: length_defs[lam] for lam in TETHER_LENGTHS}
    return [q.xreplace(subs) for q in Q]


def full_rhs(model, length_defs, gated=True):
    """The 6 components of dy/dt as plain sympy expressions (no cse)."""
    Q = forces(model, length_defs, gated)
    acc = [e.xreplace(dict(zip(Q_SYMBOLS, Q))) for e in model.qdd]
    return list(STATE_SYMBOLS[3:]) + acc


def make_lambdify(model, length_defs):
    """f(*y6, *p) -> list of 6 floats; sympy.lambdify with numpy, default options."""
    exprs = full_rhs(model, length_defs, gated=True)
    return sp.lambdify(list(STATE_SYMBOLS) + PARAM_SYMBOLS, exprs, modules="numpy")


def pydy_generator() -> str:
    """PyDy's fastest backend available here: cython if Cython is installed, else lambdify."""
    return "cython" if importlib.util.find_spec("Cython") else "lambdify"


def make_pydy(model, length_defs, generator=None):
    """PyDy right-hand side rhs(x, t, p) -> x' (6-state), taut-branch forcing."""
    from pydy.codegen.ode_function_generators import generate_ode_function
    from sympy.physics.mechanics import dynamicsymbols

    generator = generator or pydy_generator()
    u = dynamicsymbols("u_dx u_dy u_th")
    sub = dict(zip(STATE_SYMBOLS, list(COORDINATES) + list(u)))
    Q = forces(model, length_defs, gated=False)
    F = sp.Matrix([Q[k] - model.f[k] for k in range(3)]).xreplace(sub)
    M = model.mass_matrix.xreplace(sub)
    kw = dict(constants=PARAM_SYMBOLS, mass_matrix=M, coordinate_derivatives=sp.Matrix(u),
              constants_arg_type="array")
    try:
        f = generate_ode_function(F, list(COORDINATES), list(u), generator=generator, **kw)
    except Exception:  # noqa: BLE001  (cython backend without a working toolchain)
        if generator == "lambdify":
            raise
        generator = "lambdify"
        f = generate_ode_function(F, list(COORDINATES), list(u), generator=generator, **kw)
    return f, generator


def ivp_fun_lambdify(f, p):
    """solve_ivp fun(t, y) for the 6-state system with the lambdified attitude RHS."""
    pl = [float(v) for v in p]

    def fun(t, y):
        return np.array(f(*y.tolist(), *pl), dtype=float)
    return fun


def ivp_fun_pydy(f, p):
    """solve_ivp fun(t, y) for the 6-state system with PyDy's attitude RHS."""

    def fun(t, y):
        return np.array(f(y, t, p), dtype=float)
    return fun


def ivp_fun_numba(derivative, p):
    """solve_ivp fun(t, y) calling the compiled tethersim.engine.dynamics.derivative.

    derivative: its entry point for one model (bench/engine_bench.derivative_entry),
    called as derivative(model, air, t, y, p, pw, dydt).
    """
    from tethersim.model.air.vector import uniform_air
    pw, air = p.copy(), uniform_air()

    def fun(t, y):
        dydt = np.empty(y.size)
        derivative(0, air, t, y, p, pw, dydt)
        return dydt
    return fun
