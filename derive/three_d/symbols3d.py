"""Ordered symbols of the 3-D model: coordinates, parameters, units.

Orders are explicit tuples, as in derive/symbols.py.  The parameter vector is
the planar one (indices 0-21 unchanged) followed by the principal moments of
inertia of the tip-mass (I1_*) and of the bus (I2_*) about their own centres,
on the boom's roll, pitch and yaw axes (docs/three-d.md).

Coordinates q = (δx, δy, δz, φ, θ, ψ):
  * δx, δy, δz: balloon position from the COM point (0, r0, 0) in the local
    frame L (docs/conventions.md: x wake, y radially up, z orbit normal);
  * θ pitch, φ roll, ψ yaw of the boom: a body 3-1-2 (z-x-y) Euler sequence,
    pitch first (as the planar θ), roll about the pitched x axis, yaw last
    about the boom.  Singular at φ = ±π/2 (boom along the orbit normal).
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

from ..symbols import PARAMETERS as PLANAR_PARAMETERS
from ..symbols import TETHER_LENGTHS, TETHER_REST, Parameter, t  # noqa: F401 (re-export)

delta_x, delta_y, delta_z, phi, theta, psi = dynamicsymbols(
    "delta_x delta_y delta_z phi theta psi")
COORDINATES = (delta_x, delta_y, delta_z, phi, theta, psi)
SPEEDS = tuple(q.diff(t) for q in COORDINATES)
ACCELERATIONS = tuple(q.diff(t, 2) for q in COORDINATES)
N_Q = len(COORDINATES)

COORDINATE_NAMES = ("delta_x", "delta_y", "delta_z", "phi", "theta", "psi")
COORDINATE_UNITS = ("m", "m", "m", "rad", "rad", "rad")
STATE_NAMES = COORDINATE_NAMES + tuple(f"{n}_dot" for n in COORDINATE_NAMES)
STATE_UNITS = COORDINATE_UNITS + ("m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s")
_MEANINGS = (
    "balloon offset along x (wake)", "balloon offset along y (radially up)",
    "balloon offset along z (orbit normal)", "roll of the boom (about pitched x)",
    "pitch of the boom (planar theta)", "yaw of the boom (about the boom axis)",
)
STATE_MEANINGS = _MEANINGS + tuple(f"rate of {m}" for m in _MEANINGS)
STATE_SYMBOLS = tuple(sp.Symbol(n, real=True) for n in STATE_NAMES)
ACCELERATION_SYMBOLS = tuple(sp.Symbol(f"{n}_ddot", real=True) for n in COORDINATE_NAMES)

# Index of each rotational coordinate in q (the rotational block of M).
ROTATION = (3, 4, 5)
TRANSLATION = (0, 1, 2)

INERTIA_AXES = ("roll", "pitch", "yaw")


def _inertia(body: int, axis: str) -> Parameter:
    who = ("tip-mass", "main bus")[body - 1]
    return Parameter(f"I{body}_{axis}", sp.Symbol(f"I{body}_{axis}", nonnegative=True),
                     "kg m^2", f"{who} principal inertia about its own {axis} axis")


INERTIAS = tuple(_inertia(b, ax) for b in (1, 2) for ax in INERTIA_AXES)
PARAMETERS = PLANAR_PARAMETERS + INERTIAS
PARAMETER_NAMES = tuple(p.name for p in PARAMETERS)
P = {p.name: p.symbol for p in PARAMETERS}


def state_substitution() -> dict:
    """Map q̈, q̇, q (functions of t) to plain symbols, highest derivatives first."""
    sub = dict(zip(ACCELERATIONS, ACCELERATION_SYMBOLS))
    sub.update(zip(SPEEDS, STATE_SYMBOLS[N_Q:]))
    sub.update(zip(COORDINATES, STATE_SYMBOLS[:N_Q]))
    return sub


def to_state_symbols(expr):
    """Replace q(t), q̇(t), q̈(t) by the plain state symbols."""
    return sp.sympify(expr).xreplace(state_substitution())


def eq44_box_inertia(mass: float, area: float) -> tuple:
    """(roll, pitch, yaw) moments [kg m²] of a cube of frontal area ``area`` (Eq 4.4).

    Parameters
    ----------
    mass : float
        Body mass [kg].
    area : float
        Frontal area [m²].

    Returns
    -------
    tuple of float
        The three equal principal moments [kg m²].

    Notes
    -----
    I_xx = I_yy = I_zz = m (2 Area)/12, i.e. m s²/6 for a cube of side s (thesis
    p. 4-5, Table 4.4): the default I1 (tip-mass) and I2 (bus) of the 3-D models.
    """
    value = mass * 2.0 * area / 12.0
    return (value, value, value)
