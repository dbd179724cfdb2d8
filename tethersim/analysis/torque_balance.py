"""The θ = 0 torque balance: why the stable band lies at E2/E1 ≈ b/a.

The balloon's equilibrium for a boom held at pitch θ (:class:`PitchTorque`, also
the quasi-static torque g(θ) that tethersim.analysis.predict walks along), the
terms of the pitch balance at θ = 0 (Eqs TB1-TB5 of docs/torque-balance.md) and
the E2 that balances them exactly (:func:`balanced_E2`).
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.equilibrium import RESIDUAL_TOL
from tethersim.engine.balloon_rest import balloon_rest
from tethersim.engine.integrators.select import specialised
from tethersim.generated.layout import (
    P_A,
    P_A1,
    P_A2,
    P_B,
    P_C1,
    P_C2,
    P_CD,
    P_E1,
    P_E2,
    P_L10,
    P_L20,
    P_OMEGA,
    P_OMEGA_EARTH,
    P_R0,
    P_RHO1,
    P_RHO2,
)
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import DEFAULT_MODEL, KERNELS, THESIS_VARIANTS, model_index
from tethersim.model.satellite import Satellite

NEWTON_MAX = 50  # iterations of the balloon's 2-state Newton solve
NEWTON_STEP_TOL = 1e-11  # m: converged when the Newton step is this small...
BALANCE_RESIDUAL_TOL = 1e-15  # SI: largest |q̈| accepted by balanced_E2 (θ exact to ~1e-10 rad)
# torque of the dampers at rest, by model: the thesis damper −c_j (ṙ3 − ṙ_end) (Eqs
# 3.43-3.44) resists the rigid rotation ω ẑ of the formation; the printed Eq 3.50 adds
# the constant erratum torque −c2 a (a + b) ω (docs/errata.md E1); the Kelvin-Voigt
# variant (objective-damper) exerts nothing at rest.
_DAMPER_AT_REST = {"derived": "thesis", "exact-gravity": "thesis", "printed": "printed",
                   "objective-damper": "none"}


# --- the quasi-static pitch torque g(θ) --------------------------------------------
class PitchTorque:
    """g(θ) = θ̈ [rad/s²] with the balloon at rest at its equilibrium for fixed θ.

    The balloon's (δx, δy) [m] solves δẍ = δÿ = 0 (Eqs 3.48-3.49 as derived) by
    Newton's method on the generated Jacobian (compiled:
    tethersim.engine.balloon_rest).  Each solve starts from the last solution, which
    continues it along θ.
    """

    def __init__(self, sat: Satellite, model: str, trail=None):
        self.m = model_index(model, THESIS_VARIANTS, "the torque balance")
        self.p = parameter_vector(sat, model)
        self.y = np.zeros(6)
        self.d = np.empty(6)
        self.J = np.empty((6, 6))
        self.trail = np.array(trail if trail is not None else sat.initial[:2], dtype=float)
        # the compiled entry, picked once: the walk of tethersim.analysis.predict calls it
        # ~60 times a grid point
        self._solve = specialised(balloon_rest, self.m,
                                  (0.0, self.trail, self.y, self.p, self.d, self.J, NEWTON_MAX,
                                   NEWTON_STEP_TOL, RESIDUAL_TOL), loud=False)

    def balloon(self, theta: float):
        """(δx, δy) [m] of the balloon's equilibrium at pitch θ, or None."""
        if not self._solve(self.m, float(theta), self.trail, self.y, self.p, self.d, self.J,
                           NEWTON_MAX, NEWTON_STEP_TOL, RESIDUAL_TOL):
            return None
        return float(self.trail[0]), float(self.trail[1])

    def __call__(self, theta: float) -> float:
        """g(θ) [rad/s²]; NaN where the balloon has no equilibrium."""
        if self.balloon(theta) is None:
            return math.nan
        return float(self.d[5])  # rhs at the converged state (balloon() evaluated it)



