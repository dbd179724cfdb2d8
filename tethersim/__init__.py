"""tethersim: a derivation-checked simulator of a gravity-gradient satellite
stabilised by a tethered drag balloon (Maramba, AFIT/GA/ENY/05-M07, 2005).

Conventions (frame, sign of ω, θ direction): docs/conventions.md.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim import _jit  # noqa: F401  (first: numba's cache folder, before any kernel)
from tethersim.analysis.outcome import Outcome, outcome
from tethersim.analysis.summary import run_summary
from tethersim.engine.dynamics import parameters_at
from tethersim.engine.result import SimResult
from tethersim.engine.simulate import RK4StepWarning, simulate
from tethersim.generated.layout import FAMILIES, PARAMETERS, STATE
from tethersim.model.inputs import air_vector, parameter_vector
from tethersim.model.materials import MATERIALS, tether_parameters, with_tethers
from tethersim.model.options import air_density
from tethersim.model.presets import load, load_preset
from tethersim.model.registry import DEFAULT_MODEL, KERNELS, NAMES, get_model
from tethersim.model.satellite import Satellite, SatelliteError
from tethersim.model.satellite import parameters as _parameters
from tethersim.output.tables import write_netcdf, write_table, write_timeseries

__all__ = ["Satellite", "SatelliteError", "SimResult", "RK4StepWarning", "Outcome", "load",
           "load_preset", "simulate", "outcome", "run_summary", "write_timeseries",
           "write_netcdf", "write_table", "accelerations", "generalized_forces", "parameters",
           "MODELS", "FAMILIES", "STATE", "PARAMETERS", "__version__", "find_equilibrium",
           "Equilibrium", "SweepSpec", "run_sweep", "Plan", "run_plan", "bodies", "body_accelerations",
           "air_density", "MATERIALS", "tether_parameters", "with_tethers"]
from tethersim._version import __version__  # noqa: E402

MODELS = NAMES  # every generated model (tethersim.model.registry)


def parameters(sat: Satellite) -> dict:
    """The thesis symbols of a satellite as SI floats.

    Parameters
    ----------
    sat : Satellite
        The satellite.

    Returns
    -------
    dict
        {symbol: value} for m1 ... rho3 (units in ``tethersim.PARAMETERS`` order,
        generated/layout.py), plus r0, omega and the uniform density rho.

    Examples
    --------
    >>> import tethersim
    >>> round(tethersim.parameters(tethersim.load_preset("satI"))["r0"] / 1e3, 3)
    6578.137
    """
    return _parameters(sat)


def _state_and_params(sat: Satellite, state, model: str, t: float = 0.0):
    if not isinstance(sat, Satellite):
        raise TypeError(f"sat must be a Satellite, got {type(sat).__name__}")
    m = get_model(model)
    y = np.asarray(state, dtype=float)
    if y.shape != (m.n_state,) or not np.all(np.isfinite(y)):
        names = ", ".join(f"{n} [{u}]" for n, u in zip(m.state, m.state_units))
        raise ValueError(f"state = {state!r}: must be {m.n_state} finite numbers ({names})")
    try:
        t = float(t)
    except (TypeError, ValueError):
        raise ValueError(f"t = {t!r}: must be a finite time [s]") from None
    if not math.isfinite(t):
        raise ValueError(f"t = {t!r}: must be a finite time [s]")
    y = np.ascontiguousarray(y)
    # the per-body densities at this state and time (the run's own air vector)
    p = parameters_at(m.index, t, y, parameter_vector(sat, model), air_vector(sat, max(t, 0.0)))
    return m, y, p


def accelerations(sat: Satellite, state, model: str = DEFAULT_MODEL, *, t: float = 0.0) -> np.ndarray:
    """Generalized accelerations of a model at one state (SI).

    Parameters
    ----------
    sat : Satellite
        The satellite.
    state : array_like
        The model's state in its STATE order; for the thesis models
        (δx [m], δy [m], θ [rad], δẋ [m/s], δẏ [m/s], θ̇ [rad/s]).
    model : str, optional
        Model name (``tethersim.MODELS``), default ``"derived"``.
    t : float, optional
        Time since the epoch [s]: where the air is (per-body NRLMSISE-00) and the
        orbit phase of a circular-orbit model.

    Returns
    -------
    numpy.ndarray
        q̈ in the order of the model's coordinates (thesis models: δẍ [m/s²],
        δÿ [m/s²], θ̈ [rad/s²]).

    Raises
    ------
    ValueError
        A state of the wrong length or with a non-finite entry, or an unknown model.

    Examples
    --------
    >>> import tethersim
    >>> sat = tethersim.load_preset("satI")
    >>> tethersim.accelerations(sat, [0, 0, 0, 0, 0, 0]).shape
    (3,)
    """
    m, y, p = _state_and_params(sat, state, model, t)
    d = np.empty(m.n_state)
    KERNELS[m.index].rhs(float(t), y, p, d)
    return d[m.n_coordinates:].copy()


def generalized_forces(sat: Satellite, state, model: str = DEFAULT_MODEL, *, t: float = 0.0) -> dict:
    """Generalized force of every force family at one state (Eqs 3.31-3.47).

    Parameters
    ----------
    sat : Satellite
        The satellite.
    state : array_like
        The model's state in its STATE order (see :func:`accelerations`).
    model : str, optional
        Model name, default ``"derived"``.
    t : float, optional
        Time since the epoch [s] (as :func:`accelerations`).

    Returns
    -------
    dict
        {family: array of Q on each coordinate} (thesis models: Q_δx [N],
        Q_δy [N], Q_θ [N m]); families drag1-3, spring1-2, damper1-2.

    Examples
    --------
    >>> import tethersim
    >>> q = tethersim.generalized_forces(tethersim.load_preset("satI"), [29, 0, 0, 0, 0, 0])
    >>> sorted(q)[:3]
    ['damper1', 'damper2', 'drag1']
    """
    m, y, p = _state_and_params(sat, state, model, t)
    out = np.zeros((len(m.families), m.n_coordinates))
    KERNELS[m.index].family_forces(y, p, out)
    return {f: out[i].copy() for i, f in enumerate(m.families)}


def bodies(sat: Satellite, state, t: float = 0.0, model: str = DEFAULT_MODEL):
    """Inertial positions and velocities of the three bodies, the boom's attitude and spin.

    The map from a model's coordinates to the inertial frame, so a model can be
    checked against any Newton–Euler code without knowing its coordinates
    (conventions: tethersim/engine/bodies.py; on a circular orbit the COM is at
    r0 (cos ωt, sin ωt, 0), as the runtime's COM orbit columns).

    Parameters
    ----------
    sat : Satellite
        The satellite.
    state : array_like
        The model's state in its STATE order (``get_model(model).state``).
    t : float, optional
        Time [s] (sets the orbit phase of a circular-orbit model).
    model : str, optional
        Model name, default ``"derived"``; planar models have φ = ψ = δz = 0.

    Returns
    -------
    tethersim.engine.bodies.Bodies
        ``position``, ``velocity`` (3 bodies × XYZ: tip-mass, bus, balloon),
        ``com_position``, ``com_velocity``, ``attitude`` (columns: roll, boom,
        pitch axes in N) and ``angular_velocity`` [rad/s], SI.

    Examples
    --------
    >>> import tethersim
    >>> sat = tethersim.load_preset("satI")
    >>> b = tethersim.bodies(sat, [29, 0, 0, 0, 0, 0])
    >>> [round(float(v), 3) for v in b.offset[0]]  # tip-mass: 10.5 m up (radial, +X at t = 0)
    [10.5, 0.0, 0.0]
    """
    from tethersim.engine.bodies import bodies_from_states

    m, y, _ = _state_and_params(sat, state, model, t)
    return bodies_from_states(sat, m.name, float(t), y)


def body_accelerations(sat: Satellite, state, t: float = 0.0, model: str = DEFAULT_MODEL):
    """Inertial accelerations of the three bodies and the boom's angular acceleration.

    From the model's generalized accelerations at ``state`` (drag, tethers and
    gravity as the model has them) mapped to the inertial frame of
    :func:`bodies`: for the balloon, m3 times this is the sum of the forces on
    it; for the boom, Euler's equations about its COM hold with this
    angular acceleration.

    Parameters
    ----------
    sat : Satellite
        The satellite.
    state : array_like
        The model's state in its STATE order.
    t : float, optional
        Time [s].
    model : str, optional
        Model name, default ``"derived"``.

    Returns
    -------
    tethersim.engine.bodies.BodyAccelerations
        ``acceleration`` (3 bodies × XYZ) [m/s²], ``com_acceleration`` [m/s²],
        ``angular_acceleration`` [rad/s²], in N.

    Examples
    --------
    >>> import tethersim
    >>> sat = tethersim.load_preset("satI")
    >>> acc = tethersim.body_accelerations(sat, [29, 0, 0, 0, 0, 0])
    >>> round(float(acc.com_acceleration[0]), 4)  # −ω² r0 along X at t = 0
    -9.2115
    """
    from tethersim.engine.bodies import accelerations_from_qdd

    m, y, p = _state_and_params(sat, state, model, t)
    d = np.empty(m.n_state)
    KERNELS[m.index].rhs(float(t), y, p, d)
    return accelerations_from_qdd(sat, m.name, float(t), y, d[m.n_coordinates:])


# heavier parts of the API (scipy.optimize, xarray/zarr) load on first use
_LAZY = {"find_equilibrium": "tethersim.analysis.equilibrium",
         "Equilibrium": "tethersim.analysis.equilibrium",
         "SweepSpec": "tethersim.experiments.sweep", "run_sweep": "tethersim.experiments.sweep",
         "Plan": "tethersim.experiments.sweep", "run_plan": "tethersim.experiments.sweep"}


def __getattr__(name):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'tethersim' has no attribute {name!r}")
