"""Force families and their generalized forces (Eqs 3.31-3.47).

A force family is a set of forces applied at the bodies' points, gated by
the tautness of at most one tether.  Its generalized force on coordinate k is
Eq 3.31, Q_k = Σ_i F_i · ∂r_i/∂q_k, computed with partial velocities
∂v_i/∂q̇_k = ∂r_i/∂q_k (the term-4 loop of sympy's LagrangesMethod).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.physics.mechanics import partial_velocity

from .kinematics import Kinematics
from .symbols import TETHER_LENGTHS, TETHER_REST, P


@dataclass(frozen=True)
class ForceFamily:
    """One family of generalized forces (Q_δx, Q_δy, Q_θ) in N, N, N m.

    ``tether`` is 1 or 2 when the family acts only while that tether is taut
    (γ_j = λ_j / l_j0 > 1, Eqs 3.35-3.36, 3.43-3.44), else None.
    """

    name: str
    Q: tuple
    tether: int | None
    equation: str
    meaning: str
    potential: object = None  # J, for conservative families (springs)


def generalized_forces(kin: Kinematics, loads) -> tuple:
    """Eq 3.31 for a list of (point index, force vector) pairs."""
    Q = [sp.S.Zero] * len(kin.speeds)
    for i, F in loads:
        pv = partial_velocity([kin.velocities[i]], kin.speeds, kin.N)[0]
        for k, dv in enumerate(pv):
            Q[k] += F.dot(dv)
    return tuple(Q)


def relative_air_velocity(kin: Kinematics, i: int):
    """V_rel,i of Eq 3.33, expressed in the local frame.

    Rotating ṙ_i and r_i to inertial axes with Rot(ωt) (3.34), subtracting
    ω_E ẑ × r, and rotating back (as the thesis does) equals ṙ_i − ω_E ẑ × r_i
    in local axes, because a rotation about z commutes with ẑ×.  The
    atmosphere co-rotates with Earth, in the same sense as the orbit.
    """
    return kin.velocities[i] - (P["omega_earth"] * kin.L.z).cross(kin.positions[i])


def drag_load(kin: Kinematics, i: int):
    """F_drag,i = −½ C_D A_i ρ_i |V_rel,i| V_rel,i (Eq 3.32), in N."""
    A = (P["A1"], P["A2"], P["A3"])[i]
    rho = (P["rho1"], P["rho2"], P["rho3"])[i]
    v = relative_air_velocity(kin, i)
    vx, vy = v.dot(kin.L.x), v.dot(kin.L.y)
    speed = sp.sqrt(vx**2 + vy**2)
    return (i, -sp.Rational(1, 2) * P["CD"] * A * rho * speed * v)


def drag_families(kin: Kinematics) -> tuple:
    """Drag on each of the three bodies, one family each (3.32-3.34, 3.45-3.47)."""
    return tuple(
        ForceFamily(f"drag{i + 1}", generalized_forces(kin, [drag_load(kin, i)]), None,
                    "3.32-3.34", f"air drag on {name}")
        for i, name in enumerate(("the tip-mass", "the main bus", "the balloon"))
    )


def relative_velocity(kin: Kinematics, end: int):
    """ṙ3 − ṙ_end with each component expanded.

    Expanding cancels the two ω r0 terms (about 7.7 km/s each) symbolically;
    left as printed they would leave a cm/s difference at ~1e-11 relative error.
    """
    v = kin.velocities[2] - kin.velocities[end]
    return sum((sp.expand(v.dot(e)) * e for e in (kin.L.x, kin.L.y)), 0 * kin.L.x)


def _tether_unit(kin: Kinematics, j: int):
    """τ_j: unit vector from the balloon to tether j's far end (3.37-3.38)."""
    return kin.tether_vectors[j] / TETHER_LENGTHS[j]


def spring_families(kin: Kinematics) -> tuple:
    """Tether tension τ_j E_j (γ_j − 1) on the balloon, its reaction on the end body."""
    fams = []
    for j, (E, end) in enumerate(((P["E1"], 0), (P["E2"], 1))):
        gamma = TETHER_LENGTHS[j] / TETHER_REST[j]  # 3.39-3.40
        F = _tether_unit(kin, j) * E * (gamma - 1)  # 3.35-3.36 (taut branch)
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"spring{j + 1}", Q, j + 1, f"3.3{5 + j}-3.42",
                                f"tension of tether {j + 1}", spring_potential(j)))
    return tuple(fams)


def spring_potential(j: int):
    """½ (E_j / l_j0)(λ_j − l_j0)², the energy stored in taut tether j [J]."""
    E = (P["E1"], P["E2"])[j]
    return E / (2 * TETHER_REST[j]) * (TETHER_LENGTHS[j] - TETHER_REST[j]) ** 2


def damper_families(kin: Kinematics) -> tuple:
    """The thesis damper: −c_j (ṙ3 − ṙ_end) on the balloon (3.43-3.44).

    It damps the whole relative inertial velocity of the tether's ends, so it
    also resists the rigid rotation ω ẑ × (r3 − r_end) of the formation.
    """
    fams = []
    for j, (c, end) in enumerate(((P["c1"], 0), (P["c2"], 1))):
        F = -c * relative_velocity(kin, end)
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"damper{j + 1}", Q, j + 1, f"3.4{3 + j}",
                                f"damping of tether {j + 1} (relative velocity)"))
    return tuple(fams)


def damper_pull(force, j: int):
    """A Kelvin-Voigt damper's force ``force`` = c_j λ̇_j along taut tether j, clamped at minus
    its spring's pull, max(c_j λ̇_j, −E_j (λ_j / l_j0 − 1)), so that spring plus damper
    never push (a line goes slack rather than push, the rule of tether codes such as
    GTOSS). The clamp is a kink, not a switch: the line's force reaches zero
    continuously, and the damper still only takes energy out, −D λ̇ <= 0 (when it holds,
    λ̇ < 0 and the stretch is positive), so the Jacobi integral's budget keeps the
    damper's power as it is.
    """
    spring = (P["E1"], P["E2"])[j] * (TETHER_LENGTHS[j] / TETHER_REST[j] - 1)
    return sp.Max(force, -spring)


def objective_damper_families(kin: Kinematics) -> tuple:
    """Kelvin-Voigt damper: c_j λ̇_j τ_j on the balloon, acting along the tether, clamped
    at the spring's pull (:func:`damper_pull`).

    λ̇_j = −τ_j·(ṙ3 − ṙ_end) is the rate of stretch, the same in every frame,
    so a rigid rotation of the formation (λ̇ = 0) is not resisted.
    """
    fams = []
    for j, (c, end) in enumerate(((P["c1"], 0), (P["c2"], 1))):
        tau = _tether_unit(kin, j)
        rate = sp.expand(-tau.dot(relative_velocity(kin, end)))
        F = damper_pull(c * rate, j) * tau
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"damper{j + 1}", Q, j + 1, "variant (issue 5)",
                                f"damping of tether {j + 1} along its stretch rate"))
    return tuple(fams)
