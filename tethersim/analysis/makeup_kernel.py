"""Drag make-up of a held circular orbit in compiled code: the one implementation.

:func:`tethersim.analysis.orbit_life.drag_makeup` (and so ``outcome()``) calls
:func:`drag_makeup_of` from Python, and a sweep's compiled block
(tethersim.experiments.sweep.kernel) calls :func:`drag_makeup_kernel` without leaving
compiled code: one function, so a plan's record and ``outcome()`` give the same number
bit for bit.

The make-up is the along-track drag of the three bodies, averaged in time over the
samples (trapezoid rule; non-finite samples skipped), over the total mass, times one
day [m/s/day].  Each body i (tip-mass, bus, balloon) at r = (x, y) in the local frame L
(y from Earth's centre) moving at ṙ meets air that co-rotates with the Earth, so its
velocity relative to the air is V = (ẋ − (ω − ω_E) y, ẏ + (ω − ω_E) x) and its drag
along +x is −½ C_D A_i ρ_i |V| V_x (derive/forces.py's law).  Tip-mass at
(b sin θ, r0 + b cos θ), bus at (−a sin θ, r0 − a cos θ), balloon at (δx, r0 + δy):
the planar geometry of Eq 3.9, which a 3-D model's θ, δx, δy also give (its roll and
yaw tilt the boom out of the plane; the along-track drag keeps the in-plane terms, as
:func:`~tethersim.analysis.orbit_life.along_track_drag` does).  ρ_i: the run's uniform
densities, or, in per-body air, each body's from the run's air vector at the same
point the dynamics take it (engine/dynamics.py ``model_densities``).  A free-orbit
model holds no orbit: NaN.
"""
from __future__ import annotations

import math

import numpy as np
from numba import literally, njit
from numba.extending import overload

from tethersim.engine.dynamics import held_circle, literal_index, model_densities
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.select import call
from tethersim.engine.integrators.steps import copy_into
from tethersim.generated.trig import sincos
from tethersim.model.air.indices import DAY
from tethersim.model.air.vector import UNIFORM
from tethersim.model.registry import record

_STATES = ("delta_x", "delta_y", "theta", "delta_x_dot", "delta_y_dot", "theta_dot")
_PARAMETERS = ("A1", "A2", "A3", "a", "b", "CD", "r0", "omega",
               "omega_earth", "rho1", "rho2", "rho3")


def model_mass(model, p):
    """m1 + m2 + m3 [kg] of parameter vector ``p`` (compiled code, literal model only)."""
    raise NotImplementedError("model_mass is only callable from compiled code")


@overload(model_mass, inline="always", prefer_literal=True)
def _model_mass(model, p):
    if (k := literal_index(model)) is None:
        return None
    m1, m2, m3 = (record(k).parameters.index(n) for n in ("m1", "m2", "m3"))

    def impl(model, p):
        return p[m1] + p[m2] + p[m3]
    return impl


def model_along_track_drag(model, Y, i, q):
    """Along-track drag of the three bodies [N] at sample ``i`` of states ``Y``, densities
    and all from parameter vector ``q`` (compiled code, literal model only; NaN for a
    model that holds no circular orbit)."""
    raise NotImplementedError("model_along_track_drag is only callable from compiled code")


@overload(model_along_track_drag, inline="always", prefer_literal=True)
def _model_along_track_drag(model, Y, i, q):
    if (k := literal_index(model)) is None:
        return None
    if not held_circle(k):
        def nothing(model, Y, i, q):
            return math.nan
        return nothing
    rec = record(k)
    ix, iy, ith, ixd, iyd, ithd = (rec.state.index(s) for s in _STATES)
    a1, a2, a3, ia, ib, icd, ir0, iw, iwe, i1, i2, i3 = (
        rec.parameters.index(n) for n in _PARAMETERS)

    def impl(model, Y, i, q):
        dw = q[iw] - q[iwe]
        r0, a, b, thd = q[ir0], q[ia], q[ib], Y[i, ithd]
        # the kernels' own sin and cos (generated/trig.py: within 1 ulp of libm, no call)
        # and sqrt for hypot (|V| ~ 7.7 km/s: no overflow): the bench's 64-point sweep
        # pays 1-2 % for its records' make-up, against 3-4 % with libm's calls
        sn, cs = sincos(Y[i, ith])
        total = 0.0
        for x, y, xd, yd, area, rho in (
                (b * sn, r0 + b * cs, b * cs * thd, -b * sn * thd, q[a1], q[i1]),
                (-a * sn, r0 - a * cs, -a * cs * thd, a * sn * thd, q[a2], q[i2]),
                (Y[i, ix], r0 + Y[i, iy], Y[i, ixd], Y[i, iyd], q[a3], q[i3])):
            vx, vy = xd - dw * y, yd + dw * x
            total += -0.5 * q[icd] * area * rho * math.sqrt(vx * vx + vy * vy) * vx
        return total
    return impl


@njit(cache=True, nogil=True)
def drag_makeup_kernel(model, air, T, Y, n, p):
    """Velocity per day [m/s/day] that holds the circular orbit against the drag of the
    first ``n`` samples (times T, states Y rows); NaN with fewer than two finite ones."""
    literally(model)
    f = np.empty(n)
    if air[0] == UNIFORM:  # p's densities: a loop without a call
        for i in range(n):
            f[i] = model_along_track_drag(model, Y, i, p)
    else:  # pw: p with each body's density, where the dynamics take it
        pw = np.empty(p.shape[0])  # not p.copy(): p may be borrowed (borrow.py)
        copy_into(borrow(pw), p)
        for i in range(n):
            model_densities(model, T[i], Y[i], p, pw, air)
            f[i] = model_along_track_drag(model, Y, i, pw)
    total, count = 0.0, 0
    t0 = t_prev = f0 = f_prev = math.nan
    for i in range(n):
        if not math.isfinite(f[i]):
            continue
        if count == 0:
            t0, f0 = T[i], f[i]
        else:  # numpy's trapezoid term, (Δt (f_i + f_i-1)) / 2
            total += (T[i] - t_prev) * (f[i] + f_prev) / 2.0
        t_prev, f_prev, count = T[i], f[i], count + 1
    if count < 2:
        return math.nan
    mean = total / (t_prev - t0) if t_prev > t0 else f0
    return mean / model_mass(model, p) * DAY


@njit(cache=True, nogil=True)
def _drag_makeup_of(model, air, T, Y, p):
    # on borrowed views: the types a sweep's compiled block passes (sweep/kernel.py
    # _measure), so one compiled loop serves both (the compile-once rule)
    literally(model)
    return drag_makeup_kernel(model, borrow(air), borrow(T), borrow(Y), T.shape[0], borrow(p))


def drag_makeup_of(model: int, air, T, Y, p) -> float:
    """Drag make-up [m/s/day] of samples (T, Y) of model index ``model`` (parameter vector
    ``p``, air vector ``air``; C-contiguous float arrays); NaN for a free-orbit model."""
    return call(_drag_makeup_of, model, air, T, Y, p)
