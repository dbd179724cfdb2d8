"""Force families of the 3-D model and their generalized forces (Eqs 3.31-3.47 in 3-D).

Same families, laws and gates as derive/forces.py, with the z components kept:
drag on each body in co-rotating air, tension-only tether springs and either
damper law.  Q_k = Σ_i F_i · ∂ṙ_i/∂q̇_k (Eq 3.31) over the six speeds; the
end bodies are on the boom axis, so no family exerts a torque about it
(Q_ψ = 0 for every family).
"""
from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import partial_velocity

from ..forces import ForceFamily, damper_pull
from .kinematics3d import Kinematics3D
from .symbols3d import TETHER_LENGTHS, TETHER_REST, P

FAMILY_ORDER = ("drag1", "drag2", "drag3", "spring1", "spring2", "damper1", "damper2")


def generalized_forces(kin: Kinematics3D, loads) -> tuple:
    """Eq 3.31 for (point index, force vector) pairs, over the model's speeds.

    Parameters
    ----------
    kin : Kinematics3D
        The geometry (inertial velocities give the partial velocities).
    loads : iterable of (int, sympy Vector)
        Body index and the force applied at its centre [N].

    Returns
    -------
    tuple
        Q_k for q = (δx, δy, δz, φ, θ, ψ) [N, N, N, N m, N m, N m] (then r, ν
        [N, N m] on a free orbit).
    """
    Q = [sp.S.Zero] * len(kin.speeds)
    for i, F in loads:
        pv = partial_velocity([kin.velocities[i]], kin.speeds, kin.N)[0]
        for k, dv in enumerate(pv):
            Q[k] += F.dot(dv)
    return tuple(Q)


def _vector(kin: Kinematics3D, comps):
    return comps[0] * kin.L.x + comps[1] * kin.L.y + comps[2] * kin.L.z


def drag_families(kin: Kinematics3D) -> tuple:
    """−½ C_D A_i ρ_i |V_rel,i| V_rel,i with V_rel,i = ṙ_i − ω_E ẑ × r_i (3.32-3.34).

    The air co-rotates with Earth about the orbit normal (docs/conventions.md),
    so its velocity has no z component; V_rel keeps the body's own ż.
    """
    fams = []
    for i, name in enumerate(("the tip-mass", "the main bus", "the balloon")):
        A, rho = (P["A1"], P["A2"], P["A3"])[i], (P["rho1"], P["rho2"], P["rho3"])[i]
        v = kin.velocities[i] - (P["omega_earth"] * kin.L.z).cross(kin.positions[i])
        comps = kin.components(v)
        speed = sp.sqrt(sum(c**2 for c in comps))
        F = -sp.Rational(1, 2) * P["CD"] * A * rho * speed * _vector(kin, comps)
        fams.append(ForceFamily(f"drag{i + 1}", generalized_forces(kin, [(i, F)]), None,
                                "3.32-3.34", f"air drag on {name}"))
    return tuple(fams)


def relative_velocity(kin: Kinematics3D, end: int):
    """ṙ3 − ṙ_end, each component expanded so the two ω r0 terms cancel exactly."""
    v = kin.velocities[2] - kin.velocities[end]
    return _vector(kin, [sp.expand(c) for c in kin.components(v)])


def _tether_unit(kin: Kinematics3D, j: int):
    """τ_j, unit vector from the balloon to tether j's far end (3.37-3.38)."""
    return kin.tether_vectors[j] / TETHER_LENGTHS[j]


def spring_potential(j: int):
    """½ (E_j / l_j0)(λ_j − l_j0)², the energy of taut tether j [J]."""
    E = (P["E1"], P["E2"])[j]
    return E / (2 * TETHER_REST[j]) * (TETHER_LENGTHS[j] - TETHER_REST[j]) ** 2


def spring_families(kin: Kinematics3D) -> tuple:
    """τ_j E_j (λ_j/l_j0 − 1) on the balloon and its reaction on the end body (3.35-3.42)."""
    fams = []
    for j, (E, end) in enumerate(((P["E1"], 0), (P["E2"], 1))):
        F = _tether_unit(kin, j) * E * (TETHER_LENGTHS[j] / TETHER_REST[j] - 1)
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"spring{j + 1}", Q, j + 1, f"3.3{5 + j}-3.42",
                                f"tension of tether {j + 1}", spring_potential(j)))
    return tuple(fams)


def damper_families(kin: Kinematics3D) -> tuple:
    """The thesis damper −c_j (ṙ3 − ṙ_end) on the balloon (3.43-3.44), in 3-D."""
    fams = []
    for j, (c, end) in enumerate(((P["c1"], 0), (P["c2"], 1))):
        F = -c * relative_velocity(kin, end)
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"damper{j + 1}", Q, j + 1, f"3.4{3 + j}",
                                f"damping of tether {j + 1} (relative velocity)"))
    return tuple(fams)


def objective_damper_families(kin: Kinematics3D) -> tuple:
    """Kelvin-Voigt damper c_j λ̇_j τ_j on the balloon, λ̇_j = −τ_j·(ṙ3 − ṙ_end), clamped
    at the spring's pull (derive/forces.py damper_pull)."""
    fams = []
    for j, (c, end) in enumerate(((P["c1"], 0), (P["c2"], 1))):
        tau = _tether_unit(kin, j)
        rate = sp.expand(-tau.dot(relative_velocity(kin, end)))
        F = damper_pull(c * rate, j) * tau
        Q = generalized_forces(kin, [(2, F), (end, -F)])
        fams.append(ForceFamily(f"damper{j + 1}", Q, j + 1, "variant (issue 5)",
                                f"damping of tether {j + 1} along its stretch rate"))
    return tuple(fams)


def _ordered(fams) -> tuple:
    by_name = {f.name: f for f in fams}
    return tuple(by_name[n] for n in FAMILY_ORDER)


def thesis_families(kin: Kinematics3D) -> tuple:
    """Drag on each body, each tether's spring and thesis damper, in FAMILY_ORDER."""
    return _ordered(drag_families(kin) + spring_families(kin) + damper_families(kin))


def objective_families(kin: Kinematics3D) -> tuple:
    """As :func:`thesis_families` with the Kelvin-Voigt dampers."""
    return _ordered(drag_families(kin) + spring_families(kin) + objective_damper_families(kin))
