"""Inertial kinematics of the three bodies from any model's state (issue 13).

Every model (planar, 3-D, circular or free orbit) describes the same geometry
(derive/kinematics.py, derive/three_d/kinematics3d.py, docs/conventions.md):

* the local frame L turns about the orbit normal ẑ by the angle Λ from the
  inertial frame N: Λ = ωt − π/2 for a circular-orbit model (the COM at polar
  angle ωt, r0 (cos ωt, sin ωt, 0): at t = 0 on +X moving along +Y, as the
  runtime's COM orbit columns X, Y), Λ = ν for a free-orbit model
  (R = r (−sin ν, cos ν, 0), docs/orbit.md);
* the boom COM G = r L.y (r = r0 on a circular orbit);
* the boom frame B = Rz(Λ) Rz(−θ) Rx(φ) Ry(ψ) (body 3-1-2 from L: pitch −θ
  about L.z, roll φ about the pitched x, yaw ψ about the boom); B's columns are
  the roll axis, the boom axis (tip-mass side, the yaw axis) and the pitch axis;
* tip-mass at G + b B.y, bus at G − a B.y, balloon at G + (δx, δy, δz) in L.

A planar model is the 3-D one with φ = ψ = δz = 0 (states it does not have
are zero).  Nothing here is generated: it is the independent map from a
model's coordinates to inertial positions, velocities and accelerations that
Newton–Euler checks need (tests/analysis/test_bodies.py).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tethersim.model.registry import get_model
from tethersim.model.satellite import Satellite

BODY_NAMES = ("tip-mass", "bus", "balloon")
_COORDS = ("delta_x", "delta_y", "delta_z", "phi", "theta", "psi", "r", "nu")


@dataclass(frozen=True)
class Bodies:
    """Inertial positions and velocities of the three bodies and the boom's attitude.

    Arrays have a leading sample axis when built along a run
    (:meth:`tethersim.SimResult.bodies`); SI, in the inertial frame N (X, Y in
    the orbit plane, Z the orbit normal).

    Attributes
    ----------
    t : numpy.ndarray
        Time [s].
    position, velocity : numpy.ndarray
        (..., 3, 3): body (``BODY_NAMES``: tip-mass, bus, balloon) × (X, Y, Z) [m, m/s].
    com_position, com_velocity : numpy.ndarray
        (..., 3): the boom COM (the reference point of the models) [m, m/s].
    offset : numpy.ndarray
        (..., 3, 3): position minus COM position of each body, computed without
        the orbit radius (no rounding at the 1e-9 m of a 6.6e6 m position) [m].
    attitude : numpy.ndarray
        (..., 3, 3): the boom's attitude matrix, columns the body axes in N:
        roll axis, boom axis (tip-mass side; yaw axis), pitch axis.
    angular_velocity : numpy.ndarray
        (..., 3): the boom's inertial angular velocity in N [rad/s].
    """

    t: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    com_position: np.ndarray
    com_velocity: np.ndarray
    offset: np.ndarray
    attitude: np.ndarray
    angular_velocity: np.ndarray

    def __getitem__(self, name: str) -> np.ndarray:
        """Position of the body called ``name`` (``"tip-mass"``, ``"bus"``, ``"balloon"``)."""
        return self.position[..., BODY_NAMES.index(name), :]


@dataclass(frozen=True)
class BodyAccelerations:
    """Inertial accelerations at one state (SI, frame N as :class:`Bodies`).

    Attributes
    ----------
    acceleration : numpy.ndarray
        (3, 3): body (tip-mass, bus, balloon) × (X, Y, Z) [m/s²].
    com_acceleration : numpy.ndarray
        (3,): the boom COM's [m/s²].
    angular_acceleration : numpy.ndarray
        (3,): the boom's inertial angular acceleration in N [rad/s²].
    """

    acceleration: np.ndarray
    com_acceleration: np.ndarray
    angular_acceleration: np.ndarray


def _rot(axis: int, ang):
    """Active rotation matrices (..., 3, 3) about coordinate axis ``axis``."""
    c, s = np.cos(ang), np.sin(ang)
    one = np.ones_like(c)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    R = np.zeros(c.shape + (3, 3))
    R[..., axis, axis] = one
    R[..., i, i], R[..., j, j] = c, c
    R[..., i, j], R[..., j, i] = -s, s
    return R


def _mv(R, v):
    return np.einsum("...ij,...j->...i", R, v)


def _coordinates(model: str, sat: Satellite, t, states: np.ndarray) -> dict:
    """q, q̇ by name (zeros for coordinates the model lacks), plus Λ, Λ̇, r, ṙ."""
    m = get_model(model)
    n = m.n_coordinates
    q = {k: np.zeros(states.shape[:-1]) for k in _COORDS}
    qd = {k: np.zeros(states.shape[:-1]) for k in _COORDS}
    for i, name in enumerate(m.state[:n]):
        q[name], qd[name] = states[..., i], states[..., n + i]
    if m.orbit == "free":
        lam, lamd = q["nu"], qd["nu"]
    else:
        q["r"] = np.full(states.shape[:-1], sat.r0)
        lam = sat.omega * np.asarray(t, float) - np.pi / 2 + np.zeros(states.shape[:-1])
        lamd = np.full(states.shape[:-1], sat.omega)
    q["Lambda"], qd["Lambda"] = lam, lamd
    return q, qd


def _frames(q):
    """Rotation matrices N←L, N←A, N←C, N←B."""
    RL = _rot(2, q["Lambda"])
    RA = RL @ _rot(2, -q["theta"])
    RC = RA @ _rot(0, q["phi"])
    RB = RC @ _rot(1, q["psi"])
    return RL, RA, RC, RB


def _kinematics(sat: Satellite, q, qd):
    RL, RA, RC, RB = _frames(q)
    z = np.array([0.0, 0.0, 1.0])
    ez = np.broadcast_to(z, RL.shape[:-1])
    r, rd, lamd = q["r"], qd["r"], qd["Lambda"]
    Ly, Lx = RL[..., :, 1], RL[..., :, 0]
    G = r[..., None] * Ly
    vG = rd[..., None] * Ly - (r * lamd)[..., None] * Lx
    w = ((lamd - qd["theta"])[..., None] * ez + qd["phi"][..., None] * RA[..., :, 0]
         + qd["psi"][..., None] * RC[..., :, 1])
    boom = RB[..., :, 1]
    ends = (sat.b, -sat.a)
    off = [d * boom for d in ends]
    vel = [vG + d * np.cross(w, boom) for d in ends]
    p = np.stack([q["delta_x"], r + q["delta_y"], q["delta_z"]], axis=-1)
    pd = np.stack([qd["delta_x"], rd + qd["delta_y"], qd["delta_z"]], axis=-1)
    off.append(_mv(RL, np.stack([q["delta_x"], q["delta_y"], q["delta_z"]], axis=-1)))
    off = np.stack(off, -2)
    vel.append(_mv(RL, pd + lamd[..., None] * np.cross(ez, p)))
    return RL, RA, RC, RB, G, vG, w, G[..., None, :] + off, np.stack(vel, -2), off


def bodies_from_states(sat: Satellite, model: str, t, states) -> Bodies:
    """:class:`Bodies` of ``model``'s states (..., n_state) at times ``t`` (broadcast)."""
    states = np.asarray(states, float)
    q, qd = _coordinates(model, sat, t, states)
    _, _, _, RB, G, vG, w, pos, vel, off = _kinematics(sat, q, qd)
    tt = np.asarray(t, float) + np.zeros(states.shape[:-1])
    return Bodies(tt, pos, vel, G, vG, off, RB, w)


