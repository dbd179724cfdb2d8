"""What the orbit costs: drag make-up of a held circular orbit, lifetime of a free one.

* :func:`along_track_drag` -- the along-track drag force of the three bodies [N] per
  sample of a circular-orbit run (positive: towards the wake, +x).
* :func:`drag_makeup` -- the velocity per day [m/s/day] a thruster must give to hold
  the thesis's circular orbit: that drag averaged over the run, divided by the mass.
* :func:`lifetime` -- when a free orbit re-entered [s] (``res.reentry_time``), else None.

Drag on body i (the law of derive/forces.py): F_i = −½ C_D A_i ρ_i |V_i| V_i, V_i its
velocity relative to air that co-rotates with the Earth.  In the local frame L (origin
at Earth's centre, rotating at ω ẑ, docs/conventions.md) a body at r = (x, y) moving
at ṙ has V = (ẋ − (ω − ω_E) y, ẏ + (ω − ω_E) x); ρ_i is the run's density (uniform,
or, for ``density = "per-body"``, Vallado or NRLMSISE-00 at the body's own position,
from the run's air vector: tethersim.model.air.vector).  :func:`drag_makeup` is the
compiled kernel that a plan's records use too (tethersim.analysis.makeup_kernel);
:func:`along_track_drag` is this module's own numpy series of the same law, each body
at its own longitude, which the tests hold it to.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.engine.result import SimResult
from tethersim.model.air.vector import body_densities
from tethersim.model.constants import OMEGA_EARTH, R_EARTH


def body_states(res: SimResult) -> dict:
    """Local positions and velocities of the three bodies of a circular-orbit run.

    Returns
    -------
    dict
        ``{"tip-mass" | "bus" | "balloon": (x, y, xdot, ydot)}``, arrays [m, m/s] in L
        (y measured from Earth's centre: r0 + offset).
    """
    s = res.satellite
    r0 = s.r0
    th, thd = res.theta, res.thetadot
    sn, cs = np.sin(th), np.cos(th)
    return {"tip-mass": (s.b * sn, r0 + s.b * cs, s.b * cs * thd, -s.b * sn * thd),
            "bus": (-s.a * sn, r0 - s.a * cs, -s.a * cs * thd, s.a * sn * thd),
            "balloon": (res.x, r0 + res.y, res.xdot, res.ydot)}


def along_track_drag(res: SimResult) -> np.ndarray:
    """Along-track drag of the three bodies [N] per sample (+x, the wake).

    Parameters
    ----------
    res : SimResult
        A run of a circular-orbit model.

    Returns
    -------
    numpy.ndarray
        (n,) the sum of the bodies' drag components along +x.

    Raises
    ------
    ValueError
        For a free-orbit run (no orbit is held, nothing is made up).
    """
    if res.layout.orbit != "circular":
        raise ValueError(f"model {res.model}: drag make-up is for a held circular orbit; "
                         f"a free orbit decays instead (see lifetime)")
    s = res.satellite
    dw = s.omega - OMEGA_EARTH
    areas = {"tip-mass": s.A1, "bus": s.A2, "balloon": s.A3}
    total = np.zeros(res.t.size)
    for body, (x, y, xd, yd) in body_states(res).items():
        vx, vy = xd - dw * y, yd + dw * x
        if res.per_body:
            # the body's inertial polar angle: the COM's ωt plus its angle in L
            # (L's y axis radial at ωt, its x axis at ωt − π/2)
            angle = s.omega * res.t + np.arctan2(-x, y)
            rho = body_densities(np.hypot(x, y) - R_EARTH, angle, res.t, res.air)
        else:
            rho = s.rho
        total += -0.5 * s.CD * areas[body] * rho * np.hypot(vx, vy) * vx
    return total


def drag_makeup(res: SimResult) -> float:
    """Velocity per day [m/s/day] that holds a circular orbit against the drag of the run.

    The along-track drag of the three bodies, averaged over the run's samples in
    time (trapezoid), divided by the total mass, times one day: the compiled kernel
    that a plan's records use too (tethersim.analysis.makeup_kernel; per-body air at
    the point the dynamics take it).  NaN for a free-orbit run or fewer than two
    finite samples.
    """
    if res.layout.orbit != "circular" or res.t.size < 2:
        return math.nan
    from tethersim.analysis.makeup_kernel import drag_makeup_of
    return drag_makeup_of(res.layout.index, res.air, res.t, res.states, res.parameters)


def lifetime(res: SimResult) -> float | None:
    """When the run re-entered [s] (``res.reentry_time``); None if it did not."""
    return res.reentry_time
