"""Frames, points and velocities of the 3-D model (3-D extension of Eqs 3.10-3.17).

Frames: N inertial; L the local frame turning at ω about N.z (Eq 3.13); the
boom's attitude by a body 3-1-2 sequence from L:

  A = L rotated by −θ about L.z   (pitch; A.y = (sin θ, cos θ, 0) as Eq 3.10)
  C = A rotated by  φ about A.x   (roll; the boom C.y leaves the orbit plane)
  B = C rotated by  ψ about C.y   (yaw about the boom axis B.y = C.y)

Body axes B.x (roll), B.y (yaw, the boom, tip-mass side), B.z (pitch) coincide
with L.x, L.y, L.z at φ = θ = ψ = 0.  The tip-mass sits at +b B.y, the bus at
−a B.y from the COM point (0, r0, 0), so at φ = 0 the positions are Eqs
3.10-3.11.  The map (θ̇, φ̇, ψ̇) → angular velocity is singular where
cos φ = 0: the boom along the orbit normal, 90° from the nominal attitude.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.mechanics import Particle, Point, ReferenceFrame, inertia

from .symbols3d import COORDINATES, SPEEDS, TETHER_LENGTHS, P, t

BODY_NAMES = ("tip-mass", "bus", "balloon")


@dataclass(frozen=True)
class Kinematics3D:
    """Frames, points, positions and inertial velocities of the three bodies.

    Attributes
    ----------
    N, L, B : ReferenceFrame
        Inertial, local (orbiting) and boom body frames.
    positions, velocities : tuple of sympy Vector
        Body i+1 (1 tip-mass, 2 bus, 3 balloon) from Earth's centre and its
        inertial velocity (d/dt in N, i.e. d/dt|_L r + ω ẑ × r, Eq 3.13).
    box_inertias : tuple of sympy Dyadic
        Principal inertias of the tip-mass and bus about their own centres,
        on B (roll B.x, yaw B.y, pitch B.z).
    tether_vectors : tuple of sympy Vector
        Balloon → far end of tether j+1 (τ_j λ_j, Eqs 3.37-3.38 in 3-D).
    tether_length_defs : dict
        λ1, λ2 → their definitions (Eqs 3.41-3.42 with the z component).
    radius : sympy.Expr
        Distance of the COM point G from Earth's centre: r0, or r(t) on a free orbit.
    speeds : tuple
        Generalized speeds of Eq 3.31 (the free orbit adds ṙ, ν̇).
    """

    N: ReferenceFrame
    L: ReferenceFrame
    B: ReferenceFrame
    particles: tuple
    positions: tuple
    velocities: tuple
    box_inertias: tuple
    tether_vectors: tuple
    tether_length_defs: dict
    radius: object = P["r0"]
    speeds: tuple = SPEEDS

    def components(self, vec) -> tuple:
        """(x, y, z) components of a vector in the local frame L."""
        return tuple(vec.dot(e) for e in (self.L.x, self.L.y, self.L.z))


def kinematics_3d(radius=None, angle=None, speeds=SPEEDS) -> Kinematics3D:
    """Build the 3-D geometry (positions, velocities, box inertias, tethers).

    Parameters
    ----------
    radius : sympy.Expr, optional
        |G|, the COM point's distance from Earth's centre: r0 (default, Eq 3.14)
        or r(t) on a free orbit (derive/three_d/free3d.py).
    angle : sympy.Expr, optional
        Angle of L from N about z: ωt (default, Eq 3.13) or ν(t).
    speeds : tuple, optional
        Generalized speeds the force families are projected on (Eq 3.31).

    Returns
    -------
    Kinematics3D
        Frames N, L, B; the bodies' positions and inertial velocities in L;
        the box inertia dyadics; the tether vectors and length definitions.
    """
    dx, dy, dz, phi, theta, psi = COORDINATES
    a, b = P["a"], P["b"]
    r0 = P["r0"] if radius is None else radius
    N = ReferenceFrame("N")
    L = N.orientnew("L", "Axis", [P["omega"] * t if angle is None else angle, N.z])  # Eq 3.13
    A = L.orientnew("A", "Axis", [-theta, L.z])  # pitch, clockwise about +z (Eq 3.10)
    C = A.orientnew("C", "Axis", [phi, A.x])  # roll
    B = C.orientnew("B", "Axis", [psi, C.y])  # yaw about the boom
    O = Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", r0 * L.y)  # COM point of the planar model (Eqs 3.10-3.11)
    offsets = (b * B.y, -a * B.y)
    r = tuple((G.pos_from(O) + off).express(L) for off in offsets)
    r = r + ((dx * L.x + (r0 + dy) * L.y + dz * L.z),)
    masses = (P["m1"], P["m2"], P["m3"])
    particles, vels = [], []
    for k, (ri, m) in enumerate(zip(r, masses)):
        pt = O.locatenew(f"P{k + 1}", ri)
        v = ri.dt(N).express(L)
        pt.set_vel(N, v)
        vels.append(v)
        particles.append(Particle(f"m_P{k + 1}", pt, m))
    boxes = tuple(inertia(B, P[f"I{k}_roll"], P[f"I{k}_yaw"], P[f"I{k}_pitch"]) for k in (1, 2))
    tether_vectors = (r[0] - r[2], r[1] - r[2])
    defs = {}
    for lam, vec in zip(TETHER_LENGTHS, tether_vectors):
        x, y, z = (vec.dot(e) for e in (L.x, L.y, L.z))
        defs[lam] = sp.sqrt(x**2 + y**2 + z**2)
    return Kinematics3D(N, L, B, tuple(particles), r, tuple(vels), boxes,
                        tether_vectors, defs, r0, tuple(speeds))
