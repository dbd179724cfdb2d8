"""``forces`` with a free-orbit (or 3-D) model: every coordinate's table, not a shape error;
``in_plane_forces`` picks the thesis's three by name."""
from __future__ import annotations

import csv

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.force_peaks import COORDINATES, in_plane_forces
from tethersim.model.registry import get_model

from .conftest import call

pytestmark = pytest.mark.slow  # compiles the planar free-orbit kernels


def test_in_plane_forces_are_the_dx_dy_theta_columns_by_name():
    res = ts.simulate(ts.load_preset("satI").replace(orbit="free"), periods=0.05, progress=False)
    names = res.layout.state
    assert len(names) // 2 > 3  # r and nu too
    for k, (c, _, _) in enumerate(COORDINATES):
        np.testing.assert_array_equal(in_plane_forces(res)[:, :, k],
                                      res.forces[:, :, names.index(c)])


def test_forces_of_a_free_model_writes_a_row_and_a_figure_per_coordinate(tmp_path):
    code, _, err = call(["forces", "satI", "--model", "free", "--periods", "0.05", "--quiet",
                         "--out", str(tmp_path / "f")])
    assert code == 0, err
    with open(tmp_path / "f" / "forces.csv") as fh:
        rows = list(csv.DictReader(fh))
    # every coordinate of the model: the in-plane three, then the orbit's r and nu
    model = get_model("free")
    names = [r["coordinate"] for r in rows]
    assert names == ["delta_x", "delta_y", "theta", "r", "nu"]
    assert [r["unit"] for r in rows] == ["N", "N", "N m", "N", "N m"]
    for name in names:
        assert (tmp_path / "f" / f"forces_{name}.png").is_file()
    assert names == list(model.state[:model.n_coordinates])