# --- torque balance: E2/E1 ≈ b/a (docs/torque-balance.md) ---------------------------
def balloon_trail_at_zero_pitch(sat: Satellite, model: str = DEFAULT_MODEL, guess=None):
    """(δx, δy) [m] of the balloon's equilibrium with the boom held at θ = 0.

    Solves δẍ = δÿ = 0 (Eqs 3.48-3.49) at θ = 0 and zero rates, from ``guess``
    (default: the initial δx, δy).  Raises RuntimeError if there is none.
    """
    trail = PitchTorque(sat, model, guess).balloon(0.0)
    if trail is None:
        raise RuntimeError(f"{sat.name}: no balloon equilibrium at theta = 0")
    return trail


def torque_balance_terms(sat: Satellite, delta_x: float, delta_y: float,
                         model: str = DEFAULT_MODEL) -> dict:
    """The terms of the θ = 0 torque balance (docs/torque-balance.md, Eqs TB1-TB5).

    At θ = 0, with the balloon at rest at (δx, δy) [m] and λ1 = √(δx² + (b − δy)²),
    λ2 = √(δx² + (a + δy)²) [m], the pitch equation holds when (TB3)

        a T2 δx/λ2 = b T1 δx/λ1 + (b D1 − a D2) + M_c,   T_j = E_j (λ_j/l_j0 − 1),

    so that (TB4)

        E2/E1 = (b/a)(λ2/λ1)(λ1/l10 − 1)/(λ2/l20 − 1)
                + λ2 (b D1 − a D2 + M_c) / (a δx E1 (λ2/l20 − 1)).

    Returns b_over_a, leading (TB5: (b/a)(δx/l10 − 1)/(δx/l20 − 1), = b/a when l10 =
    l20), second_order (TB6, the expansion to (h/δx)²), geometric (the first term of
    TB4), drag_torque b D1 − a D2 [N m], damper_torque M_c [N m], ratio (TB4) and
    lambda1, lambda2 [m].
    """
    p = parameter_vector(sat, model)
    a, b, l1, l2 = p[P_A], p[P_B], p[P_L10], p[P_L20]
    dx, dy = float(delta_x), float(delta_y)
    h1, h2 = b - dy, a + dy
    lam1, lam2 = math.hypot(dx, h1), math.hypot(dx, h2)
    eps1, eps2 = lam1 / l1 - 1.0, lam2 / l2 - 1.0
    w, we, r0 = p[P_OMEGA], p[P_OMEGA_EARTH], p[P_R0]
    # end-body drag at rest, θ = 0: air speed (ω − ω_E)(r0 + y_i), y1 = b, y2 = −a (Eq 3.33)
    d1 = 0.5 * p[P_CD] * p[P_RHO1] * p[P_A1] * ((w - we) * (r0 + b)) ** 2
    d2 = 0.5 * p[P_CD] * p[P_RHO2] * p[P_A2] * ((w - we) * (r0 - a)) ** 2
    kind = _DAMPER_AT_REST.get(model)
    if kind is None:
        model_index(model, THESIS_VARIANTS, "the torque balance")
        raise ValueError(f"model {model!r}: no torque-balance formula for its dampers")
    c1, c2 = p[P_C1], p[P_C2]
    m_c = 0.0 if kind == "none" else w * (c1 * b * h1 + c2 * a * h2)
    if kind == "printed":
        m_c -= w * c2 * a * (a + b)
    geometric = (b / a) * (lam2 / lam1) * eps1 / eps2
    E1 = p[P_E1]
    extra = lam2 * (b * d1 - a * d2 + m_c) / (a * dx * eps2 * E1) if E1 > 0 else math.inf
    lead = (b / a) * (dx / l1 - 1.0) / (dx / l2 - 1.0)
    second = lead * (1.0 + (h2**2 - h1**2) / (2 * dx**2) + h1**2 / (2 * dx * (dx - l1))
                     - h2**2 / (2 * dx * (dx - l2)))
    return {"b_over_a": b / a, "leading": lead, "second_order": second,
            "geometric": geometric, "drag_torque": b * d1 - a * d2, "damper_torque": m_c,
            "ratio": geometric + extra, "lambda1": lam1, "lambda2": lam2}


