"""Ordered symbols of the thesis model: coordinates, parameters, units.

Every order here is an explicit tuple (never taken from a set) because the
generated kernels index plain float arrays by position: ``y[STATE.index(...)]``
and ``p[PARAMETER_NAMES.index(...)]``.  The generated files reproduce these
tables in their headers.

Conventions (stated once, in docs/conventions.md):
  * local frame, origin at Earth's centre, rotating with angular velocity ω ẑ
    (Eq 3.13), x along the local horizontal, y radially up, z out of plane;
    the COM sits at (0, r0) and moves along **-x** (ω ẑ × r), so +x is the wake;
  * θ is the pitch of the boom from +y towards +x on the tip-mass side (Eq 3.10).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

t = dynamicsymbols._t

# Generalized coordinates q = (δx, δy, θ) of Eqs 3.10-3.12, in this order.
delta_x, delta_y, theta = dynamicsymbols("delta_x delta_y theta")
COORDINATES = (delta_x, delta_y, theta)
SPEEDS = tuple(q.diff(t) for q in COORDINATES)
ACCELERATIONS = tuple(q.diff(t, 2) for q in COORDINATES)


@dataclass(frozen=True)
class Parameter:
    """One model parameter: code name, sympy symbol, SI unit, meaning."""

    name: str
    symbol: sp.Symbol
    unit: str
    meaning: str


def _p(name: str, unit: str, meaning: str, latex: str | None = None) -> Parameter:
    return Parameter(name, sp.Symbol(latex or name, positive=True), unit, meaning)


# Order of the parameter vector p of every generated kernel.  The thesis names
# (Table 4.1) are kept; rho1..rho3 are the densities at the three bodies
# (all equal to the orbit-altitude density in the thesis's uniform model).
PARAMETERS = (
    _p("m1", "kg", "tip-mass"),
    _p("m2", "kg", "main bus"),
    _p("m3", "kg", "balloon"),
    _p("A1", "m^2", "frontal area of the tip-mass"),
    _p("A2", "m^2", "frontal area of the main bus"),
    _p("A3", "m^2", "frontal area of the balloon"),
    _p("a", "m", "COM to main bus distance"),
    _p("b", "m", "COM to tip-mass distance"),
    _p("l10", "m", "rest (taut) length of tether 1, tip-mass to balloon", "l_10"),
    _p("l20", "m", "rest (taut) length of tether 2, bus to balloon", "l_20"),
    _p("E1", "N", "tether 1 modulus x 1 mm^2 cross-section (N/mm^2 x mm^2)"),
    _p("E2", "N", "tether 2 modulus x 1 mm^2 cross-section (N/mm^2 x mm^2)"),
    _p("c1", "N s/m", "tether 1 damping coefficient"),
    _p("c2", "N s/m", "tether 2 damping coefficient"),
    _p("CD", "1", "drag coefficient (all bodies, thesis p. 3-9)", "C_D"),
    _p("r0", "m", "orbit radius of the COM", "r_0"),
    _p("mu", "m^3/s^2", "Earth's gravitational parameter"),
    _p("omega", "rad/s", "orbital rate sqrt(mu/r0^3), Eq 3.14"),
    _p("omega_earth", "rad/s", "Earth's rotation rate (atmosphere co-rotates)", "omega_E"),
    _p("rho1", "kg/m^3", "air density at the tip-mass", "rho_1"),
    _p("rho2", "kg/m^3", "air density at the main bus", "rho_2"),
    _p("rho3", "kg/m^3", "air density at the balloon", "rho_3"),
)
PARAMETER_NAMES = tuple(p.name for p in PARAMETERS)
P = {p.name: p.symbol for p in PARAMETERS}

STATE_NAMES = ("delta_x", "delta_y", "theta", "delta_x_dot", "delta_y_dot", "theta_dot")
STATE_UNITS = ("m", "m", "rad", "m/s", "m/s", "rad/s")

# Plain (non-function) symbols standing for the state inside generated code.
STATE_SYMBOLS = tuple(sp.Symbol(n, real=True) for n in STATE_NAMES)

# Tether lengths λ1, λ2 (Eqs 3.41-3.42) appear as symbols so that the generated
# code computes each once and branches on it (taut when λ_j > l_j0, Eqs 3.35-3.36).
lambda1, lambda2 = sp.symbols("lambda1 lambda2", positive=True)
TETHER_LENGTHS = (lambda1, lambda2)
TETHER_REST = (P["l10"], P["l20"])


def state_substitution() -> dict:
    """Map q̈, q̇, q (functions of t) to the plain state symbols (δx ... θ̇)."""
    sub = {}
    for qdd in ACCELERATIONS:
        sub[qdd] = sp.Symbol(f"{qdd.args[0].func.__name__}_ddot", real=True)
    for qd, s in zip(SPEEDS, STATE_SYMBOLS[3:]):
        sub[qd] = s
    for q, s in zip(COORDINATES, STATE_SYMBOLS[:3]):
        sub[q] = s
    return sub


ACCELERATION_SYMBOLS = tuple(
    sp.Symbol(f"{q.func.__name__}_ddot", real=True) for q in COORDINATES
)
