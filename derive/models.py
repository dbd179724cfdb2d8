"""Every model: each a definition fed to the one pipeline (derive.model.derive).

Planar, circular orbit (the thesis's variants):

derived          the default: thesis model (3.10-3.47) derived cleanly, the
                 Lagrange equations truncated to the printed order (3.28-3.30).
printed          Eqs 3.48-3.50 exactly as printed, errata included.
exact-gravity    as derived, without the binomial expansion (V = −μ m/|r|).
objective-damper as derived, with Kelvin-Voigt tether dampers acting along the
                 tether on its stretch rate instead of Eqs 3.43-3.44.

3-D, circular orbit (roll, pitch, yaw; balloon in 3-D; docs/three-d.md):

3d                  thesis gravity (three binomial terms per inverse power,
                    equations truncated at O(1/r0) as Eqs 3.28-3.30) and the
                    thesis dampers (3.43-3.44).
3d-exact-gravity    point-mass + MacCullagh gravity with exact |r_i|, no
                    truncation; thesis dampers.
3d-objective-damper as 3d with Kelvin-Voigt dampers along the tethers.

Free orbit (r, ν as coordinates; docs/orbit.md), each with its circular twin:
free, free-exact-gravity, free-objective-damper (planar) and 3d-free,
3d-free-objective-damper (3-D; derive/three_d/free3d.py says why there is no
3-D free exact-gravity model).

The order of DEFINITIONS is the order of tethersim.MODELS.
"""
from __future__ import annotations

from . import printed
from .coordinates import FREE, FREE_3D, PLANAR, THREE_D
from .energy import inverse_distance_binomial, inverse_distance_exact
from .forces import (
    ForceFamily,
    damper_families,
    drag_families,
    objective_damper_families,
    spring_families,
    spring_potential,
)
from .model import ModelDefinition
from .orbit import inverse_powers_binomial, inverse_powers_exact
from .three_d import forces3d
from .three_d.energy3d import binomial_power, exact_power
from .three_d.free3d import TRUNCATION_DEGREE, taylor_power

FAMILY_ORDER = ("drag1", "drag2", "drag3", "spring1", "spring2", "damper1", "damper2")


def _ordered(fams) -> tuple:
    by_name = {f.name: f for f in fams}
    return tuple(by_name[n] for n in FAMILY_ORDER)


def thesis_families(kin):
    """Drag on each body, each tether's spring and each tether's damper (3.31-3.47)."""
    return _ordered(drag_families(kin) + spring_families(kin) + damper_families(kin))


def objective_families(kin):
    return _ordered(drag_families(kin) + spring_families(kin)
                    + objective_damper_families(kin))


def printed_families(kin):
    """Eqs 3.48-3.50 as printed (the kinematics are not used)."""
    return tuple(ForceFamily(n, printed.FAMILIES[n], printed.FAMILY_TETHER[n],
                             "3.48-3.50", f"{n} as printed",
                             spring_potential(int(n[-1]) - 1) if n.startswith("spring") else None)
                 for n in FAMILY_ORDER)


PLANAR_DEFINITIONS = (
    ModelDefinition("derived", "clean derivation of the thesis model, truncated to the "
                    "order of Eqs 3.28-3.30", PLANAR, inverse_distance_binomial,
                    1, thesis_families),
    ModelDefinition("printed", "Eqs 3.48-3.50 exactly as printed in the thesis, errata "
                    "included", PLANAR, inverse_distance_binomial, None,
                    printed_families, lhs_override=printed.LHS),
    ModelDefinition("exact-gravity", "derived model with exact point-mass gravity "
                    "mu/|r| (no binomial expansion, no truncation)", PLANAR,
                    inverse_distance_exact, None, thesis_families),
    ModelDefinition("objective-damper", "derived model with Kelvin-Voigt tether dampers "
                    "(damping of the stretch rate only)", PLANAR,
                    inverse_distance_binomial, 1, objective_families),
)
THREE_D_DEFINITIONS = (
    ModelDefinition("3d", "3-D thesis model (roll, pitch, yaw; balloon in 3-D), binomial "
                    "gravity truncated to the order of Eqs 3.28-3.30, thesis dampers",
                    THREE_D, binomial_power, 1, forces3d.thesis_families),
    ModelDefinition("3d-exact-gravity", "3-D model with exact point-mass gravity and "
                    "MacCullagh box terms (no expansion, no truncation), thesis dampers",
                    THREE_D, exact_power, None, forces3d.thesis_families),
    ModelDefinition("3d-objective-damper", "3-D thesis model with Kelvin-Voigt tether "
                    "dampers (damping of the stretch rate only)", THREE_D, binomial_power, 1,
                    forces3d.objective_families),
)
FREE_DEFINITIONS = (
    ModelDefinition("free", "free orbit (r, nu as coordinates), thesis gravity "
                    "binomial truncated at third degree in the offsets, thesis dampers",
                    FREE, inverse_powers_binomial, None, thesis_families, circular="derived"),
    ModelDefinition("free-exact-gravity", "free orbit (r, nu as coordinates), exact "
                    "point-mass gravity mu/|r_i|, thesis dampers",
                    FREE, inverse_powers_exact, None, thesis_families, circular="exact-gravity"),
    ModelDefinition("free-objective-damper", "free orbit (r, nu as coordinates), "
                    "truncated binomial gravity, Kelvin-Voigt tether dampers",
                    FREE, inverse_powers_binomial, None, objective_families,
                    circular="objective-damper"),
)
FREE_3D_DEFINITIONS = (
    ModelDefinition("3d-free", "3-D model on a free orbit (r, nu as coordinates), thesis "
                    "gravity binomial truncated at third degree in the offsets, J2 at each "
                    "body's latitude, thesis dampers", FREE_3D, taylor_power, TRUNCATION_DEGREE,
                    forces3d.thesis_families, circular="3d"),
    ModelDefinition("3d-free-objective-damper", "3-D model on a free orbit (r, nu as "
                    "coordinates), truncated binomial gravity, J2 at each body's latitude, "
                    "Kelvin-Voigt tether dampers", FREE_3D, taylor_power, TRUNCATION_DEGREE,
                    forces3d.objective_families, circular="3d-objective-damper"),
)
# one registry of every model, in one order: the thesis variants, 3-D, free orbit, 3-D free
DEFINITIONS = PLANAR_DEFINITIONS + THREE_D_DEFINITIONS + FREE_DEFINITIONS + FREE_3D_DEFINITIONS
BY_NAME = {d.name: d for d in DEFINITIONS}
