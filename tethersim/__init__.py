"""tethersim: a derivation-checked simulator of a gravity-gradient satellite
stabilised by a tethered drag balloon (Maramba, AFIT/GA/ENY/05-M07, 2005).

Conventions (frame, sign of ω, θ direction): docs/conventions.md.
"""
from __future__ import annotations

import numpy as np

from generated import dispatch
from generated.layout import FAMILIES, PARAMETERS, STATE

from .dynamics import body_densities
from .models import DEFAULT_MODEL, model_index
from .presets import load, load_preset
from .result import SimResult
from .satellite import Satellite, SatelliteError, parameter_vector
from .satellite import parameters as _parameters
from .simulation import RK4StepWarning, simulate

__all__ = ["Satellite", "SatelliteError", "SimResult", "RK4StepWarning", "load", "load_preset",
           "simulate", "accelerations", "generalized_forces", "parameters", "MODELS",
           "FAMILIES", "STATE", "PARAMETERS"]
__version__ = "0.1.0"
MODELS = dispatch.MODEL_NAMES


def parameters(sat: Satellite) -> dict:
    """Thesis symbols (m1 ... rho) as SI floats; see generated/layout.py for units."""
    return _parameters(sat)


def _state_and_params(sat: Satellite, state):
    if not isinstance(sat, Satellite):
        raise TypeError(f"sat must be a Satellite, got {type(sat).__name__}")
    y = np.asarray(state, dtype=float)
    if y.shape != (6,) or not np.all(np.isfinite(y)):
        raise ValueError(f"state = {state!r}: must be 6 finite numbers "
                         f"(δx [m], δy [m], θ [rad], δẋ [m/s], δẏ [m/s], θ̇ [rad/s])")
    p = parameter_vector(sat)
    if sat.density_mode == "per-body":
        pw = p.copy()
        body_densities(y, p, pw)
        p = pw
    return y, p


def accelerations(sat: Satellite, state, model: str = DEFAULT_MODEL) -> np.ndarray:
    """(δẍ [m/s²], δÿ [m/s²], θ̈ [rad/s²]) at state (δx, δy, θ, δẋ, δẏ, θ̇) in SI."""
    m = model_index(model)
    y, p = _state_and_params(sat, state)
    d = np.empty(6)
    dispatch.rhs(m, 0.0, y, p, d)
    return d[3:].copy()


def generalized_forces(sat: Satellite, state, model: str = DEFAULT_MODEL) -> dict:
    """{family: (Q_δx [N], Q_δy [N], Q_θ [N m])} for every force family (Eqs 3.31-3.47)."""
    m = model_index(model)
    y, p = _state_and_params(sat, state)
    out = np.zeros((len(FAMILIES), 3))
    dispatch.family_forces(m, y, p, out)
    return {f: out[i].copy() for i, f in enumerate(FAMILIES)}
