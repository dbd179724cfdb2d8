"""Bead chains through simulate() and the CLI (docs/beads.md)."""
from __future__ import annotations

import pytest

from tethersim.cli.main import main


@pytest.mark.parametrize("n", ["65", "-1"])
def test_cli_refuses_beads_outside_0_to_64_in_one_line(n, tmp_path, capsys):
    assert main(["run", "satI", "--beads", n, "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"beads = {n}: allowed an integer 0 to 64" in err


# each chain loop compiles for 20-50 s cold: the runs are the slow tier (CI runs it)
@pytest.mark.slow
def test_zero_beads_on_massless_lines_is_the_plain_run_to_1e_12():
    import numpy as np

    import tethersim as ts
    sat = ts.load_preset("satI")
    plain = ts.simulate(sat, 1.0, method="rk4", steps=2000, progress=False)
    chain = ts.simulate(sat, 1.0, method="rk4", steps=2000, progress=False, beads=0)
    assert chain.status == plain.status == "ok"
    a, b = plain.states[:, :6], chain.states[:, :6]
    scale = np.max(np.abs(a), axis=0)
    assert np.max(np.abs(a - b) / scale) <= 1e-12


@pytest.mark.slow
def test_a_bead_run_writes_bead_columns_and_the_tether_shape(tmp_path):
    out = tmp_path / "o"
    assert main(["run", "satI", "--beads", "2", "--set", "mt1=0.01", "--set", "mt2=0.01",
                 "--periods", "0.05", "--out", str(out), "--quiet"]) == 0
    header = (out / "timeseries.csv").read_text().splitlines()[0]
    for col in ("x_1_1", "y_1_2", "x_2_2", "tension_1_1", "tension_2_3"):
        assert col in header, col
    assert (out / "tether_shape.png").is_file()
