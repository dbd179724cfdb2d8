"""CLASS_RTOL gives the converged classes: on reference grids of the three presets (the
thesis's moduli and damping maps, coarse), every class at CLASS_RTOL equals the class at
the sweep's converged DEFAULT_RTOL, and the pitch it trims to moves far less than the
settling band."""
from __future__ import annotations

import numpy as np
import pytest

from tethersim import load_preset
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.experiments.sweep import SweepSpec
from tethersim.experiments.sweep.convergence import class_convergence
from tethersim.experiments.sweep.plan import CLASS_RTOL, DEFAULT_RTOL

GRIDS = {
    "satI moduli": ("satI", (("E1", np.linspace(0.0005, 0.02, 5)),
                             ("E2", np.linspace(0.005, 0.06, 5)))),
    "satI damping": ("satI", (("c1", np.linspace(0.0, 0.012, 4)),
                              ("c2", np.linspace(0.0, 0.012, 4)))),
    "satII moduli": ("satII", (("E2", np.linspace(0.03, 0.06, 7)),)),
    "dumbsat moduli": ("dumbsat", (("E1", np.linspace(0.0005, 0.06, 4)),
                                   ("E2", np.linspace(0.005, 0.06, 4)))),
}


@pytest.mark.parametrize("name", GRIDS)
def test_no_class_changes_at_the_class_tolerance(name):
    preset, axes = GRIDS[name]
    spec = SweepSpec(load_preset(preset), axes, periods=50.0, progress=False)
    ref, loose = class_convergence(spec, (DEFAULT_RTOL, CLASS_RTOL), workers=2)
    assert ref["rtol"] == DEFAULT_RTOL and ref["class_changes"] == 0
    assert loose["class_changes"] == 0
    assert loose["max_dtheta_ss"] < 1e-3 * SETTLING_TOL
    assert loose["work"] < 1.0  # and it is cheaper
