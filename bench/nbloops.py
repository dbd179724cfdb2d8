"""Numba loops that call the generated kernels N times (no Python call overhead).

The same tiny explicit-Euler feedback as the C loops in cref.py (y += eps*dydt
after every call) keeps each call dependent on the previous one, so neither
compiler can hoist, vectorise across calls or drop a call.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.engine.dynamics import derivative
from tethersim.generated.derived import rhs
from tethersim.generated.derived import rhs as derived_rhs
from tethersim.generated.layout import P_MU
from tethersim.model.air.vector import uniform_air

AIR = uniform_air()


@njit(cache=False)
def rhs6_loop(y, p, n, eps):
    """n calls of generated.derived.rhs (6-state); y advanced in place."""
    dydt = np.empty(6)
    acc = 0.0
    for _ in range(n):
        rhs(0.0, y, p, dydt)
        for k in range(6):
            y[k] += eps * dydt[k]
        acc += dydt[5]
    return acc


@njit(cache=False)
def derivative_loop(y, p, pw, n, eps):
    """n calls of tethersim.engine.dynamics.derivative (10-state, model 'derived' as a literal)."""
    dydt = np.empty(10)
    acc = 0.0
    for _ in range(n):
        derivative(0, AIR, 0.0, y, p, pw, dydt)
        for k in range(10):
            y[k] += eps * dydt[k]
        acc += dydt[5]
    return acc


@njit(cache=False)
def _derivative_fixed_model(t, y, p, dydt):
    """Diagnostic twin of tethersim.engine.dynamics.derivative with the model fixed at
    compile time (no cfg, no runtime model dispatch): shows what the dispatch costs."""
    derived_rhs(t, y[:6], p, dydt[:6])
    X, Y = y[6], y[7]
    r = math.hypot(X, Y)
    k = -p[P_MU] / (r * r * r)
    dydt[6] = y[8]
    dydt[7] = y[9]
    dydt[8] = k * X
    dydt[9] = k * Y


@njit(cache=False)
def derivative_fixed_loop(y, p, n, eps):
    """n calls of _derivative_fixed_model (10-state, no dispatch)."""
    dydt = np.empty(10)
    acc = 0.0
    for _ in range(n):
        _derivative_fixed_model(0.0, y, p, dydt)
        for k in range(10):
            y[k] += eps * dydt[k]
        acc += dydt[5]
    return acc
