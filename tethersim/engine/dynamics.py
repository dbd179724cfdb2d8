"""The full state derivative that every integrator advances (jitted kernels).

Integrated state (SI): the generated model's own state and nothing else, m =
len(Model.state) floats (tethersim.model.registry; e.g. (δx, δy, θ, δẋ, δẏ, θ̇) for
the thesis models).  A free-orbit model carries its orbit (r, ν) in that state; a
circular-orbit model holds its reference point on the circle of radius r0 at polar
angle ωt, a closed form (:func:`held_circle_orbit`) that no kernel reads back from
the state, so it is computed where it is wanted (the outputs), never integrated.

The model is a compile-time constant of every compiled loop: each ``model_*``
function below takes the model index (tethersim.model.registry order) as an
integer *literal* and resolves to that model's generated kernel, so each model
gets its own specialised loop and no branch on the model runs per evaluation.
A loop obtains the literal with ``numba.literally(model)`` (integrators/rk4.py,
dop853.py).  Everything a loop needs to know about a model's layout — its
state size, whether its orbit is the held circle, where the densities and ω sit in
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
from tethersim.model.registry import (  # noqa: F401  (KERNELS: re-exported, tests/engine)
    KERNELS,
    MODELS,
    bead_index,
    kernels_of,
    record,
)


def held_circle(model: int) -> bool:
    """True when model ``model`` holds its reference point on the circle r0, ωt.

    Such a model (every circular-orbit model) has no orbit state: its orbit is the
    closed form :func:`held_circle_orbit`; a free-orbit model integrates r and ν.
    """
    return record(model).orbit == "circular"


def held_circle_orbit(r0: float, omega: float, t) -> np.ndarray:
    """The held circle's reference point at times ``t``: (..., 4) of X, Y [m], VX, VY [m/s].

    X = r0 cos ωt, Y = r0 sin ωt, VX = −r0 ω sin ωt, VY = r0 ω cos ωt: the start is
    (r0, 0) moving +Y at r0 ω (Table 4.3), and the two-body motion of Eq 3.9 from
    there is this circle exactly when ω² r0³ = μ (Satellite.omega).

    Parameters
    ----------
    r0 : float
        Orbit radius [m] (the parameter vector's ``r0``).
    omega : float
        Orbital rate [rad/s] (the parameter vector's ``omega``).
    t : array_like
        Times [s].
    """
    wt = omega * np.asarray(t, dtype=float)
    c, s = np.cos(wt), np.sin(wt)
    v = r0 * omega
    return np.stack([r0 * c, r0 * s, -v * s, v * c], axis=-1)


def literal_index(model):
    """The model index a numba type carries as a literal, else None (overloads' typing).

    Only a literal model index picks a kernel: a run-time index is a typing error,
    not a silent fallback to a branch on every evaluation.
    """
    return model.literal_value if isinstance(model, types.IntegerLiteral) else None


def model_rhs(model, t, y, p, dydt):
    """Generated rhs of model ``model`` (an integer literal in compiled code only)."""
    raise NotImplementedError("model_rhs is only callable from compiled code")


def model_size(model, y):
    """Length of model ``model``'s state (``Model.n_state``), a compile-time constant.

    The step functions loop over the state with this bound rather than the array's
    run-time length, so LLVM sees a constant trip count (the C ports' ``#define NS``)
    and unrolls the stage sums; each component's arithmetic is unchanged.  A bead
    chain's state size is its number of beads' (tethersim.model.beads): ``len(y)``.
    """
    raise NotImplementedError("model_size is only callable from compiled code")


def model_tether_margins(model, y, p, g):
    """g[j] = λ_j − l_j0 of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_tether_margins is only callable from compiled code")


def model_densities(model, t, y, p, pw, air):
    """pw = p with ρ1..ρ3 at each body (air vector ``air``; compiled code, literal model only)."""
    raise NotImplementedError("model_densities is only callable from compiled code")


@overload(model_rhs, inline="always", prefer_literal=True)
def _model_rhs(model, t, y, p, dydt):
    if (k := literal_index(model)) is None:
        return None
    rhs = kernels_of(k).rhs

    def impl(model, t, y, p, dydt):
        rhs(t, y, p, dydt)
    return impl


@overload(model_size, inline="always", prefer_literal=True)
def _model_size(model, y):
    if (k := literal_index(model)) is None:
        return None
    if bead_index(k):
        def impl(model, y):
            return y.shape[0]
        return impl
    n = MODELS[k].n_state

    def impl(model, y):
        return n
    return impl


@overload(model_tether_margins, inline="always", prefer_literal=True)
def _model_tether_margins(model, y, p, g):
    if (k := literal_index(model)) is None:
        return None
    margins = kernels_of(k).tether_margins

    def impl(model, y, p, g):
        margins(y, p, g)
    return impl


@overload(model_densities, inline="always", prefer_literal=True)
def _model_densities(model, t, y, p, pw, air):
    if (k := literal_index(model)) is None:
        return None
    radii = kernels_of(k).body_radii
    i1, i2, i3 = (record(k).parameters.index(n) for n in ("rho1", "rho2", "rho3"))
    # the inertial polar angle of the reference point, for the longitude under it:
    # ω t on the held circle (the COM starts on +X, held_circle_orbit), ν + π/2 on a free
    # orbit (R = r (−sin ν, cos ν), docs/orbit.md).  Every body takes this angle: the
    # bodies sit within ~100 m of it, 1.5e-5 rad of longitude, a 0.2 s shift of local
    # time (docs/air.md bounds the density error this makes)
    if held_circle(k):
        i_angle, from_state, offset = record(k).parameters.index("omega"), False, 0.0
    else:
        i_angle, from_state, offset = record(k).state.index("nu"), True, 0.5 * math.pi

    def impl(model, t, y, p, pw, air):
        for i in range(p.shape[0]):  # a loop: no slice-assignment error path to compile
            pw[i] = p[i]
        r1, r2, r3 = radii(y, p)
        angle = y[i_angle] + offset if from_state else p[i_angle] * t
        pw[i1] = body_density(r1 - R_EARTH, angle, t, air)
        pw[i2] = body_density(r2 - R_EARTH, angle, t, air)
        pw[i3] = body_density(r3 - R_EARTH, angle, t, air)
    return impl


@njit(cache=True)
def derivative(model, air, t, y, p, pw, dydt):
    """dy/dt of the integrated state: the generated model's rhs (with the per-body air).

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
        Integrated state (the model's state, its STATE order).
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
    model_rhs(model, t, y, par, dydt)


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
