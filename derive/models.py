"""The model variants: each a definition fed to the one pipeline.

derived          the default: thesis model (3.10-3.47) derived cleanly, the
                 Lagrange equations truncated to the printed order (3.28-3.30).
printed          Eqs 3.48-3.50 exactly as printed, errata included.
exact-gravity    as derived, without the binomial expansion (V = −μ m/|r|).
objective-damper as derived, with Kelvin-Voigt tether dampers acting along the
                 tether on its stretch rate instead of Eqs 3.43-3.44.
"""
from __future__ import annotations

from . import printed
from .energy import inverse_distance_binomial, inverse_distance_exact
from .forces import (
    ForceFamily,
    damper_families,
    drag_families,
    objective_damper_families,
    spring_families,
    spring_potential,
)
from .kinematics import planar_kinematics
from .pipeline import ModelDefinition

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


DEFINITIONS = (
    ModelDefinition("derived", "clean derivation of the thesis model, truncated to the "
                    "order of Eqs 3.28-3.30", planar_kinematics, inverse_distance_binomial,
                    1, thesis_families),
    ModelDefinition("printed", "Eqs 3.48-3.50 exactly as printed in the thesis, errata "
                    "included", planar_kinematics, inverse_distance_binomial, None,
                    printed_families, lhs_override=printed.LHS),
    ModelDefinition("exact-gravity", "derived model with exact point-mass gravity "
                    "mu/|r| (no binomial expansion, no truncation)", planar_kinematics,
                    inverse_distance_exact, None, thesis_families),
    ModelDefinition("objective-damper", "derived model with Kelvin-Voigt tether dampers "
                    "(damping of the stretch rate only)", planar_kinematics,
                    inverse_distance_binomial, 1, objective_families),
)
BY_NAME = {d.name: d for d in DEFINITIONS}
