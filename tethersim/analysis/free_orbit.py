"""What an engineer reads off a free-orbit run: altitude, orbit elements, air density.

* :func:`osculating_elements` -- semi-major axis and eccentricity of the two-body
  (point-mass) orbit through the boom COM's position and velocity at each sample;
* :func:`body_air_densities` -- the density each body met [kg/m^3], as the run's
  compiled loop computed it (the same kernel, the run's own air vector);
* :func:`free_orbit_series` -- these as the extra time-series columns of a free-orbit
  run (tethersim.output.tables writes them to CSV and NetCDF).

The COM is the model's reference point (``SimResult.orbit``); altitude is its radius
minus R_E (``SimResult.altitude``), the quantity the re-entry check uses.
"""
from __future__ import annotations

import numpy as np

from tethersim.engine.bodies import BODY_NAMES
from tethersim.engine.result import SimResult
from tethersim.model.air.vector import body_densities
from tethersim.model.constants import MU_EARTH, R_EARTH


def osculating_elements(res: SimResult) -> tuple:
    """(a [m], e [1]) of the osculating Keplerian orbit of the boom COM, per sample.

    From vis-viva, 1/a = 2/r − v²/μ, and the eccentricity vector
    e = ((v² − μ/r) R − (R·V) V) / μ of the COM's inertial R, V (``res.orbit``).
    Point-mass gravity: with J2 on, these are the Keplerian elements of the
    instantaneous state, which oscillate about the mean ones.
    """
    X, Y, VX, VY = res.orbit.T
    r = np.hypot(X, Y)
    v2 = VX * VX + VY * VY
    a = 1.0 / (2.0 / r - v2 / MU_EARTH)
    rv = X * VX + Y * VY
    ex = ((v2 - MU_EARTH / r) * X - rv * VX) / MU_EARTH
    ey = ((v2 - MU_EARTH / r) * Y - rv * VY) / MU_EARTH
    return a, np.hypot(ex, ey)


def body_air_densities(res: SimResult) -> np.ndarray:
    """(n, 3) air density [kg/m^3] at the tip-mass, bus and balloon at each sample.

    The run's own air: the uniform density (the parameter vector's ρ) in the uniform
    mode; else :func:`~tethersim.model.air.vector.body_density` of the run's air
    vector at each body's altitude |R_i| − R_E, at the COM's inertial polar angle
    (as the compiled loop does; tethersim.engine.dynamics).  NaN where a body is
    outside the air model's altitudes.
    """
    n = res.t.size
    if not res.per_body:
        return np.full((n, len(BODY_NAMES)), res.satellite.rho)
    heights = np.linalg.norm(res.bodies().position, axis=-1) - R_EARTH  # (n, 3)
    angle = np.arctan2(res.orbit[:, 1], res.orbit[:, 0])
    t = np.ascontiguousarray(res.t, dtype=np.float64)
    return np.column_stack([body_densities(np.ascontiguousarray(heights[:, i]), angle, t,
                                           res.air) for i in range(len(BODY_NAMES))])


def free_orbit_series(res: SimResult) -> list:
    """[(name, values, unit)] of the derived columns of a free-orbit run; [] otherwise.

    ``altitude`` [m] of the boom COM, the osculating ``semi_major_axis`` [m] and
    ``eccentricity`` [1], and ``rho_tip_mass``, ``rho_bus``, ``rho_balloon``
    [kg/m^3], the air density each body met.
    """
    if res.layout.orbit != "free" or res.t.size == 0:
        return []
    a, e = osculating_elements(res)
    rho = body_air_densities(res)
    out = [("altitude", res.altitude, "m"), ("semi_major_axis", a, "m"),
           ("eccentricity", e, "1")]
    out += [(f"rho_{b.replace('-', '_')}", rho[:, i], "kg/m^3") for i, b in enumerate(BODY_NAMES)]
    return out
