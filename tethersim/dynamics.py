"""The full state derivative that every integrator advances (jitted kernels).

Integrated state (10 floats for today's models, SI):
  y[0:m]    the generated model's state, m = model_state_size(model)
            ((δx, δy, θ, δẋ, δẏ, θ̇) in generated/layout.py)
  y[m:m+4]  (X, Y, VX, VY): the COM in the inertial (GCE) plane, two-body Eq 3.9

The model is a compile-time constant of every compiled loop: ``derivative``
takes the model index (generated.dispatch.MODEL_NAMES) as an integer
*literal* and calls that model's generated ``rhs`` directly (``model_rhs``),
so each model gets its own specialised loop and no branch on the model runs
per evaluation.  A loop obtains the literal with ``numba.literally(model)``
(integrators/rk4.py, dop853.py); a model added to generated/ by `make derive`
gets its loop with no edit here.

cfg (an int64 array: cfg[0] model index, cfg[1] 1 for per-body air density)
is kept for the post-processing kernels (evaluate.py), which run once per
sample and dispatch on the model at run time.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

import generated
from generated import dispatch, layout
from generated.layout import (P_A, P_B, P_L10, P_L20, P_MU, P_R0, P_RHO1, P_RHO2,
                              P_RHO3)

from .atmosphere import TABLE, density_kernel
from .constants import R_EARTH

N_ATTITUDE = len(layout.STATE)  # today's models (all share generated/layout.py)
N_ORBIT = 4  # X, Y, VX, VY appended after the model's own state
N_STATE = N_ATTITUDE + N_ORBIT
CFG_MODEL, CFG_PER_BODY = 0, 1

# generated kernel modules in model-index order (make derive writes both lists)
KERNELS = tuple(generated.MODELS.values())
if tuple(generated.MODELS) != dispatch.MODEL_NAMES:
    raise ImportError("generated/ is inconsistent (MODELS vs dispatch.MODEL_NAMES): run make derive")


def _kernel_state_size(module) -> int:
    # a model module with its own layout (other state sizes) says so with STATE
    return len(getattr(module, "STATE", layout.STATE))


def state_size(model: int) -> int:
    """Length of the integrated state of model index ``model`` (model + orbit).

    Parameters
    ----------
    model : int
        Index into generated.dispatch.MODEL_NAMES.

    Returns
    -------
    int
        The model's own state size plus the 4 floats of the COM orbit.
    """
    return _kernel_state_size(KERNELS[model]) + N_ORBIT


def model_rhs(model, t, y, p, dydt):
    """Generated rhs of model ``model`` (an integer literal in compiled code only)."""
    raise NotImplementedError("model_rhs is only callable from compiled code")


def model_state_size(model):
    """Size of model ``model``'s own state (compiled code, literal model only)."""
    raise NotImplementedError("model_state_size is only callable from compiled code")


@overload(model_rhs, inline="always", prefer_literal=True)
def _model_rhs(model, t, y, p, dydt):
    # only a literal model index picks a kernel: a run-time index is a typing
    # error, not a silent fallback to a branch on every evaluation
    if not isinstance(model, types.IntegerLiteral):
        return None
    rhs = KERNELS[model.literal_value].rhs

    def impl(model, t, y, p, dydt):
        rhs(t, y, p, dydt)
    return impl


@overload(model_state_size, inline="always", prefer_literal=True)
def _model_state_size(model):
    if not isinstance(model, types.IntegerLiteral):
        return None
    n = _kernel_state_size(KERNELS[model.literal_value])

    def impl(model):
        return n
    return impl


@njit(cache=True)
def body_densities(y, p, pw):
    """pw = p with ρ1, ρ2, ρ3 at each body's own altitude |r_i| − R_E (3.10-3.12)."""
    for i in range(p.shape[0]):  # a loop: no slice-assignment error path to compile
        pw[i] = p[i]
    r0, a, b, th = p[P_R0], p[P_A], p[P_B], y[2]
    s, c = math.sin(th), math.cos(th)
    h1 = math.hypot(b * s, r0 + b * c) - R_EARTH
    h2 = math.hypot(-a * s, r0 - a * c) - R_EARTH
    h3 = math.hypot(y[0], r0 + y[1]) - R_EARTH
    pw[P_RHO1] = density_kernel(h1, TABLE)
    pw[P_RHO2] = density_kernel(h2, TABLE)
    pw[P_RHO3] = density_kernel(h3, TABLE)


@njit(cache=True)
def derivative(model, per_body, t, y, p, pw, dydt):
    """dy/dt of the integrated state: generated model + two-body orbit (Eq 3.9).

    Parameters
    ----------
    model : int literal
        Model index (generated.dispatch.MODEL_NAMES); must be a compile-time
        literal (``numba.literally`` in the calling loop).
    per_body : bool
        True: air density at each body's own altitude (computed into pw).
    t : float
        Time [s].
    y : ndarray
        State (model state, then X, Y, VX, VY).
    p : ndarray
        Parameter vector (generated/layout.py).
    pw : ndarray
        Scratch parameter vector, overwritten when per_body.
    dydt : ndarray
        Output, same length as y.
    """
    m = model_state_size(model)
    par = p
    if per_body:
        body_densities(y, p, pw)
        par = pw
    # the generated rhs reads y[0:m] and writes dydt[0:m] only: passing the whole
    # arrays avoids building two slice views per call (~10 % of an RK4 run)
    model_rhs(model, t, y, par, dydt)
    X, Y = y[m], y[m + 1]
    r2 = X * X + Y * Y  # hypot's overflow guard is not needed at orbit scale
    k = -p[P_MU] / (r2 * math.sqrt(r2))
    dydt[m] = y[m + 2]
    dydt[m + 1] = y[m + 3]
    dydt[m + 2] = k * X
    dydt[m + 3] = k * Y


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
