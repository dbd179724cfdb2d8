"""Every file a command writes is checked writable before it runs, in one line naming
--out and the file: a sweep.csv that was a folder used to fail after every point ran,
and feasibility/report --out FILE said '[Errno 20] Not a directory: .../store'."""
from __future__ import annotations

import os
import time

import pytest

from tethersim.cli.main import main
from tethersim.cli.preflight import check_file, check_files, check_folder


def _line(capsys) -> str:
    err = capsys.readouterr().err
    assert "Traceback" not in err and "Errno" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[0]


def test_a_folder_where_the_sweep_writes_its_table_is_refused_before_the_runs(tmp_path, capsys):
    out = tmp_path / "o5"
    (out / "sweep.csv").mkdir(parents=True)
    t0 = time.perf_counter()
    assert main(["sweep", "satI", "--E1", "0.001,0.004", "--periods", "0.2",
                 "--out", str(out), "--quiet"]) == 2
    assert time.perf_counter() - t0 < 5.0
    line = _line(capsys)
    assert line.startswith(f"tethersim: error: --out {out}: ") and "sweep.csv is a folder" in line
    assert not (out / "sweep.zarr").exists(), "no point ran"


def test_a_folder_where_run_writes_its_time_series_is_refused_before_the_run(tmp_path, capsys):
    out = tmp_path / "r"
    (out / "timeseries.csv").mkdir(parents=True)
    assert main(["run", "satI", "--periods", "1", "--out", str(out), "--quiet"]) == 2
    assert "timeseries.csv is a folder" in _line(capsys)
    assert not (out / "summary.json").exists()


@pytest.mark.parametrize("argv", [
    ["feasibility", "satI", "--altitude", "200", "--quiet"],
    ["report", "--quiet"],
    ["sweep", "satI", "--E1", "0.003,0.004", "--periods", "0.1", "--quiet"],
    ["run", "satI", "--periods", "1", "--quiet"],
])
def test_out_that_is_a_file_is_named(tmp_path, capsys, argv):
    afile = tmp_path / "passwd"
    afile.write_text("x\n")
    assert main([*argv, "--out", str(afile)]) == 2
    assert _line(capsys) == f"tethersim: error: --out {afile}: is a file, not a folder; give a folder"
    assert afile.read_text() == "x\n"


def test_out_under_a_file_is_named(tmp_path, capsys):
    afile = tmp_path / "f"
    afile.write_text("")
    out = afile / "sub"
    assert main(["compare", "satI", "--periods", "1", "--out", str(out), "--quiet"]) == 2
    assert _line(capsys) == (f"tethersim: error: --out {out}: {afile} is a file, so the folder "
                             f"cannot be created; give another --out")


def test_tune_out_that_is_a_folder_is_refused_before_the_runs(tmp_path, capsys):
    t0 = time.perf_counter()
    assert main(["tune", "satI", "--out", str(tmp_path)]) == 2
    assert time.perf_counter() - t0 < 5.0
    assert _line(capsys) == (f"tethersim: error: --out {tmp_path}: is a folder, not a file; "
                             f"remove it or give another --out")


def test_helpers_accept_what_can_be_written(tmp_path):
    check_folder(tmp_path / "new" / "deeper")  # created later, parents and all
    check_files(tmp_path, ("a.csv", "b.png"))
    check_file(tmp_path / "new" / "t.toml")


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes anywhere")
def test_read_only_folder_is_refused(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        with pytest.raises(ValueError, match=f"--out {ro / 'x'}: {ro} is not writable"):
            check_folder(ro / "x")
    finally:
        ro.chmod(0o700)


def test_a_folder_where_run_draws_a_plot_is_refused_before_the_run(tmp_path, capsys):
    out = tmp_path / "r"
    (out / "theta.png").mkdir(parents=True)
    assert main(["run", "satI", "--periods", "1", "--out", str(out), "--quiet"]) == 2
    assert "theta.png is a folder" in _line(capsys)
    assert not (out / "timeseries.csv").exists()
    # without plots the folder is in nobody's way
    assert main(["run", "satI", "--periods", "1", "--no-plots", "--no-check", "--out", str(out),
                 "--quiet"]) == 0
