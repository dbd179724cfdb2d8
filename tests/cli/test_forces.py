"""tethersim/cli/forces.py: the force breakdown's files, table and folders."""
from __future__ import annotations

import csv
import json

import pytest

import tethersim as ts
from tethersim.analysis.force_peaks import COORDINATES
from tethersim.generated import layout as L

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_forces_writes_three_pngs_and_csv(tmp_path, cli):
    out = tmp_path / "f"
    code, stdout, _ = cli(["forces", "satI", "--periods", "1", "--out", str(out), "--quiet"])
    assert code == 0
    for name in ("forces_delta_x.png", "forces_delta_y.png", "forces_theta.png"):
        assert (out / name).read_bytes()[:8] == PNG_MAGIC, name
        assert name in stdout
    with (out / "forces.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert [r["coordinate"] for r in rows] == [c[0] for c in COORDINATES]
    assert [r["unit"] for r in rows] == ["N", "N", "N m"]
    x = rows[0]
    assert x["family"] in L.FAMILIES and x["runner_up"] in L.FAMILIES
    assert 0.1 < float(x["max_abs_Q"]) < 0.3  # the balloon's drag, ~0.18 N (docs/metrics.md)
    assert 0.0 <= float(x["time [orbits]"]) <= 1.0
    assert float(x["time [s]"]) == pytest.approx(
        float(x["time [orbits]"]) * ts.load_preset("satI").period)
    assert "δx [N]" in stdout and "θ [N m]" in stdout and "runner-up" in stdout
    assert "DOP853 adaptive, rtol 1e-10, switches located" in stdout


def test_forces_faithful_default_out_is_the_satellites_folder(in_tmp, cli):
    code, stdout, _ = cli(["forces", "SATI", "--periods", "1", "--faithful", "--quiet",
                           "--scale", "c1=10", "--scale", "c2=10"])
    assert code == 0
    assert "fixed step 26.55 s (faithful to the thesis)" in stdout  # 200 steps per orbit
    assert "RK4 step 26.55 s (200 per orbit, thesis ch. 5; 200 steps)" in stdout
    out = in_tmp / "results" / "satI" / "forces"  # one folder per satellite
    assert (out / "forces.csv").is_file() and (out / "forces_theta.png").is_file()
    record = json.loads((out / "satellite.json").read_text())
    assert record["overrides"] == ["--scale c1=10", "--scale c2=10"]


def test_forces_bad_set_name_exits_2_and_names_it(tmp_path, cli):
    out = tmp_path / "never"
    code, _stdout, stderr = cli(["forces", "satI", "--periods", "1", "--set", "E9=0.1",
                                "--out", str(out), "--quiet"])
    assert code == 2
    assert "E9" in stderr and "error" in stderr
    assert not out.exists()  # checked before the run and before any output
