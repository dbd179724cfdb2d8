"""tethersim/experiments/real_tethers.py: the real-line satellite, its stretched lengths and
its density-step run."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.experiments.real_tethers import (
    LINE,
    REAL_MODEL,
    STRETCHED_LENGTHS,
    density_step,
    real_lines,
    stretched_lengths,
    trim,
)
from tethersim.model.materials import MATERIALS
from tethersim.model.presets import load_preset


@pytest.fixture(scope="module")
def satI():
    return load_preset("satI")


def test_stretched_lengths_are_the_thesis_equilibriums_line_lengths_to_5_mm(satI):
    got = stretched_lengths(satI)
    assert np.allclose(got, STRETCHED_LENGTHS, rtol=0, atol=5e-3), got


def test_real_lines_are_the_materials_ea_and_strength_at_the_given_lengths(satI):
    name, d = LINE
    m = MATERIALS[name]
    area = math.pi * d ** 2 / 4
    s = real_lines(satI, (10.0, 12.0))
    assert (s.l10, s.l20) == (10.0, 12.0)
    assert s.E1 == pytest.approx(m.E * area, rel=1e-12)
    assert s.Fb1 == pytest.approx(m.strength * area, rel=1e-12)
    # the loss factor's damping c = η √(k μ) at the line's own stiffness k = EA / l0
    assert s.c2 / s.c1 == pytest.approx(math.sqrt(10.0 / 12.0), rel=1e-12)
    assert (real_lines(satI).l10, real_lines(satI).l20) == (satI.l10, satI.l20)


def test_a_stiff_lines_trim_hardly_moves_with_the_air_where_the_thesis_tethers_leave_the_band(satI):
    thesis, real = trim(satI), trim(real_lines(satI, STRETCHED_LENGTHS))
    spread = lambda t: max(abs(v - t["theta"]) for v in t["theta_at"].values())  # noqa: E731
    assert spread(thesis) > 0.05 > 100 * spread(real)
    # the balloon stays where the thesis's tethers held it: δx within the lines' strain
    assert real["delta_x"] == pytest.approx(thesis["delta_x"], abs=0.01)


@pytest.mark.slow  # the implicit loop of objective-damper: ~15 s to compile cold
def test_a_density_step_run_at_nominal_air_stays_at_its_equilibrium(satI):
    sat = real_lines(satI, STRETCHED_LENGTHS)
    res = density_step(sat, 1.0, 1.0)
    assert res.status == "ok" and res.method == "implicit" and res.model == REAL_MODEL
    eq = trim(sat)
    assert res.theta[0] == pytest.approx(eq["theta"], abs=1e-12)
    assert np.max(np.abs(res.theta - eq["theta"])) < 1e-6