def accelerations_from_qdd(sat: Satellite, model: str, t: float, state, qdd) -> BodyAccelerations:
    """Inertial accelerations from a state and its generalized accelerations q̈."""
    m = get_model(model)
    state = np.asarray(state, float)
    q, qd = _coordinates(model, sat, t, state)
    qdd_named = {k: 0.0 for k in _COORDS}
    qdd_named.update(dict(zip(m.state[:m.n_coordinates], np.asarray(qdd, float))))
    lamdd = qdd_named["nu"] if m.orbit == "free" else 0.0
    RL, RA, RC, RB, G, vG, w, pos, vel, _ = _kinematics(sat, q, qd)
    ez = np.array([0.0, 0.0, 1.0])
    lamd, thd, phd, psd = qd["Lambda"], qd["theta"], qd["phi"], qd["psi"]
    wA = (lamd - thd) * ez
    wC = wA + phd * RA[:, 0]
    alpha = ((lamdd - qdd_named["theta"]) * ez + qdd_named["phi"] * RA[:, 0]
             + phd * np.cross(wA, RA[:, 0]) + qdd_named["psi"] * RC[:, 1]
             + psd * np.cross(wC, RC[:, 1]))
    r, rd = q["r"], qd["r"]
    # local-frame vector p(t) = (δx, r + δy, δz): ä = R (p̈ + 2Λ̇ ẑ×ṗ + Λ̈ ẑ×p + Λ̇² ẑ×(ẑ×p))

    def local_acc(p, pd, pdd):
        return RL @ (pdd + 2 * lamd * np.cross(ez, pd) + lamdd * np.cross(ez, p)
                     + lamd**2 * np.cross(ez, np.cross(ez, p)))
    aG = local_acc(np.array([0.0, r, 0.0]), np.array([0.0, rd, 0.0]),
                   np.array([0.0, qdd_named["r"], 0.0]))
    p3 = np.array([q["delta_x"], r + q["delta_y"], q["delta_z"]])
    pd3 = np.array([qd["delta_x"], rd + qd["delta_y"], qd["delta_z"]])
    pdd3 = np.array([qdd_named["delta_x"], qdd_named["r"] + qdd_named["delta_y"],
                     qdd_named["delta_z"]])
    boom = RB[:, 1]
    acc = [aG + d * (np.cross(alpha, boom) + np.cross(w, np.cross(w, boom)))
           for d in (sat.b, -sat.a)]
    acc.append(local_acc(p3, pd3, pdd3))
    return BodyAccelerations(np.array(acc), aG, alpha)
