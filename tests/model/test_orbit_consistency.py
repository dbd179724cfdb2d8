"""One orbit per run: free-orbit models against circular satellites, the air a free orbit
gets by default, eccentric orbits whose apogee leaves the air model (issue 19)."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.experiments.compare import compare
from tethersim.model import atmosphere
from tethersim.model.constants import R_EARTH
from tethersim.model.options import CONSTANT_AIR_NOTE, apogee_altitude, body_reach, density_text
from tethersim.model.presets import from_dict, load
from tethersim.model.presets.write import dumps
from tethersim.model.registry import FREE_VARIANTS, MODELS, model_for_orbit
from tethersim.model.satellite import Satellite, SatelliteError

SAT = ts.load_preset("satI")
FREE_MODELS = [m.name for m in MODELS if m.orbit == "free"]


@pytest.mark.parametrize("name", FREE_MODELS)
def test_a_free_model_refuses_a_circular_orbit_naming_model_orbit_and_fix(name):
    with pytest.raises(ValueError) as exc:
        model_for_orbit(name, "circular")
    msg = str(exc.value)
    assert "\n" not in msg and f"model = {name!r}" in msg and "orbit = 'circular'" in msg
    assert "orbit='free'" in msg
    twin = {v: k for k, v in FREE_VARIANTS.items()}.get(name)
    if twin:
        assert f"model = {twin!r}" in msg


@pytest.mark.parametrize("name", ["free", "3d-free"])
def test_simulate_refuses_a_free_model_on_a_circular_satellite_before_running(name):
    with pytest.raises(ValueError, match=rf"^model = '{name}' is a free-orbit model"):
        ts.simulate(SAT, model=name, periods=0.01, progress=False)


def test_compare_refuses_two_names_that_run_one_model():
    free = SAT.replace(orbit="free")
    with pytest.raises(ValueError, match=r"^models: derived, free all run model 'free'"):
        compare(free, models=("derived", "free"), periods=0.01, progress=False)


def test_the_density_follows_the_orbit_unless_given():
    assert SAT.density_auto and SAT.density_mode == "uniform"
    free = SAT.replace(orbit="free")
    assert free.density_auto and free.density_mode == "per-body"
    assert free.replace(orbit="circular").density_mode == "uniform"
    explicit = SAT.replace(density_mode="uniform")
    assert not explicit.density_auto
    assert explicit.replace(orbit="free").density_mode == "uniform"
    assert SAT.replace(density_mode="per-body").replace(orbit="free").density_mode == "per-body"


def test_uniform_air_on_a_free_orbit_is_explained_in_the_density_line():
    uniform_free = SAT.replace(orbit="free", density_mode="uniform")
    assert density_text(uniform_free).endswith(f"NOTE: {CONSTANT_AIR_NOTE}")
    for sat in (SAT, SAT.replace(orbit="free"), SAT.replace(density_mode="uniform")):
        assert "NOTE" not in density_text(sat)


def test_an_automatic_density_survives_to_dict_and_the_toml_writer(tmp_path):
    free = SAT.replace(orbit="free")
    d = free.to_dict()
    assert "density_mode" not in d and "density_auto" not in d
    back = Satellite(**d)
    assert back.density_auto and back.density_mode == "per-body"
    assert Satellite(**free.replace(density_mode="uniform").to_dict()).density_mode == "uniform"
    path = tmp_path / "s.toml"
    path.write_text(dumps(free))
    assert load(path).density_auto and load(path).density_mode == "per-body"
    path.write_text(dumps(free.replace(density_mode="uniform")))
    assert (load(path).density_auto, load(path).density_mode) == (False, "uniform")


def test_a_toml_density_key_is_explicit():
    doc = {"name": "x",
           "satellite": dict(m1=10.0, m2=105.0, m3=1.0, A1=0.1, A2=1.05, A3=12.0, a=1.0, b=10.5),
           "tethers": dict(l10=6.0, l20=6.0, E1_N_per_mm2=0.004, E2_N_per_mm2=0.0427,
                           c1=3e-4, c2=3e-4),
           "orbit": dict(altitude_km=200.0, orbit="free"),
           "initial": dict(delta_x=29.0, delta_y=0.0, theta0_deg=30.0, delta_x_dot=0.0,
                           delta_y_dot=0.0, theta_dot=0.0)}
    assert from_dict(doc).density_mode == "per-body"
    doc["environment"] = {"density": "uniform"}
    assert from_dict(doc).density_mode == "uniform" and not from_dict(doc).density_auto


def _e_max(sat, top):
    """Largest e whose apogee r_p (1 + e) / (1 - e) stays at R_E + top (solved for e)."""
    r_p, r_a = R_EARTH + sat.altitude, R_EARTH + top
    return (r_a - r_p) / (r_a + r_p)


@pytest.mark.parametrize("density", ["per-body", "uniform"])
def test_an_apogee_above_the_air_table_is_refused_at_load(density):
    top = atmosphere.H_MAX - (body_reach(SAT) if density == "per-body" else 0.0)
    e_max = _e_max(SAT, top)
    with pytest.raises(SatelliteError) as exc:
        SAT.replace(orbit="free", eccentricity=0.0999, density_mode=density)
    msg = str(exc.value)
    assert "\n" not in msg and "eccentricity = 0.0999" in msg
    assert f"apogee at {(SAT.r0 * 1.0999 / 0.9001 - R_EARTH) / 1e3:.1f} km" in msg
    assert f"0 <= e <= {math.floor(e_max * 1e4) / 1e4:.4f}" in msg
    ok = SAT.replace(orbit="free", eccentricity=e_max * (1 - 1e-9), density_mode=density)
    assert apogee_altitude(ok) <= top
    with pytest.raises(SatelliteError, match="leaves the air model"):
        SAT.replace(orbit="free", eccentricity=e_max * (1 + 1e-6), density_mode=density)


def test_the_apogee_is_the_vis_viva_apogee_of_the_perigee_start():
    sat = SAT.replace(orbit="free", eccentricity=0.02)
    a = sat.r0 / (1 - 0.02)  # perigee r_p = a (1 - e)
    assert apogee_altitude(sat) == pytest.approx(a * 1.02 - R_EARTH, rel=1e-14)


def test_the_equilibrium_refuses_a_free_orbit():
    with pytest.raises(ValueError, match=r"^orbit = 'free': the equilibrium is that of the "
                                         r"orbit held circular"):
        find_equilibrium(SAT.replace(orbit="free"))
