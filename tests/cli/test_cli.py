"""Command line: tethersim run | validate | show (tethersim/cli/main.py), called in-process."""
from __future__ import annotations

import contextlib
import io
import json
import math
import subprocess
import sys
from importlib import resources

import numpy as np
import pytest

from tethersim.cli.main import main

SATI_TEXT = (resources.files("tethersim.model.presets") / "satI.toml").read_text()
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def satI_run(tmp_path_factory):
    """One short adaptive run of satI with every output (0.5 orbits)."""
    out = tmp_path_factory.mktemp("run") / "out"
    buf = io.StringIO()  # module scope: no capsys, capture stdout by hand
    with contextlib.redirect_stdout(buf):
        code = main(["run", "satI", "--periods", "0.5", "--out", str(out), "--quiet"])
    return code, out, buf.getvalue()


def test_run_exits_zero_and_writes_every_output(satI_run):
    code, out, stdout = satI_run
    assert code == 0
    for name in ("timeseries.csv", "timeseries.nc", "theta.png", "delta_x.png",
                 "delta_y.png", "overview.png", "summary.json"):
        path = out / name
        assert path.is_file(), name
        assert path.stat().st_size > 0, name
        assert name in stdout  # "wrote ..." lists it


def test_run_pngs_are_png_files(satI_run):
    _, out, _ = satI_run
    for name in ("theta.png", "delta_x.png", "delta_y.png", "overview.png"):
        assert (out / name).read_bytes()[:8] == PNG_MAGIC


def test_run_csv_header_has_si_units_and_data_parse(satI_run):
    _, out, _ = satI_run
    path = out / "timeseries.csv"
    header = path.read_text().splitlines()[0].split(",")
    assert header[:7] == ["t [s]", "delta_x [m]", "delta_y [m]", "theta [rad]",
                          "delta_x_dot [m/s]", "delta_y_dot [m/s]", "theta_dot [rad/s]"]
    assert header[7:] == ["X [m]", "Y [m]", "VX [m/s]", "VY [m/s]"]
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    assert data.shape[1] == 11
    assert data[0, 0] == 0.0
    assert data[0, 3] == pytest.approx(math.pi / 6)  # θ0 = π/6 rad (Table 4.2), not degrees
    assert data[-1, 0] == pytest.approx(0.5 * 5309.64, rel=1e-4)  # period ≈ 5310 s (facts.md)


def test_run_netcdf_opens_with_xarray_and_has_units(satI_run):
    xr = pytest.importorskip("xarray")
    _, out, _ = satI_run
    with xr.open_dataset(out / "timeseries.nc", engine="scipy") as ds:
        ds.load()
        assert ds["t"].attrs["units"] == "s"
        expected = {"delta_x": "m", "delta_y": "m", "theta": "rad", "delta_x_dot": "m/s",
                    "delta_y_dot": "m/s", "theta_dot": "rad/s", "X": "m", "Y": "m",
                    "VX": "m/s", "VY": "m/s"}
        for var, unit in expected.items():
            assert ds[var].attrs["units"] == unit, var
        assert ds.attrs["satellite"] == "SatI"
        csv = np.loadtxt(out / "timeseries.csv", delimiter=",", skiprows=1)
        np.testing.assert_array_equal(ds["t"].values, csv[:, 0])
        np.testing.assert_array_equal(ds["theta"].values, csv[:, 3])


def test_run_summary_json_matches_stdout(satI_run):
    _, out, stdout = satI_run
    summary = json.loads((out / "summary.json").read_text())
    for key in ("mean pitch [rad]", "steady-state pitch [rad]", "settling time [orbits]",
                "tumbled", "upside down", "status", "label"):
        assert key in summary
        assert key in stdout
    assert summary["status"] == "ok"
    assert summary["tumbled"] is False
    assert "SatI" in summary["label"]


def test_run_summary_json_is_strict_json(satI_run):
    _, out, _ = satI_run

    def reject(constant):
        raise ValueError(f"{constant} is not JSON")

    json.loads((out / "summary.json").read_text(), parse_constant=reject)


