"""The full state derivative that every integrator advances (jitted kernels).

Integrated state (10 floats, SI):
  y[0:6]  (δx, δy, θ, δẋ, δẏ, θ̇): the generated model (generated/layout.py)
  y[6:10] (X, Y, VX, VY): the COM in the inertial (GCE) plane, two-body Eq 3.9

cfg is an int64 array: cfg[0] model index (generated.dispatch.MODEL_NAMES),
cfg[1] 1 for per-body air density (each body at its own altitude), else 0.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.generated import dispatch
from tethersim.generated.layout import (P_A, P_B, P_L10, P_L20, P_MU, P_R0, P_RHO1, P_RHO2,
                              P_RHO3)

from tethersim.model.atmosphere import TABLE, density_kernel
from tethersim.model.constants import R_EARTH

N_STATE = 10
N_ATTITUDE = 6
CFG_MODEL, CFG_PER_BODY = 0, 1


@njit(cache=True)
def body_densities(y, p, pw):
    """pw = p with ρ1, ρ2, ρ3 at each body's own altitude |r_i| − R_E (3.10-3.12)."""
    pw[:] = p
    r0, a, b, th = p[P_R0], p[P_A], p[P_B], y[2]
    s, c = math.sin(th), math.cos(th)
    h1 = math.hypot(b * s, r0 + b * c) - R_EARTH
    h2 = math.hypot(-a * s, r0 - a * c) - R_EARTH
    h3 = math.hypot(y[0], r0 + y[1]) - R_EARTH
    pw[P_RHO1] = density_kernel(h1, TABLE)
    pw[P_RHO2] = density_kernel(h2, TABLE)
    pw[P_RHO3] = density_kernel(h3, TABLE)


@njit(cache=True)
def derivative(cfg, t, y, p, pw, dydt):
    """dy/dt of the 10-float state (generated model + two-body orbit, Eq 3.9)."""
    par = p
    if cfg[CFG_PER_BODY] == 1:
        body_densities(y, p, pw)
        par = pw
    # the generated rhs reads y[0:6] and writes dydt[0:6] only: passing the whole
    # arrays avoids building two slice views per call (~10 % of an RK4 run)
    dispatch.rhs(cfg[CFG_MODEL], t, y, par, dydt)
    X, Y = y[6], y[7]
    r2 = X * X + Y * Y  # hypot's overflow guard is not needed at orbit scale
    k = -p[P_MU] / (r2 * math.sqrt(r2))
    dydt[6] = y[8]
    dydt[7] = y[9]
    dydt[8] = k * X
    dydt[9] = k * Y


@njit(cache=True)
def tether_margins(y, p, g):
    """g[j] = λ_j − l_j0 [m] (Eqs 3.39-3.42): tether j is taut when g[j] > 0."""
    th = y[2]
    s, c = math.sin(th), math.cos(th)
    a, b = p[P_A], p[P_B]
    g[0] = math.hypot(b * s - y[0], b * c - y[1]) - p[P_L10]
    g[1] = math.hypot(-a * s - y[0], -a * c - y[1]) - p[P_L20]


def initial_state(sat_initial, r0: float, v_circ: float) -> np.ndarray:
    """Attitude initial state + the COM at (r0, 0) moving (0, v) (Table 4.3)."""
    return np.array(list(sat_initial) + [r0, 0.0, 0.0, v_circ], dtype=np.float64)
