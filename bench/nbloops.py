"""Numba loops that call the generated kernels N times (no Python call overhead).

The same tiny explicit-Euler feedback as the C loops in cref.py (y += eps*dydt
after every call) keeps each call dependent on the previous one, so neither
compiler can hoist, vectorise across calls or drop a call.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from tethersim.engine.dynamics import derivative
from tethersim.generated.derived import rhs
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
    """n calls of tethersim.engine.dynamics.derivative (6-state, model 'derived' as a literal)."""
    dydt = np.empty(6)
    acc = 0.0
    for _ in range(n):
        derivative(0, AIR, 0.0, y, p, pw, dydt)
        for k in range(6):
            y[k] += eps * dydt[k]
        acc += dydt[5]
    return acc
