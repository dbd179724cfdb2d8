"""Run plots: a 3-D model adds roll, yaw and δz; planar output keeps its four files."""
from __future__ import annotations

import math

import pytest

import tethersim
from tethersim.output.plots.run import plot_result

# compiles the 3-D kernels (jacobian ~15 s cold): the slow tier (make test-slow, CI)
pytestmark = pytest.mark.slow


def test_3d_run_writes_roll_yaw_and_delta_z_plots(tmp_path):
    sat = tethersim.load_preset("satI").replace(initial_3d={"phi": math.radians(5)})
    res = tethersim.simulate(sat, periods=0.2, model="3d", progress=False)
    names = [p.name for p in plot_result(res, tmp_path)]
    assert names == ["theta.png", "delta_x.png", "delta_y.png", "roll.png", "yaw.png",
                     "delta_z.png", "overview.png", "tensions.png"]
    assert all((tmp_path / n).stat().st_size > 10_000 for n in names)


def test_planar_run_writes_only_the_planar_plots(tmp_path):
    res = tethersim.simulate(tethersim.load_preset("satI"), periods=0.2, progress=False)
    assert [p.name for p in plot_result(res, tmp_path)] == [
        "theta.png", "delta_x.png", "delta_y.png", "overview.png", "tensions.png"]
