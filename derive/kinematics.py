"""Frames, points and velocities of the planar thesis model (Eqs 3.10-3.17).

The velocities are not typed in: each is the time derivative of the position
in the inertial frame N, which sympy's frame kinematics evaluates as
d/dt|_L r + ω ẑ × r (Eq 3.13) because the local frame L rotates with ω about z.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.mechanics import Particle, Point, ReferenceFrame

from .symbols import COORDINATES, SPEEDS, TETHER_LENGTHS, P, t

BODY_NAMES = ("tip-mass", "bus", "balloon")


@dataclass(frozen=True)
class Kinematics:
    """Frames, points, positions and inertial velocities of the three bodies.

    ``positions[i]`` and ``velocities[i]`` are sympy vectors of body i+1
    (1 tip-mass, 2 bus, 3 balloon) from Earth's centre, expressed in L.
    ``tether_vectors[j]`` is the vector from the balloon to the far end of
    tether j+1 (τ_j λ_j, Eqs 3.37-3.38) and ``tether_length_defs`` maps the
    symbols λ1, λ2 to their definitions (Eqs 3.41-3.42).
    """

    N: ReferenceFrame
    L: ReferenceFrame
    origin: Point
    points: tuple
    particles: tuple
    positions: tuple
    velocities: tuple
    tether_vectors: tuple
    tether_length_defs: dict
    speeds: tuple = SPEEDS  # generalized speeds of Eq 3.31 (the free orbit adds ṙ, ν̇)


def planar_kinematics() -> Kinematics:
    """Build the thesis geometry: Eqs 3.10-3.12 positions, 3.13-3.17 velocities."""
    dx, dy, th = COORDINATES
    a, b, r0, omega = P["a"], P["b"], P["r0"], P["omega"]
    N = ReferenceFrame("N")
    # L turns about z at the orbital rate: its angular velocity in N is ω ẑ (3.13).
    L = N.orientnew("L", "Axis", [omega * t, N.z])
    O = Point("O")  # Earth's centre, fixed in N
    O.set_vel(N, 0)
    r = (
        b * sp.sin(th) * L.x + (r0 + b * sp.cos(th)) * L.y,  # 3.10 tip-mass
        -a * sp.sin(th) * L.x + (r0 - a * sp.cos(th)) * L.y,  # 3.11 main bus
        dx * L.x + (r0 + dy) * L.y,  # 3.12 balloon
    )
    names = ("P1", "P2", "P3")
    masses = (P["m1"], P["m2"], P["m3"])
    points, particles, vels = [], [], []
    for name, ri, m in zip(names, r, masses):
        pt = O.locatenew(name, ri)
        v = pt.pos_from(O).dt(N).express(L)  # 3.15-3.17 from frame kinematics
        pt.set_vel(N, v)
        points.append(pt)
        vels.append(v)
        particles.append(Particle(f"m_{name}", pt, m))
    tether_vectors = (r[0] - r[2], r[1] - r[2])
    defs = {}
    for lam, vec in zip(TETHER_LENGTHS, tether_vectors):
        x, y = vec.dot(L.x), vec.dot(L.y)
        defs[lam] = sp.sqrt(x**2 + y**2)  # 3.41-3.42
    return Kinematics(N, L, O, tuple(points), tuple(particles), r, tuple(vels),
                      tether_vectors, defs)
