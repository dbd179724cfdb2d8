"""tethersim: a derivation-checked simulator of a gravity-gradient satellite
stabilised by a tethered drag balloon (Maramba, AFIT/GA/ENY/05-M07, 2005).

Conventions (frame, sign of ω, θ direction): docs/conventions.md.
"""
from __future__ import annotations

import numpy as np

from tethersim import _jit  # noqa: F401  (first: numba's cache folder, before any kernel)
from tethersim.generated import dispatch
from tethersim.generated.layout import FAMILIES, PARAMETERS, STATE

from tethersim.engine.dynamics import body_densities
from tethersim.model.registry import DEFAULT_MODEL, model_index
from tethersim.model.presets import load, load_preset
from tethersim.engine.result import SimResult
from tethersim.model.satellite import Satellite, SatelliteError, parameter_vector
from tethersim.model.satellite import parameters as _parameters
from tethersim.engine.simulate import RK4StepWarning, simulate
from tethersim.analysis.outcome import Outcome, outcome
from tethersim.analysis.summary import run_summary
from tethersim.output.tables import write_netcdf, write_table, write_timeseries

__all__ = ["Satellite", "SatelliteError", "SimResult", "RK4StepWarning", "Outcome", "load",
           "load_preset", "simulate", "outcome", "run_summary", "write_timeseries",
           "write_netcdf", "write_table", "accelerations", "generalized_forces", "parameters",
           "MODELS", "FAMILIES", "STATE", "PARAMETERS", "__version__", "find_equilibrium",
           "Equilibrium", "SweepSpec", "run_sweep"]
from tethersim._version import __version__  # noqa: E402
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


# heavier parts of the API (scipy.optimize, xarray/zarr) load on first use
_LAZY = {"find_equilibrium": "tethersim.analysis.equilibrium",
         "Equilibrium": "tethersim.analysis.equilibrium",
         "SweepSpec": "tethersim.experiments.sweep", "run_sweep": "tethersim.experiments.sweep"}


def __getattr__(name):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'tethersim' has no attribute {name!r}")
