"""tethersim/cli/sweep.py: store, table and map; bad grids refused naming the field."""
from __future__ import annotations

import pytest


def test_sweep_writes_store_csv_and_map(tmp_path, cli):
    out = tmp_path / "cli"
    rc, text, err = cli(["sweep", "satI", "--E1", "0.0038,0.0042", "--E2", "0.042:0.043:2",
                         "--periods", "1", "--out", str(out), "--quiet"])
    assert rc == 0, err
    for name in ("sweep.zarr", "sweep.csv", "stability_map.png", "satellite.json"):
        assert (out / name).exists()
    assert "4 runs of 1 orbits" in text and "stable" in text
    assert "DOP853 adaptive, rtol 1e-09" in text


def test_sweep_default_out_is_under_the_satellites_folder(in_tmp, cli):
    rc, _text, err = cli(["sweep", "satII", "--c1", "0.0003", "--periods", "0.05", "--faithful",
                         "--quiet"])
    assert rc == 0, err
    assert (in_tmp / "results" / "satII" / "sweep-c1-faithful" / "sweep.csv").is_file()


@pytest.mark.parametrize("argv, message", [
    (["--periods", "1"], "one or two grids"),
    (["--E1", "0:1:2", "--E2", "0:1:2", "--c1", "0:1:2"], "one or two grids"),
    (["--E1", "0:0.01"], "start:stop:count"),
    (["--E1", "0.004", "--workers", "0"], "--workers: must be an integer >= 1, got 0"),
    (["--E1", "0.004", "--workers", "2", "--dask-workers", "2"], "alternatives"),
    (["--l10=-1,6"], "l10 = -1"),
])
def test_sweep_bad_input_exits_2_naming_the_field(argv, message, tmp_path, cli):
    rc, _, err = cli(["sweep", "satI", *argv, "--out", str(tmp_path / "x"), "--quiet"])
    assert rc == 2
    assert message in err and err.count("\n") == 1
    assert not (tmp_path / "x").exists()
