"""The full state derivative that every integrator advances (jitted kernels).

Integrated state (SI):
  y[0:m]    the generated model's own state, m = len(Model.state)
            (tethersim.model.registry; e.g. (δx, δy, θ, δẋ, δẏ, θ̇) for the thesis models)
  y[m:m+4]  (X, Y, VX, VY): for circular-orbit models only, the COM in the inertial
            (GCE) plane, two-body Eq 3.9; a free-orbit model carries r and ν itself

The model is a compile-time constant of every compiled loop: each ``model_*``
function below takes the model index (tethersim.model.registry order) as an
integer *literal* and resolves to that model's generated kernel, so each model
gets its own specialised loop and no branch on the model runs per evaluation.
A loop obtains the literal with ``numba.literally(model)`` (integrators/rk4.py,
dop853.py).  Everything a loop needs to know about a model's layout — its
state size, whether a COM orbit is appended, where the densities and μ sit in
its parameter vector, its tether margins and body radii — comes from the
generated module, so a model that `make derive` adds gets its loop with no
edit here.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit, types
from numba.extending import overload

from tethersim.engine.integrators.select import call
from tethersim.model.air.vector import UNIFORM, body_density
from tethersim.model.constants import R_EARTH
from tethersim.model.registry import KERNELS, MODELS

N_ORBIT = 4  # X, Y, VX, VY appended after a circular-orbit model's own state


def has_com_orbit(model: int) -> bool:
    """True when the engine appends the two-body COM orbit to model ``model``'s state."""
    return MODELS[model].orbit == "circular"


def state_size(model: int) -> int:
    """Length of the integrated state of model index ``model``.

    Parameters
    ----------
    model : int
        Index in :data:`tethersim.model.registry.MODELS`.

    Returns
    -------
    int
        The model's own state size, plus the 4 floats of the COM orbit for a
        circular-orbit model.
    """
    return MODELS[model].n_state + (N_ORBIT if has_com_orbit(model) else 0)


def literal_index(model):
    """The model index a numba type carries as a literal, else None (overloads' typing).

    Only a literal model index picks a kernel: a run-time index is a typing error,
    not a silent fallback to a branch on every evaluation.
    """
    return model.literal_value if isinstance(model, types.IntegerLiteral) else None


def model_rhs(model, t, y, p, dydt):
    """Generated rhs of model ``model`` (an integer literal in compiled code only)."""
    raise NotImplementedError("model_rhs is only callable from compiled code")


def model_size(model):
    """Length of model ``model``'s integrated state, a compile-time constant (literal model).

    The step functions loop over the state with this bound rather than the array's
    run-time length, so LLVM sees a constant trip count (the C ports' ``#define NS``)
    and unrolls the stage sums; each component's arithmetic is unchanged.
    """
    raise NotImplementedError("model_size is only callable from compiled code")


