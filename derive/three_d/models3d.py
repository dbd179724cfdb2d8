"""The 3-D model variants, each a definition fed to derive3d.

3d                  thesis gravity (three binomial terms per inverse power,
                    equations truncated at O(1/r0) as Eqs 3.28-3.30) and the
                    thesis dampers (3.43-3.44).
3d-exact-gravity    point-mass + MacCullagh gravity with exact |r_i|, no
                    truncation; thesis dampers.
3d-objective-damper as 3d with Kelvin-Voigt dampers along the tethers.
"""
from __future__ import annotations

from .energy3d import binomial_power, exact_power
from .forces3d import objective_families, thesis_families
from .pipeline3d import ModelDefinition3D

DEFINITIONS_3D = (
    ModelDefinition3D("3d", "3-D thesis model (roll, pitch, yaw; balloon in 3-D), binomial "
                      "gravity truncated to the order of Eqs 3.28-3.30, thesis dampers",
                      binomial_power, 1, thesis_families),
    ModelDefinition3D("3d-exact-gravity", "3-D model with exact point-mass gravity and "
                      "MacCullagh box terms (no expansion, no truncation), thesis dampers",
                      exact_power, None, thesis_families),
    ModelDefinition3D("3d-objective-damper", "3-D thesis model with Kelvin-Voigt tether "
                      "dampers (damping of the stretch rate only)", binomial_power, 1,
                      objective_families),
)
BY_NAME_3D = {d.name: d for d in DEFINITIONS_3D}
