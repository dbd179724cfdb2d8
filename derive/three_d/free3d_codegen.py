"""Print the 3-D free-orbit models with the free-orbit printer (derive/orbit_codegen.py).

The kernels, their signatures and the LDLᵀ solve are the planar free models'
(16 states, 8×8 mass matrix); what differs is the layout below: the 3-D
state and parameter vectors, the 3-D code names (sin/cos of φ, θ, ψ), and the
zero-axial-inertia rule of the 3-D models (I1_yaw + I2_yaw = 0: ψ̈ = 0).
"""
from __future__ import annotations

from ..orbit_codegen import FreeLayout, geometry_lines, module_source
from ..printer import module_filename
from .codegen3d import ZERO_AXIAL, block, prepare
from .free3d import (
    FREE3D_ACCELERATION_SYMBOLS,
    FREE3D_DEFINITIONS,
    FREE3D_PARAMETERS,
    FREE3D_Q_SYMBOLS,
    FREE3D_STATE_NAMES,
    FREE3D_STATE_SYMBOLS,
    FREE3D_STATE_UNITS,
    derive_free3d,
    free3d_kinematics,
    free3d_substitution,
    length_definitions,
)

PSI = FREE3D_STATE_NAMES.index("psi")

FREE3D = FreeLayout(
    FREE3D_STATE_NAMES, FREE3D_STATE_UNITS, FREE3D_STATE_SYMBOLS, FREE3D_ACCELERATION_SYMBOLS,
    FREE3D_Q_SYMBOLS, FREE3D_PARAMETERS, block, prepare, ("phi", "theta", "psi"),
    'GEOMETRY = "3d"  # roll, pitch, yaw and an out-of-plane balloon',
    ("Produced by `make derive` (python -m derive) from derive/three_d/free3d.py and",
     "derive/orbit_codegen.py; regenerate instead of editing.  docs/three-d.md, docs/orbit.md."),
    axial=(PSI, ZERO_AXIAL), force_units="N, N, N, N m, N m, N m, N, N m")


def write_free3d_models(out, definitions=FREE3D_DEFINITIONS) -> list:
    """Derive each 3-D free-orbit model and write its module into ``out``; the file names."""
    kin = free3d_kinematics()
    geometry = geometry_lines(kin, free3d_substitution(), FREE3D, (kin.L.x, kin.L.y, kin.L.z),
                              " (docs/three-d.md, about the orbit radius r)")
    written = []
    for defn in definitions:
        fname = module_filename(defn.name)
        (out / fname).write_text(module_source(derive_free3d(defn), length_definitions(),
                                               geometry, FREE3D))
        written.append(fname)
    return written