def test_faithful_run_prints_thesis_step_size(tmp_path, capsys):
    # facts.md: 17.7 s/step for 5 periods in 1500 steps (thesis p. 5-2)
    code = main(["run", "satI", "--faithful", "--periods", "5", "--steps", "1500",
                 "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)])
    captured = capsys.readouterr()
    assert code == 0
    assert "17.70" in captured.out
    assert "1500 steps" in captured.out
    assert "faithful" in captured.out
    assert "RK4StepWarning" not in captured.err  # the thesis step is stable
    assert not (tmp_path / "theta.png").exists()  # --no-plots
    assert (tmp_path / "timeseries.csv").is_file()


def test_faithful_run_with_an_unstable_step_warns_and_reports_divergence(tmp_path, capsys):
    # 5 periods in 50 steps: 531 s per step, far beyond the tether oscillation's RK4 limit
    code = main(["run", "satI", "--faithful", "--periods", "5", "--steps", "50",
                 "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)])
    captured = capsys.readouterr()
    assert code == 1  # the run diverged: status "diverged", exit 1
    warning_lines = [ln for ln in captured.err.splitlines()
                     if ln.startswith("tethersim: warning: RK4StepWarning:")]
    assert len(warning_lines) == 1
    assert "unstable" in warning_lines[0]
    assert "non-finite" in captured.err
    assert "Traceback" not in captured.err
    assert (tmp_path / "timeseries.csv").is_file()  # what finished is still written


def test_console_entry_point_prints_warning_and_error_to_stderr(tmp_path):
    # the real process, python -m tethersim: exit codes and stderr as a user sees them
    proc = subprocess.run(
        [sys.executable, "-m", "tethersim", "run", "satI", "--faithful", "--periods", "5",
         "--steps", "50", "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)],
        capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1
    assert "RK4StepWarning" in proc.stderr
    assert "Traceback" not in proc.stderr
    proc = subprocess.run([sys.executable, "-m", "tethersim", "show", "nosuchsat"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert proc.stderr.startswith("tethersim: error:")
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr


def test_validate_one_satellite_prints_tables_4_4_and_4_5(capsys):
    assert main(["validate", "satI"]) == 0
    out = capsys.readouterr().out
    assert "Table 4.4" in out
    assert "Table 4.5" in out
    assert "SatI" in out
    assert "kg m^2" in out and "rad/s" in out


@pytest.mark.parametrize("name", ["satI", "SATII", "dumbsat"])
def test_show_prints_parameters_with_units(name, capsys):
    assert main(["show", name]) == 0
    out = capsys.readouterr().out
    lines = {line.split()[0]: line for line in out.splitlines()[1:] if line.strip()}
    for key, unit in (("m1", "kg"), ("A3", "m^2"), ("l10", "m"), ("E1", "N"),
                      ("c1", "N s/m"), ("altitude", "m")):
        assert lines[key].rstrip().endswith(unit), lines[key]
    assert "theta [rad]" in out
    assert "rad/s" in out and "kg/m^3" in out
    # facts.md: orbital period ≈ 5310 s at 200 km
    assert "period 5309.64 s" in out


def test_show_accepts_a_user_toml_path(tmp_path, capsys):
    path = tmp_path / "mine.toml"
    path.write_text(SATI_TEXT.replace('name = "SatI"', 'name = "Mine"'))
    assert main(["show", str(path)]) == 0
    assert "Mine" in capsys.readouterr().out


def _bad_toml(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(SATI_TEXT.replace("m1 = 10.0", "m1 = -10.0"))
    return path


@pytest.mark.parametrize("argv, words", [
    (["run", "satIII", "--no-plots"], ["unknown preset", "satIII"]),
    (["show", "nosuchsat"], ["unknown preset"]),
    (["validate", "satI", "nosuchsat"], ["unknown preset"]),
    (["show", "BAD_TOML"], ["m1", "> 0"]),
    (["run", "BAD_TOML", "--no-plots"], ["m1", "> 0"]),
    (["show", "MISSING_TOML"], ["cannot read"]),
    (["run", "satI", "--periods", "0", "--no-plots"], ["periods"]),
    (["run", "satI", "--periods", "nan", "--no-plots"], ["periods"]),
    (["run", "satI", "--method", "rk4", "--steps", "0", "--no-plots"], ["steps"]),
], ids=["run-unknown-preset", "show-unknown-preset", "validate-unknown-preset",
        "show-bad-toml", "run-bad-toml", "show-missing-toml", "run-periods-0",
        "run-periods-nan", "run-steps-0"])
def test_bad_input_exits_2_with_one_line_error(argv, words, tmp_path, capsys):
    argv = [str(_bad_toml(tmp_path)) if a == "BAD_TOML"
            else str(tmp_path / "missing.toml") if a == "MISSING_TOML" else a for a in argv]
    if argv[0] == "run":
        argv += ["--out", str(tmp_path / "out"), "--quiet"]
    code = main(argv)
    captured = capsys.readouterr()
    assert code == 2
    err = captured.err.strip()
    assert err.startswith("tethersim: error:")
    assert "\n" not in err
    assert "Traceback" not in captured.err
    for w in words:
        assert w in err
    assert not (tmp_path / "out" / "timeseries.csv").exists()


def test_unusable_out_folder_exits_2_with_one_line_error(tmp_path, capsys):
    not_a_folder = tmp_path / "file"
    not_a_folder.write_text("")
    code = main(["run", "satI", "--periods", "0.05", "--no-plots", "--no-check", "--quiet",
                 "--out", str(not_a_folder)])
    assert code == 2
    assert capsys.readouterr().err.startswith("tethersim: error:")


@pytest.mark.parametrize("argv", [["--help"], ["run", "--help"], ["validate", "--help"],
                                  ["show", "--help"]])
def test_help_exits_zero(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 0
    assert "usage: tethersim" in capsys.readouterr().out


def test_no_command_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as exc:
        main([])
    assert exc.value.code == 2
    assert "usage" in capsys.readouterr().err
