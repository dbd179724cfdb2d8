"""tethersim/cli/run.py: outputs, units, the printed step, default folder per satellite."""
from __future__ import annotations

import json
import math
from importlib import resources

import numpy as np
import pytest

from .conftest import QUICK, call

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
SATI_TEXT = (resources.files("tethersim.model.presets") / "satI.toml").read_text()
FAST = ["--faithful", *QUICK, "--no-plots", "--no-check"]


@pytest.fixture(scope="module")
def satI_run(tmp_path_factory):
    """One short adaptive run of satI with every output (0.5 orbits)."""
    out = tmp_path_factory.mktemp("run") / "out"
    code, stdout, _ = call(["run", "satI", "--periods", "0.5", "--out", str(out), "--quiet"])
    return code, out, stdout


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
    assert header[7:11] == ["X [m]", "Y [m]", "VX [m/s]", "VY [m/s]"]
    assert header[11:] == ["tension_1 [N]", "tension_2 [N]"]  # issue 21: the tethers' loads
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    assert data.shape[1] == 13
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


def test_run_summary_json_matches_stdout_and_records_the_satellite(satI_run):
    _, out, stdout = satI_run
    summary = json.loads((out / "summary.json").read_text())
    for key in ("mean pitch [rad]", "steady-state pitch [rad]", "settling time [orbits]",
                "tumbled", "upside down", "status", "label"):
        assert key in summary
        assert key in stdout
    assert summary["status"] == "ok"
    assert summary["tumbled"] is False
    assert "SatI" in summary["label"]
    assert (summary["satellite"], summary["from"], summary["overrides"]) == ("SatI", "satI", [])
    assert summary["integrator"] == "DOP853 adaptive, rtol 1e-10, switches located"
    assert summary["integrator"] in stdout


def test_run_summary_json_is_strict_json(satI_run):
    _, out, _ = satI_run

    def reject(constant):
        raise ValueError(f"{constant} is not JSON")

    json.loads((out / "summary.json").read_text(), parse_constant=reject)


def test_faithful_run_with_thesis_ch4_steps_prints_that_step(tmp_path, cli):
    # facts.md: 17.7 s/step for 5 periods in 1500 steps (thesis p. 5-2)
    code, out, err = cli(["run", "satI", "--faithful", "--periods", "5", "--steps", "1500",
                          "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)])
    assert code == 0
    assert "RK4 step 17.70 s (300 per orbit; 1500 steps), switches not located" in out
    assert "faithful" in out
    assert "RK4StepWarning" not in err  # the thesis step is stable
    assert not (tmp_path / "theta.png").exists()  # --no-plots
    assert (tmp_path / "timeseries.csv").is_file()


def test_faithful_run_without_steps_uses_200_per_orbit(tmp_path, cli):
    code, out, _ = cli(["run", "satI", *FAST, "--out", str(tmp_path)])
    assert code == 0
    assert "RK4 step 26.55 s (200 per orbit, thesis ch. 5; 10 steps)" in out
    assert len(np.loadtxt(tmp_path / "timeseries.csv", delimiter=",", skiprows=1)) == 11


def test_faithful_run_with_an_unstable_step_warns_and_reports_divergence(tmp_path, cli):
    # 5 periods in 50 steps: 531 s per step, far beyond the tether oscillation's RK4 limit
    code, _out, err = cli(["run", "satI", "--faithful", "--periods", "5", "--steps", "50",
                          "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)])
    assert code == 1  # the run diverged: status "diverged", exit 1
    warning_lines = [ln for ln in err.splitlines()
                     if ln.startswith("tethersim: warning: RK4StepWarning:")]
    assert len(warning_lines) == 1
    assert "unstable" in warning_lines[0]
    error_lines = [ln for ln in err.splitlines() if ln.startswith("tethersim: error:")]
    # the run blows up: it leaves the model's domain before its state turns non-finite
    assert len(error_lines) == 1 and ("non-finite" in error_lines[0]
                                      or "left the model's domain" in error_lines[0])
    assert "Traceback" not in err
    assert (tmp_path / "timeseries.csv").is_file()  # what finished is still written


def test_run_without_out_writes_results_per_satellite(in_tmp, cli):
    for name in ("satI", "SATII"):
        code, _out, err = cli(["run", name, *FAST])
        assert code == 0, err
    a = json.loads((in_tmp / "results" / "satI" / "summary.json").read_text())
    b = json.loads((in_tmp / "results" / "satII" / "summary.json").read_text())
    assert (a["satellite"], b["satellite"]) == ("SatI", "SatII")  # neither replaced the other
    assert not (in_tmp / "results" / "summary.json").exists()


def test_run_of_a_toml_without_out_uses_its_file_name(in_tmp, cli):
    path = in_tmp / "my sat.toml"
    path.write_text(SATI_TEXT.replace('name = "SatI"', 'name = "Mine"'))
    code, _, err = cli(["run", str(path), *FAST])
    assert code == 0, err
    assert json.loads((in_tmp / "results" / "my_sat" / "summary.json").read_text())[
        "satellite"] == "Mine"


def test_run_refuses_to_replace_another_satellites_results(in_tmp, cli):
    assert cli(["run", "satI", *FAST])[0] == 0
    before = (in_tmp / "results" / "satI" / "timeseries.csv").read_bytes()
    target = in_tmp / "results" / "satI"
    code, _out, err = cli(["run", "satII", *FAST, "--out", str(target)])
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("tethersim: error:")
    assert "SatI (satI)" in err and "SatII (satII)" in err and "--force" in err
    assert (target / "timeseries.csv").read_bytes() == before  # untouched


def test_run_refuses_other_overrides_in_the_same_folder_and_force_replaces(in_tmp, cli):
    assert cli(["run", "satI", *FAST])[0] == 0
    code, _, err = cli(["run", "satI", *FAST, "--set", "E1=0.005"])
    assert code == 2 and "--set E1=0.005" in err
    code, _, err = cli(["run", "satI", *FAST, "--set", "E1=0.005", "--force"])
    assert code == 0, err
    summary = json.loads((in_tmp / "results" / "satI" / "summary.json").read_text())
    assert summary["overrides"] == ["--set E1=0.005"]


def test_unusable_out_folder_exits_2_with_one_line_error(tmp_path, cli):
    not_a_folder = tmp_path / "file"
    not_a_folder.write_text("")
    code, _, err = cli(["run", "satI", *FAST, "--out", str(not_a_folder)])
    assert code == 2
    assert err.startswith("tethersim: error: --out") and err.count("\n") == 1


def test_run_interrupted_writes_what_finished_and_exits_130_with_one_line(tmp_path, cli,
                                                                          monkeypatch):
    import dataclasses

    from tethersim.engine import simulate as engine

    real = engine.simulate

    def interrupted(*args, **kwargs):  # what simulate returns after Ctrl-C: the run so far
        return dataclasses.replace(real(*args, **kwargs), status="interrupted")

    monkeypatch.setattr(engine, "simulate", interrupted)
    code, _, err = cli(["run", "satI", *FAST, "--out", str(tmp_path)])
    assert code == 130
    assert err.startswith("tethersim: interrupted: the output holds the run up to t = ")
    assert err.count("\n") == 1
    assert json.loads((tmp_path / "summary.json").read_text())["status"] == "interrupted"
