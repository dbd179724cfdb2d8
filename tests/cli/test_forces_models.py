"""``forces`` with a free-orbit (or 3-D) model: the in-plane table, not a shape error."""
from __future__ import annotations

import csv

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.force_peaks import COORDINATES, in_plane_forces

from .conftest import call

pytestmark = pytest.mark.slow  # compiles the planar free-orbit kernels


def test_in_plane_forces_are_the_dx_dy_theta_columns_by_name():
    res = ts.simulate(ts.load_preset("satI").replace(orbit="free"), periods=0.05, progress=False)
    names = res.layout.state
    assert len(names) // 2 > 3  # r and nu too
    for k, (c, _, _) in enumerate(COORDINATES):
        np.testing.assert_array_equal(in_plane_forces(res)[:, :, k],
                                      res.forces[:, :, names.index(c)])


def test_forces_of_a_free_model_writes_the_three_coordinate_table(tmp_path):
    code, _, err = call(["forces", "satI", "--model", "free", "--periods", "0.05", "--quiet",
                         "--out", str(tmp_path / "f")])
    assert code == 0, err
    with open(tmp_path / "f" / "forces.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["coordinate"] for r in rows] == [c for c, _, _ in COORDINATES]
