"""Orbit and air options: one table, preset sections, --set, one-line errors."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.model import params
from tethersim.model.presets import from_dict
from tethersim.model.presets.write import dumps

SAT = ts.load_preset("satI")


def test_replace_with_every_option_round_trips():
    s = SAT.replace(orbit="free", j2=True, eccentricity=0.001, atmosphere="nrlmsise00",
                    epoch="2017-06-23T00:00:00", f107=150, f107a=150, ap=4)
    assert (s.orbit, s.j2, s.eccentricity, s.atmosphere) == ("free", True, 0.001, "nrlmsise00")
    assert (s.f107, s.f107a, s.ap) == (150.0, 150.0, 4.0)
    # the uniform density is MSIS's at the orbit altitude (24 local times), not Vallado's
    assert s.rho != pytest.approx(SAT.rho, rel=0.01)
    assert ts.parameters(s)["rho"] == s.rho


def test_defaults_keep_the_thesis_and_the_store_json():
    assert (SAT.orbit, SAT.j2, SAT.eccentricity, SAT.atmosphere) == ("circular", False, 0.0,
                                                                      "vallado")
    assert SAT.reentry_altitude == 120e3 and SAT.density_scale == 1.0
    assert "orbit" not in SAT.to_dict() and "density_scale" not in SAT.to_dict()
    assert SAT.rho == pytest.approx(2.789e-10)


def test_density_scale_multiplies_the_uniform_density():
    assert SAT.replace(density_scale=1.5).rho == pytest.approx(1.5 * SAT.rho, rel=1e-15)


@pytest.mark.parametrize("change, match", [
    (dict(orbit="elliptic"), r"satI.toml \(modified\): orbit = 'elliptic': allowed values circular, free$"),
    (dict(orbit="free", eccentricity=0.1), r"eccentricity = 0.1: allowed range 0 <= e < 0.1$"),
    (dict(orbit="free", eccentricity=-0.01), r"eccentricity = -0.01: allowed range"),
    (dict(eccentricity=0.01), r"eccentricity = 0.01: needs orbit = 'free'"),
    (dict(j2=True), r"j2 = true: needs orbit = 'free'"),
    (dict(orbit="free", j2="yes"), r"j2 = 'yes': must be true or false$"),
    (dict(reentry_altitude=50e3), r"reentry_altitude = 50 km: allowed range 80..1000 km$"),
    (dict(orbit="free", reentry_altitude=250e3), r"reentry_altitude = 250 km: must be below"),
    (dict(atmosphere="jacchia"), r"atmosphere = 'jacchia': allowed values vallado, nrlmsise00$"),
    (dict(atmosphere="nrlmsise00", f107=30, f107a=150, ap=4), r"f107 = 30 sfu is outside"),
    (dict(atmosphere="nrlmsise00", f107=150), r"give all three"),
    (dict(epoch="yesterday"), r"epoch = 'yesterday': must be an ISO date"),
    (dict(atmosphere="nrlmsise00", epoch="2040-01-01"), r"outside the bundled space-weather"),
    (dict(density_scale=0.0), r"density_scale = 0: allowed range 0.01..100$"),
    (dict(density_mode="per-body", atmosphere="nrlmsise00", altitude=80.05e3, f107=150.0,
          f107a=150.0, ap=4.0), r"stays inside 80-1000 km \(nrlmsise00\)$"),
])
def test_bad_values_give_one_line_errors_naming_the_field(change, match):
    with pytest.raises(ts.SatelliteError, match=match) as exc:
        SAT.replace(**change)
    assert "\n" not in str(exc.value)


def test_set_takes_options_as_text_and_numbers_in_edge_units():
    s = params.apply_overrides(SAT, ["orbit=free", "j2=true", "eccentricity=0.002",
                                     "reentry_altitude=130"])
    assert (s.orbit, s.j2, s.eccentricity, s.reentry_altitude) == ("free", True, 0.002, 130e3)
    with pytest.raises(ValueError, match=r"^--set orbit=oval: allowed values circular, free$"):
        params.apply_overrides(SAT, ["orbit=oval"])
    with pytest.raises(ValueError, match="is an option, not a number"):
        params.parse_grid(params.check_name("orbit"), "1,2")


def _doc(**sections):
    doc = {"name": "X", "satellite": dict(m1=10.0, m2=105.0, m3=1.0, A1=0.1, A2=1.05, A3=12.0,
                                          a=1.0, b=10.5),
           "tethers": dict(l10=6.0, l20=6.0, E1_N_per_mm2=0.004, E2_N_per_mm2=0.0427, c1=3e-4,
                           c2=3e-4),
           "orbit": {"altitude_km": 200.0}, "initial": dict(
               delta_x=29.0, delta_y=0.0, theta0_deg=30.0, delta_x_dot=0.0, delta_y_dot=0.0,
               theta_dot=0.0)}
    for k, v in sections.items():
        doc.setdefault(k, {}).update(v)
    return doc


def test_preset_sections_orbit_and_atmosphere():
    s = from_dict(_doc(orbit=dict(orbit="free", j2=True, eccentricity=0.001,
                                  reentry_altitude_km=110.0),
                       atmosphere=dict(atmosphere="nrlmsise00", epoch="2017-06-23T00:00:00",
                                       f107=150.0, f107a=150.0, ap=4.0, density_scale=1.0)))
    assert (s.orbit, s.j2, s.eccentricity, s.reentry_altitude) == ("free", True, 0.001, 110e3)
    assert s.atmosphere == "nrlmsise00" and s.f107 == 150.0
    import tomllib
    assert from_dict(tomllib.loads(dumps(s)), "x") == s  # the writer writes them back


def test_preset_errors_name_the_file_key():
    with pytest.raises(ts.SatelliteError, match=r"^f\.toml: orbit\.orbit = 'x': allowed"):
        from_dict(_doc(orbit=dict(orbit="x")), "f.toml")
    with pytest.raises(ts.SatelliteError, match=r"orbit\.j2 = 1: must be true or false$"):
        from_dict(_doc(orbit=dict(j2=1)), "f.toml")
    with pytest.raises(ts.SatelliteError, match=r"unknown key atmosphere\.'rho'"):
        from_dict(_doc(atmosphere=dict(rho=1.0)), "f.toml")


def test_air_density_equals_pymsis_direct_output():
    import pymsis
    s = SAT.replace(atmosphere="nrlmsise00", epoch="2017-06-23T06:00:00", f107=120.0,
                    f107a=140.0, ap=7.0, density_scale=1.3)
    h, t, lon = 250e3, 5400.0, 1.2
    when = np.datetime64("2017-06-23T07:30:00")
    direct = pymsis.calculate(when, math.degrees(lon), 0.0, h / 1e3, 120.0, 140.0,
                              [[7.0] * 7], version=0)[0, 0]
    assert ts.air_density(s, h, t, lon) == pytest.approx(1.3 * direct, rel=1e-12)
    assert ts.air_density(SAT, 200e3) == pytest.approx(2.789e-10, rel=1e-12)  # Vallado
    with pytest.raises(ValueError, match="outside 80-1000 km"):
        ts.air_density(s, 50e3)


def test_air_density_from_the_bundled_table_for_the_epoch():
    from tethersim.model.air.indices import indices_for_day
    s = SAT.replace(atmosphere="nrlmsise00", epoch="2015-03-17T00:00:00")
    day = indices_for_day("2015-03-17")
    same = SAT.replace(atmosphere="nrlmsise00", epoch="2015-03-17T00:00:00", f107=day.f107,
                       f107a=day.f107a, ap=day.ap)
    assert ts.air_density(s, 300e3) == ts.air_density(same, 300e3)