def torque_balance_ratio(sat: Satellite, model: str = DEFAULT_MODEL, trail=None) -> float:
    """E2/E1 that balances the tether torques at θ = 0: TB4 of docs/torque-balance.md.

    trail: the balloon's (δx, δy) [m]; default: its equilibrium with the boom held
    at θ = 0 and the satellite's own E1, E2 (balloon_trail_at_zero_pitch).  TB4 is
    exact at the trail of the balanced satellite.  At the default trail it is
    within 1e-5 (relative) of balanced_E2/E1 while E2 is within a factor 2 of balance,
    for the three presets (tests/analysis/test_predict.py).  Its leading term is b/a.
    """
    if trail is None:
        trail = balloon_trail_at_zero_pitch(sat, model)
    return torque_balance_terms(sat, trail[0], trail[1], model)["ratio"]


def balanced_E2(sat: Satellite, E1: float | None = None, model: str = DEFAULT_MODEL) -> float:
    """E2 [N] that puts the equilibrium at θ = 0 exactly, for E1 [N] (default sat.E1).

    Solves the three equilibrium equations q̈(δx, δy, θ = 0) = 0 for (δx, δy, E2) by
    Newton's method, with the generated Jacobian for δx, δy.  q̈ is affine in E2 while
    tether 2 is taut, so ∂q̈/∂E2 = q̈(E2 + 1 N) − q̈(E2).  It starts from TB4
    (torque_balance_ratio).  Raises ValueError if no E2 >= 0 balances, RuntimeError
    if Newton fails.
    """
    E1 = sat.E1 if E1 is None else float(E1)
    m = model_index(model, THESIS_VARIANTS, "the torque balance")
    s = sat.replace(E1=E1, E2=E1 * sat.b / sat.a)
    trail = balloon_trail_at_zero_pitch(s, model)
    E2 = torque_balance_terms(s, trail[0], trail[1], model)["ratio"] * E1 if E1 > 0 else 0.0
    p = parameter_vector(s, model)
    y, d, d1, J = np.zeros(6), np.empty(6), np.empty(6), np.empty((6, 6))
    z = np.array([trail[0], trail[1], E2])
    A = np.empty((3, 3))
    for _ in range(NEWTON_MAX):
        y[0], y[1] = z[0], z[1]
        p[P_E2] = z[2]
        KERNELS[m].rhs(0.0, y, p, d)
        KERNELS[m].jacobian(0.0, y, p, J)
        p[P_E2] = z[2] + 1.0
        KERNELS[m].rhs(0.0, y, p, d1)
        A[:, :2] = J[3:, :2]
        A[:, 2] = d1[3:] - d[3:]
        try:
            step = np.linalg.solve(A, d[3:])
        except np.linalg.LinAlgError:
            raise RuntimeError(f"{sat.name}: balanced_E2 met a singular Jacobian (tether 2 "
                               f"slack at theta = 0?)") from None
        z -= step
        if not np.all(np.isfinite(z)):
            break
        if abs(step[0]) + abs(step[1]) <= NEWTON_STEP_TOL and abs(step[2]) <= 1e-14 * max(
                abs(z[2]), 1e-12):
            break
    y[0], y[1] = z[0], z[1]
    p[P_E2] = z[2]
    KERNELS[m].rhs(0.0, y, p, d)
    if not (np.all(np.isfinite(z)) and np.max(np.abs(d[3:])) <= BALANCE_RESIDUAL_TOL):
        raise RuntimeError(f"{sat.name}: no torque-balanced E2 found for E1 = {E1:g} N "
                           f"(residual {np.max(np.abs(d[3:])):.3g})")
    if z[2] < 0:
        raise ValueError(f"{sat.name}: the torque balance at E1 = {E1:g} N needs E2 = "
                         f"{z[2]:.4g} N < 0")
    return float(z[2])


__all__ = ["PitchTorque", "balanced_E2", "balloon_trail_at_zero_pitch", "torque_balance_ratio",
           "torque_balance_terms"]
