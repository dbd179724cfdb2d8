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


EXCESS_RTOL = 1e-6  # RK4 matches e^z to O(z^5): below this the excess is truncation, not instability


def taut_tether_modes(sat: Satellite) -> np.ndarray:
    """Eigenvalues of the balloon bouncing on both tethers taut, λ = −ζ ± i w.

    The tether force grows at dT/dλ = E_j / l_j0 once taut, so the balloon
    (mass m3) has w² <= (E1/l10 + E2/l20)/m3 and damping rate ζ = (c1+c2)/(2 m3).
    A tether that is slack at the initial state is taut later, so the step must
    support this mode too.
    """
    k = sat.E1 / sat.l10 + sat.E2 / sat.l20
    zeta = (sat.c1 + sat.c2) / (2 * sat.m3)
    w2 = k / sat.m3 - zeta**2
    if w2 >= 0:
        return np.array([complex(-zeta, np.sqrt(w2)), complex(-zeta, -np.sqrt(w2))])
    r = np.sqrt(-w2)
    return np.array([-zeta + r, -zeta - r], dtype=complex)


def rk4_amplification(sat: Satellite, h: float, model: str = "derived", state=None) -> float:
    """Largest spurious growth factor of RK4 over the linear modes at ``state``.

    For each eigenvalue λ of the Jacobian (default state: the initial one),
    |R(hλ)| / max(1, |e^{hλ}|): above 1 the integrator amplifies a mode that
    the true linear dynamics does not (modes that physically grow, Re λ > 0,
    are not blamed on the step).
    """
    lam = np.concatenate([
        np.linalg.eigvals(attitude_jacobian(sat, sat.initial if state is None else state, model)),
        taut_tether_modes(sat)])
    z = h * lam
    R = np.abs(1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24)
    exact = np.maximum(1.0, np.exp(z.real))
    return float(np.max(R / (exact * (1 + EXCESS_RTOL))))


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