def model_tether_margins(model, y, p, g):
    """g[j] = λ_j − l_j0 of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_tether_margins is only callable from compiled code")


def model_densities(model, t, y, p, pw, air):
    """pw = p with ρ1..ρ3 at each body (air vector ``air``; compiled code, literal model only)."""
    raise NotImplementedError("model_densities is only callable from compiled code")


def model_com_orbit(model, y, p, dydt):
    """Two-body COM orbit of a circular-orbit model (compiled code, literal model only)."""
    raise NotImplementedError("model_com_orbit is only callable from compiled code")


@overload(model_rhs, inline="always", prefer_literal=True)
def _model_rhs(model, t, y, p, dydt):
    if (k := literal_index(model)) is None:
        return None
    rhs = KERNELS[k].rhs

    def impl(model, t, y, p, dydt):
        rhs(t, y, p, dydt)
    return impl


@overload(model_size, inline="always", prefer_literal=True)
def _model_size(model):
    if (k := literal_index(model)) is None:
        return None
    n = state_size(k)

    def impl(model):
        return n
    return impl


@overload(model_tether_margins, inline="always", prefer_literal=True)
def _model_tether_margins(model, y, p, g):
    if (k := literal_index(model)) is None:
        return None
    margins = KERNELS[k].tether_margins

    def impl(model, y, p, g):
        margins(y, p, g)
    return impl


@overload(model_densities, inline="always", prefer_literal=True)
def _model_densities(model, t, y, p, pw, air):
    if (k := literal_index(model)) is None:
        return None
    radii = KERNELS[k].body_radii
    i1, i2, i3 = (MODELS[k].parameters.index(n) for n in ("rho1", "rho2", "rho3"))
    # the inertial polar angle of the reference point, for the longitude under it:
    # ω t on the held circle (the COM starts on +X, initial_state), ν + π/2 on a free
    # orbit (R = r (−sin ν, cos ν), docs/orbit.md).  Every body takes this angle: the
    # bodies sit within ~100 m of it, 1.5e-5 rad of longitude, a 0.2 s shift of local
    # time (docs/air.md bounds the density error this makes)
    if has_com_orbit(k):
        i_angle, from_state, offset = MODELS[k].parameters.index("omega"), False, 0.0
    else:
        i_angle, from_state, offset = MODELS[k].state.index("nu"), True, 0.5 * math.pi

    def impl(model, t, y, p, pw, air):
        for i in range(p.shape[0]):  # a loop: no slice-assignment error path to compile
            pw[i] = p[i]
        r1, r2, r3 = radii(y, p)
        angle = y[i_angle] + offset if from_state else p[i_angle] * t
        pw[i1] = body_density(r1 - R_EARTH, angle, t, air)
        pw[i2] = body_density(r2 - R_EARTH, angle, t, air)
        pw[i3] = body_density(r3 - R_EARTH, angle, t, air)
    return impl


@overload(model_com_orbit, inline="always", prefer_literal=True)
def _model_com_orbit(model, y, p, dydt):
    if (k := literal_index(model)) is None:
        return None
    if not has_com_orbit(k):
        def nothing(model, y, p, dydt):
            return None
        return nothing
    m = MODELS[k].n_state
    i_mu = MODELS[k].parameters.index("mu")

    def impl(model, y, p, dydt):
        X, Y = y[m], y[m + 1]
        r2 = X * X + Y * Y  # hypot's overflow guard is not needed at orbit scale
        c = -p[i_mu] / (r2 * math.sqrt(r2))
        dydt[m] = y[m + 2]
        dydt[m + 1] = y[m + 3]
        dydt[m + 2] = c * X
        dydt[m + 3] = c * Y
    return impl


@njit(cache=True)
def derivative(model, air, t, y, p, pw, dydt):
    """dy/dt of the integrated state: generated model (+ two-body COM orbit, Eq 3.9).

    Parameters
    ----------
    model : int literal
        Model index (registry order); must be a compile-time literal
        (``numba.literally`` in the calling loop).
    air : ndarray
        The air vector (tethersim.model.air.vector): mode 0 reads the uniform
        densities of p; the per-body modes compute ρ1..ρ3 into pw.
    t : float
        Time [s].
    y : ndarray
        Integrated state (the model's state, then X, Y, VX, VY if circular).
    p : ndarray
        Parameter vector (the model's PARAMETERS order).
    pw : ndarray
        Scratch parameter vector, overwritten in the per-body modes.
    dydt : ndarray
        Output, same length as y.
    """
    par = p
    if air[0] != UNIFORM:
        model_densities(model, t, y, p, pw, air)
        par = pw
    # the generated rhs reads y[0:m] and writes dydt[0:m] only: passing the whole
    # arrays avoids building two slice views per call (~10 % of an RK4 run)
    model_rhs(model, t, y, par, dydt)
    model_com_orbit(model, y, p, dydt)


@njit(cache=True)
def _parameters_at(model, t, y, p, air):
    literally(model)
    pw = p.copy()
    if air[0] != UNIFORM:
        model_densities(model, t, y, p, pw, air)
    return pw


def parameters_at(model: int, t: float, y, p, air) -> np.ndarray:
    """p with the per-body densities at (t, y) of model index ``model`` (from Python)."""
    return call(_parameters_at, model, t, y, p, air)


def initial_state(model: int, model_state, r0: float, v_circ: float) -> np.ndarray:
    """The integrated initial state: the model's own, then the COM at (r0, 0)
    moving (0, v) for a circular-orbit model (Table 4.3)."""
    extra = [r0, 0.0, 0.0, v_circ] if has_com_orbit(model) else []
    return np.array(list(model_state) + extra, dtype=np.float64)
