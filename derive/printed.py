"""The thesis's printed equations, transcribed term by term (not derived).

Eqs 3.28-3.30 (Lagrange left-hand sides) and 3.48-3.50 (equations of motion),
as printed in the thesis (Maramba 2005, chapter III): **as printed, errors included**.
Every tether force term is gathered on the right-hand side with the sign that
follows from Eqs 3.43-3.47.  The expressions use the plain state symbols of
``symbols.STATE_SYMBOLS`` and the tether-length symbols λ1, λ2.

Nothing here is computed from the mechanics objects: this module is the
independent reference that tests/derive/test_errata.py compares with the derivation.
"""
from __future__ import annotations

import sympy as sp

from .symbols import ACCELERATION_SYMBOLS, STATE_SYMBOLS, P, lambda1, lambda2

dx, dy, th, dxd, dyd, thd = STATE_SYMBOLS
dxdd, dydd, thdd = ACCELERATION_SYMBOLS
(m1, m2, m3, A1, A2, A3, a, b, l10, l20, E1, E2, c1, c2, CD, r0, omega, wE,
 rho1, rho2, rho3) = (P[k] for k in ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b",
                                     "l10", "l20", "E1", "E2", "c1", "c2", "CD", "r0",
                                     "omega", "omega_earth", "rho1", "rho2", "rho3"))
s, c = sp.sin(th), sp.cos(th)
half = sp.Rational(1, 2)

# Lagrange left-hand sides as printed (3.28-3.30).
LHS = (
    m3 * dxdd - 2 * m3 * omega * dyd - 3 * m3 * omega**2 * dy * dx / r0,
    m3 * dydd + 2 * m3 * omega * dxd - 3 * m3 * omega**2 * dy
    - 9 * m3 * omega**2 * dy**2 / (2 * r0) - 3 * m3 * omega**2 * dx**2 / (2 * r0),
    m1 * (b**2 * thdd + 3 * omega**2 * b**2 * c * s + 3 * omega**2 * b**3 * s / (2 * r0))
    + m2 * (a**2 * thdd + 3 * omega**2 * a**2 * c * s - 3 * omega**2 * a**3 * s / (2 * r0)),
)

# Positions (3.10-3.12) and inertial velocities (3.15-3.17) as printed.
_r = ((b * s, r0 + b * c), (-a * s, r0 - a * c), (dx, r0 + dy))
_v = (
    (b * thd * c - omega * (r0 + b * c), -b * thd * s + omega * b * s),
    (-a * thd * c - omega * (r0 - a * c), a * thd * s - omega * a * s),
    (dxd - omega * (r0 + dy), dyd + omega * dx),
)


def _vrel(i: int) -> tuple:
    """V_rel,i = ṙ_i − ω_E ẑ × r_i in local components (3.33-3.34)."""
    (x, y), (vx, vy) = _r[i], _v[i]
    return vx + wE * y, vy - wE * x


def _drag_coefficients(i: int):
    """(−½ C_D A_i ρ_i V_rel,i², V̂_x,i, V̂_y,i) of Eq 3.32."""
    A, rho = (A1, A2, A3)[i], (rho1, rho2, rho3)[i]
    vx, vy = _vrel(i)
    speed = sp.sqrt(vx**2 + vy**2)
    return -half * CD * A * rho * speed**2, vx / speed, vy / speed


_k1, _ux1, _uy1 = _drag_coefficients(0)
_k2, _ux2, _uy2 = _drag_coefficients(1)
_k3, _ux3, _uy3 = _drag_coefficients(2)
_g1, _g2 = lambda1 / l10, lambda2 / l20  # 3.39-3.40

# The relative-velocity brackets exactly as they appear in 3.48-3.50.
_D1x = dxd - omega * dy - b * thd * c + omega * b * c
_D1y = dyd + omega * dx + b * thd * s - omega * b * s
_D2x = dxd - omega * dy + a * thd * c - omega * a * c
_D2y = dyd + omega * dx - a * thd * s + omega * a * s

# Right-hand sides of 3.48 (Q_δx), 3.49 (Q_δy), 3.50 (Q_θ), one entry per family.
FAMILIES = {
    "drag1": (0, 0, _k1 * (_ux1 * b * c - _uy1 * b * s)),
    "drag2": (0, 0, _k2 * (-_ux2 * a * c + _uy2 * a * s)),
    "drag3": (_k3 * _ux3, _k3 * _uy3, 0),
    "spring1": (
        (b * s - dx) * E1 * (_g1 - 1) / lambda1,
        (b * c - dy) * E1 * (_g1 - 1) / lambda1,
        -((b * s - dx) * b * c - (b * c - dy) * b * s) * E1 * (_g1 - 1) / lambda1,
    ),
    "spring2": (
        (-a * s - dx) * E2 * (_g2 - 1) / lambda2,
        (-a * c - dy) * E2 * (_g2 - 1) / lambda2,
        -((-a * s - dx) * (-a * c) + (-a * c - dy) * a * s) * E2 * (_g2 - 1) / lambda2,
    ),
    "damper1": (
        -c1 * _D1x,
        -c1 * _D1y,
        c1 * b * c * _D1x - c1 * b * s * _D1y,
    ),
    # 3.50 as printed multiplies c2 by tether 1's brackets (b, not -a): see
    # docs/errata.md, row E1.
    "damper2": (
        -c2 * _D2x,
        -c2 * _D2y,
        -c2 * a * c * _D1x + c2 * a * s * _D1y,
    ),
}
FAMILY_TETHER = {"drag1": None, "drag2": None, "drag3": None, "spring1": 1,
                 "spring2": 2, "damper1": 1, "damper2": 2}
