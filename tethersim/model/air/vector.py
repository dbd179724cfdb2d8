"""The air as a compiled loop reads it: one flat float array, the *air vector*.

A run's air settings (:class:`~tethersim.model.air.AirModel`, the density mode
and ``density_scale``) become one read-only float64 array, so that the compiled
loops carry the whole atmosphere — MSIS grid included — in one borrowed array
and never branch on Python objects:

==========  ==============================================================
air[0]      mode: 0 uniform (the parameter vector's ρ1..ρ3: the thesis),
            1 Vallado's table at each body's altitude, 2 NRLMSISE-00 at
            each body's altitude, longitude and time (the packed grid)
air[1]      ``density_scale`` (per-body modes; the uniform ρ is scaled already)
air[2]      Greenwich sidereal angle at the epoch [rad] (grid.gmst)
air[3]      Earth's rotation rate [rad/s]
air[4:]     mode 2: the packed MSIS grid (grid.pack)
==========  ==============================================================

:func:`body_density` is the one kernel that turns (altitude, inertial polar
angle, time) into a density for the per-body modes.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from tethersim.model.air import grid as _grid
from tethersim.model.air.model import AirModel, msis_table
from tethersim.model.atmosphere import TABLE, density_kernel
from tethersim.model.constants import OMEGA_EARTH

AIR_FIELDS = ("mode", "scale", "theta0", "omega_earth")
UNIFORM, VALLADO, MSIS = 0, 1, 2
N_HEAD = len(AIR_FIELDS)


def air_vector(air: AirModel, per_body: bool, scale: float, duration_s: float) -> np.ndarray:
    """The air vector of a run.

    Parameters
    ----------
    air : AirModel
        Which air (kind, epoch, indices).
    per_body : bool
        Each body at its own altitude (else the uniform density of the parameter vector).
    scale : float
        ``density_scale``, applied by :func:`body_density` in the per-body modes.
    duration_s : float
        Length of the run [s]: the MSIS grid covers its UTC days.

    Returns
    -------
    numpy.ndarray
        Read-only float64 array laid out as :data:`AIR_FIELDS` (+ the MSIS grid).
    """
    if not per_body:
        return uniform_air()
    mode = MSIS if air.kind == "nrlmsise00" else VALLADO
    head = np.array([mode, scale, _grid.gmst(air.epoch), OMEGA_EARTH], dtype=np.float64)
    out = np.concatenate([head, msis_table(air, duration_s)]) if mode == MSIS else head
    out.setflags(write=False)
    return out


@njit(cache=True)
def body_density(h, angle, t, air):
    """Density [kg/m^3] at one body in a per-body mode of the air vector ``air``.

    Parameters
    ----------
    h : float
        The body's altitude above the WGS-84 equatorial radius [m].
    angle : float
        Inertial polar angle of the body [rad] in the equatorial plane (the
        longitude follows from the Earth's rotation since the epoch).
    t : float
        Time since the epoch [s].
    air : numpy.ndarray
        The air vector (:func:`air_vector`), mode 1 or 2.

    Returns
    -------
    float
        ``density_scale`` times Vallado's or NRLMSISE-00's density; NaN outside
        the model's altitudes (or, MSIS, outside the grid's days).
    """
    if air[0] == VALLADO:
        return air[1] * density_kernel(h, TABLE)
    lon = _grid.longitude_of(angle, t, air[2], air[3])
    return air[1] * _grid.msis_density_kernel(h, lon, t, air, N_HEAD)


@njit(cache=True)
def body_densities(h, angle, t, air):
    """:func:`body_density` at each of the points (h[i], angle[i], t[i]) (arrays, SI)."""
    out = np.empty(h.shape[0])
    for i in range(h.shape[0]):
        out[i] = body_density(h[i], angle[i], t[i], air)
    return out


def uniform_air() -> np.ndarray:
    """The air vector of the uniform mode (the thesis): ρ1..ρ3 from the parameter vector."""
    out = np.array([UNIFORM, 1.0, 0.0, OMEGA_EARTH], dtype=np.float64)
    out.setflags(write=False)
    return out
