"""Linearised step-size guidance for RK4.

The Jacobian of the attitude state derivative at a state is taken by central
differences of the generated right-hand side (a generated Jacobian is planned,
issue 5); RK4 multiplies each linear mode by R(hλ) = 1 + z + z²/2 + z³/6 + z⁴/24,
z = hλ, and is stable when |R| <= 1 for every eigenvalue λ.  For an undamped
oscillation of angular frequency w that means h w <= 2√2 ≈ 2.83.
"""
from __future__ import annotations

import numpy as np

from generated import dispatch

from .models import model_index
from .satellite import Satellite, parameter_vector


def attitude_jacobian(sat: Satellite, state, model: str = "derived") -> np.ndarray:
    """∂(dy/dt)/∂y (6x6) of the attitude state at ``state`` by central differences."""
    p = parameter_vector(sat)
    y = np.asarray(state, dtype=float)[:6]
    m = model_index(model)
    J = np.empty((6, 6))
    a, b = np.empty(6), np.empty(6)
    for i in range(6):
        d = 1e-6 * max(1.0, abs(y[i]))
        e = np.zeros(6)
        e[i] = d
        dispatch.rhs(m, 0.0, y + e, p, a)
        dispatch.rhs(m, 0.0, y - e, p, b)
        J[:, i] = (a - b) / (2 * d)
    return J


def rk4_amplification(sat: Satellite, h: float, model: str = "derived", state=None) -> float:
    """Largest |R(hλ)| over the eigenvalues of the Jacobian at ``state`` (default: initial)."""
    lam = np.linalg.eigvals(attitude_jacobian(sat, sat.initial if state is None else state, model))
    z = h * lam
    return float(np.max(np.abs(1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24)))


def rk4_max_step(sat: Satellite, model: str = "derived", state=None) -> float:
    """Largest RK4 step [s] with |R(hλ)| <= 1 for every mode (bisection)."""
    lo, hi = 0.0, 1.0
    while rk4_amplification(sat, hi, model, state) <= 1.0 and hi < 1e6:
        lo, hi = hi, 2 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if rk4_amplification(sat, mid, model, state) <= 1.0:
            lo = mid
        else:
            hi = mid
    return lo
