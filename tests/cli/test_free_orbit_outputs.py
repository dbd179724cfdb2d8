"""Free orbits at the command line: one orbit per run, its air, altitude and orbit elements
in the files, altitude.png, ``run --until reentry`` (issue 19)."""
from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from tethersim.model import atmosphere
from tethersim.model.constants import MU_EARTH, R_EARTH

from .conftest import call

QUICK = ["--periods", "0.05", "--quiet", "--no-plots", "--no-check"]


@pytest.mark.parametrize("argv, expected", [
    (["run", "satI", "--model", "free", "--set", "orbit=circular"],
     "--model free with --set orbit=circular: a free-orbit model runs a free orbit"),
    (["run", "satI", "--model", "3d-free", "--set", "orbit=circular"],
     "--model 3d-free with --set orbit=circular"),
    (["compare", "satI", "--models", "free", "--set", "orbit=circular"],
     "--models free with --set orbit=circular"),
    (["run", "satI", "--until", "reentry"], "--until reentry: needs a free orbit"),
    (["equilibrium", "satI", "--set", "orbit=free"],
     "orbit = 'free': the equilibrium is that of the orbit held circular"),
    (["feasibility", "satI", "--model", "free", "--altitude", "200"],
     "--model free: feasibility takes a circular-orbit model"),
    (["run", "satI", "--set", "orbit=free", "--set", "eccentricity=0.0999"],
     "eccentricity = 0.0999: the apogee at 1660.2 km leaves the air model"),
    (["run", "satI", "--model", "free", "--set", "reentry_altitude=250"],
     "--model free (orbit = 'free'):"),
])
def test_contradictory_orbit_options_are_refused_in_one_line(argv, expected, tmp_path):
    code, out, err = call([*argv, "--out", str(tmp_path / "o"), *QUICK[:3]]
                          if argv[0] in ("run", "compare") else argv)
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith("tethersim: error: ") and expected in err
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("kind, names", [("model", "free"), ("model", "3d-free"),
                                          ("models", ["derived,free-exact-gravity"])])
def test_a_free_model_makes_the_satellite_free_before_the_run(kind, names):
    from argparse import Namespace

    from tethersim.cli.options import satellite  # resolves the orbit (tethersim.cli.orbit)
    args = Namespace(satellite="satI", set=[], scale=[], allow_implausible=False,
                     **{kind: names})
    sat = satellite(args)
    assert (sat.orbit, sat.density_mode) == ("free", "per-body")
    setattr(args, kind, "derived" if kind == "model" else ["derived,exact-gravity"])
    assert satellite(args).orbit == "circular"


# --- runs of the planar free model (a ~20 s compile): the slow tier ------------------------
@pytest.fixture(scope="module")
def free_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("free") / "out"
    code, stdout, err = call(["run", "satI", "--model", "free", "--periods", "3", "--quiet",
                              "--no-check", "--out", str(out)])
    return code, out, stdout, err


def _columns(path):
    with open(path) as fh:
        rows = list(csv.reader(fh))
    head = rows[0]
    data = np.array([[float(c) if c else np.nan for c in r] for r in rows[1:]])
    return {h: data[:, i] for i, h in enumerate(head)}


@pytest.mark.slow
def test_a_free_satI_run_with_default_air_does_not_end_ok_within_three_orbits(free_run):
    code, out, _, err = free_run
    summary = json.loads((out / "summary.json").read_text())
    assert summary["orbit"] == "free (model free)"
    assert summary["air density"].startswith("Vallado Table 8-4 at each body's own altitude")
    assert summary["status"] in ("re-entered", "left-domain")
    assert code == 1 and summary["run ended by"].split(":")[0] in ("re-entered",
                                                                   "left the model's domain")


@pytest.mark.slow
def test_the_altitude_column_is_the_radius_minus_earths(free_run):
    c = _columns(free_run[1] / "timeseries.csv")
    np.testing.assert_array_equal(c["altitude [m]"], c["r [m]"] - R_EARTH)
    assert c["altitude [m]"][-1] < c["altitude [m]"][0] - 10e3  # it decayed


@pytest.mark.slow
def test_the_orbit_elements_match_vis_viva_and_angular_momentum_from_the_state(free_run):
    c = _columns(free_run[1] / "timeseries.csv")
    r, rd, nud = c["r [m]"], c["r_dot [m/s]"], c["nu_dot [rad/s]"]
    a = 1 / (2 / r - (rd ** 2 + (r * nud) ** 2) / MU_EARTH)
    np.testing.assert_allclose(c["semi_major_axis [m]"], a, rtol=1e-12)
    p = (r * r * nud) ** 2 / MU_EARTH  # semi-latus rectum h^2 / mu = a (1 - e^2)
    np.testing.assert_allclose(c["eccentricity [1]"] ** 2, 1 - p / a, atol=1e-12)


@pytest.mark.slow
def test_the_density_columns_are_the_table_at_each_body(free_run):
    c = _columns(free_run[1] / "timeseries.csv")
    r, x, y = c["r [m]"][0], c["delta_x [m]"][0], c["delta_y [m]"][0]
    h_balloon = np.hypot(x, r + y) - R_EARTH  # local frame: the balloon at (x, r + y)
    assert c["rho_balloon [kg/m^3]"][0] == pytest.approx(atmosphere.density(h_balloon), rel=1e-9)
    assert np.all(c["rho_balloon [kg/m^3]"][-1] > c["rho_balloon [kg/m^3]"][0])  # lower: denser


@pytest.mark.slow
def test_the_netcdf_carries_the_same_columns_with_units(free_run):
    import xarray as xr
    ds = xr.open_dataset(free_run[1] / "timeseries.nc", engine="scipy")
    c = _columns(free_run[1] / "timeseries.csv")
    for name, unit in (("altitude", "m"), ("semi_major_axis", "m"), ("eccentricity", "1"),
                       ("rho_balloon", "kg/m^3"), ("rho_bus", "kg/m^3"),
                       ("rho_tip_mass", "kg/m^3")):
        assert ds[name].attrs["units"] == unit
        np.testing.assert_array_equal(ds[name].values, c[f"{name} [{unit}]"])
    ds.close()


@pytest.mark.slow
def test_run_writes_the_altitude_plot_of_a_free_orbit(free_run):
    assert (free_run[1] / "altitude.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.slow
def test_until_reentry_runs_to_the_reentry_and_says_so(tmp_path):
    out = tmp_path / "r"
    code, stdout, err = call(["run", "satI", "--model", "free", "--until", "reentry",
                              "--set", "reentry_altitude=170", "--quiet", "--no-plots",
                              "--out", str(out)])
    assert code == 0, err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "re-entered" and summary["until"].startswith("at most 240 h")
    assert summary["run ended by"].startswith("re-entered: the boom's COM fell below 170 km")
    assert summary["run ended at [h]"] == pytest.approx(summary["re-entry time [h]"], abs=0.01)
    assert "until re-entry, at most 240 h" in stdout


@pytest.mark.slow
def test_uniform_air_asked_for_on_a_free_orbit_is_told_once(tmp_path):
    code, stdout, err = call(["run", "satI", "--model", "free", "--set", "density=uniform",
                              *QUICK, "--out", str(tmp_path / "u")])
    assert code == 0, err
    assert (stdout + err).count("constant air at the start altitude") == 1
