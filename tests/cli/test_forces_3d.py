"""``tethersim forces`` for every model's coordinates (issue 19: ``--model 3d`` failed with
"Q has shape (1001, 7, 6): expected (samples, 7, 3)").

Truths: the model registry's coordinate list (names, SI units), and physics — a 3-D run
started in the orbit plane with point-mass end bodies stays there, so its forces on δz, φ,
ψ are zero and those on δx, δy, θ are the planar model's; tilted out of plane, the
out-of-plane forces are not.
"""
from __future__ import annotations

import csv

import numpy as np
import pytest

from tests.cli.conftest import call
from tethersim.analysis.force_peaks import coordinates, largest_forces_from
from tethersim.generated import layout as L
from tethersim.model.registry import NAMES, get_model

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("name", NAMES)
def test_every_models_coordinates_name_its_state_with_a_force_or_torque_unit(name):
    model = get_model(name)
    coords = coordinates(model)
    assert [c[0] for c in coords] == list(model.state[:model.n_coordinates])
    for (coord, _, unit), si in zip(coords, model.state_units):
        assert unit == {"m": "N", "rad": "N m"}[si], coord


def test_largest_forces_of_a_six_coordinate_q_name_each_coordinate():
    coords = coordinates(get_model("3d"))
    t = np.linspace(0.0, 10.0, 6)
    Q = np.zeros((6, len(L.FAMILIES), 6))
    for k in range(6):  # coordinate k's largest force: k + 1, at sample k, by family k % 7
        Q[k, k % 7, k] = -(k + 1.0)
    rows = largest_forces_from(t, Q, 5.0, coords)
    assert [r.coordinate for r in rows] == ["delta_x", "delta_y", "delta_z", "phi", "theta",
                                            "psi"]
    for k, r in enumerate(rows):
        assert (r.family, r.peak, r.time) == (L.FAMILIES[k % 7], k + 1.0, t[k])
    with pytest.raises(ValueError, match="coordinates"):
        largest_forces_from(t, Q, 5.0)  # the planar names for a 3-D Q


def _table(out) -> dict:
    with (out / "forces.csv").open() as fh:
        return {r["coordinate"]: r for r in csv.DictReader(fh)}


@pytest.mark.slow
def test_forces_of_an_in_plane_3d_run_are_the_planar_ones_and_zero_out_of_plane(tmp_path):
    # one fixed-step scheme for both: the same samples, so the peaks compare sample by sample
    run = ["forces", "satI", "--periods", "0.2", "--quiet", "--method", "rk4"]
    # point-mass end bodies: the planar models have no end-body moments of inertia
    code, stdout, err = call(run + ["--model", "3d", "--set", "inertia=points",
                                    "--out", str(tmp_path / "3d")])
    assert code == 0, err
    assert call(run + ["--out", str(tmp_path / "planar")])[0] == 0
    three, planar = _table(tmp_path / "3d"), _table(tmp_path / "planar")
    assert list(three) == ["delta_x", "delta_y", "delta_z", "phi", "theta", "psi"]
    for name in ("delta_z", "phi", "psi"):
        assert float(three[name]["max_abs_Q"]) == 0.0 and three[name]["family"] == ""
    for name in ("delta_x", "delta_y", "theta"):
        assert three[name]["family"] == planar[name]["family"]
        assert float(three[name]["max_abs_Q"]) == pytest.approx(
            float(planar[name]["max_abs_Q"]), rel=1e-6)
    for name in three:
        png = tmp_path / "3d" / f"forces_{name}.png"
        assert png.read_bytes()[:8] == PNG_MAGIC and str(png) in stdout
    assert "φ [N m]" in stdout and "δz [N]" in stdout


@pytest.mark.slow
def test_forces_of_a_tilted_3d_run_act_out_of_plane(tmp_path):
    code, _, err = call(["forces", "satI", "--periods", "0.2", "--quiet", "--model", "3d",
                         "--set", "phi0_deg=5", "--out", str(tmp_path)])
    assert code == 0, err
    table = _table(tmp_path)
    assert float(table["phi"]["max_abs_Q"]) > 0 and table["phi"]["family"] in L.FAMILIES
