"""Shipped presets and strict validation of satellite TOML files.

Reference relations: docs/sources.md, "The thesis" (Maramba 2005; page numbers are the
thesis's own).  Table 4.1's numbers were lost, so the presets are checked against
the relations that survive, not against values.
"""
from __future__ import annotations

import math
import re
from importlib import resources

import pytest

import tethersim
from tethersim import SatelliteError
from tethersim.model.presets import load, load_preset, resolve

SATI_TEXT = (resources.files("tethersim.model.presets") / "satI.toml").read_text()


# --- the three presets ---------------------------------------------------------

@pytest.mark.parametrize("name, expected", [
    ("satI", "SatI"), ("SATI", "SatI"), ("sati", "SatI"),
    ("satII", "SatII"), ("satii", "SatII"), ("SATII", "SatII"),
    ("dumbsat", "DumbSat"), ("DumbSat", "DumbSat"), ("DUMBSAT", "DumbSat"),
])
def test_preset_loads_by_name_in_any_case(name, expected):
    sat = load_preset(name)
    assert isinstance(sat, tethersim.Satellite)
    assert sat.name == expected
    assert tethersim.load_preset(name) == sat
    assert resolve(name) == sat


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_preset_com_lies_on_the_boom(name):
    # facts.md: "the COM is taken to stay on the boom (3-1)", i.e. m1 b = m2 a
    sat = load_preset(name)
    assert sat.m1 * sat.b == pytest.approx(sat.m2 * sat.a, rel=1e-12)


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_preset_balloon_much_lighter_than_tip_mass(name):
    # facts.md: "The balloon mass is much smaller than the tip-mass (3-1)"
    sat = load_preset(name)
    assert sat.m3 < sat.m1


def test_satI_bus_about_ten_tip_masses_and_b_a_little_over_ten_a():
    # facts.md (5-19): main bus mass ≈ 10 × tip-mass; b "a little over" 10 × a
    sat = load_preset("satI")
    assert 9.5 <= sat.m2 / sat.m1 <= 11
    assert 10 < sat.b / sat.a < 11


def test_satI_stable_moduli_ratio_near_ten_inside_sweep():
    # facts.md (5-18): stable moduli around E2 ≈ 10 × E1; E2 swept from 0 to 0.06 N/mm²
    # (E in N/mm² × 1 mm² = N, 3-1)
    sat = load_preset("satI")
    assert 5 <= sat.E2 / sat.E1 <= 15
    assert 0 <= sat.E2 <= 0.06


def test_satII_mass_and_length_ratios_about_23_and_24():
    # facts.md (5-19): bus ≈ 23 × tip-mass, b ≈ 24 × a
    sat = load_preset("satII")
    assert 20 <= sat.m2 / sat.m1 <= 26
    assert 20 <= sat.b / sat.a <= 26


def test_dumbsat_is_a_symmetric_dumbbell():
    # facts.md (4-2, 5-23): equal end masses, a = b, equal frontal areas, equal
    # tether lengths, so E1 = E2 and c1 = c2
    sat = load_preset("dumbsat")
    assert sat.m1 == sat.m2
    assert sat.a == sat.b
    assert sat.A1 == sat.A2
    assert sat.l10 == sat.l20
    assert sat.E1 == sat.E2
    assert sat.c1 == sat.c2


def test_satI_has_a_tether_with_taut_length_six_metres():
    # facts.md (5-3): "One tether's taut length is 6 m"
    sat = load_preset("satI")
    assert 6.0 in (sat.l10, sat.l20)


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_preset_initial_pitch_is_pi_over_6_with_zero_rates(name):
    # facts.md, Table 4.2: θ0 = π/6 for all three satellites; all rates zero
    sat = load_preset(name)
    assert sat.initial[2] == pytest.approx(math.pi / 6, abs=1e-15)
    assert sat.initial[3:] == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_preset_orbit_is_200_km_with_drag_coefficient_2(name):
    # facts.md: circular orbit at 200 km altitude (1-5, 3-3); C_D = 2 for every body (3-9)
    sat = load_preset(name)
    assert sat.altitude == 200e3
    assert sat.CD == 2.0
    assert sat.density_mode == "uniform"


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_preset_reproduces_thesis_step_sizes(name):
    # facts.md: 17.7 s/step for 5 periods in 1500 steps (5-2), 26.55 s/step for
    # 50 periods in 10,000 steps (5-7), 0.531 s/step for 2 periods in 20,000 (4-6)
    period = load_preset(name).period
    assert f"{period * 5 / 1500:.2f}" == "17.70"
    assert f"{period * 50 / 10000:.2f}" == "26.55"
    assert f"{period * 2 / 20000:.3f}" == "0.531"


# --- user files ------------------------------------------------------------------

def _set(text: str, key: str, value: str) -> str:
    """Replace the value of the unique line 'key = ...' in a preset's text."""
    new, n = re.subn(rf"^{re.escape(key)}\s*=.*$", f"{key} = {value}", text, flags=re.M)
    assert n == 1, key
    return new


def _drop(text: str, pattern: str) -> str:
    new, n = re.subn(pattern, "", text, flags=re.M)
    assert n >= 1, pattern
    return new


def test_user_toml_loads_via_load_and_resolve(tmp_path):
    text = _set(SATI_TEXT, "name", '"MySat"')
    text = _set(text, "delta_x", "30.0")
    path = tmp_path / "mysat.toml"
    path.write_text(text)
    for sat in (tethersim.load(path), load(str(path)), resolve(str(path))):
        assert sat.name == "MySat"
        assert sat.initial[0] == 30.0
        assert sat.m1 == load_preset("satI").m1
        assert str(path) in sat.source


def test_user_file_without_toml_suffix_resolves_as_a_path(tmp_path):
    path = tmp_path / "mysat.cfg"
    path.write_text(SATI_TEXT)
    assert resolve(str(path)) == load_preset("satI")


def test_user_toml_environment_table_is_optional_and_read(tmp_path):
    path = tmp_path / "perbody.toml"
    path.write_text(SATI_TEXT + '\n[environment]\nCD = 2.2\ndensity = "per-body"\n')
    sat = load(path)
    assert sat.CD == 2.2
    assert sat.density_mode == "per-body"


@pytest.mark.parametrize("deg", [180.0, -180.0])
def test_theta0_at_the_ends_of_the_allowed_range_loads(tmp_path, deg):
    path = tmp_path / "edge.toml"
    path.write_text(_set(SATI_TEXT, "theta0_deg", str(deg)))
    assert load(path).initial[2] == pytest.approx(math.radians(deg))


def test_integer_values_are_accepted_as_numbers(tmp_path):
    path = tmp_path / "ints.toml"
    path.write_text(_set(SATI_TEXT, "m1", "10"))
    assert load(path).m1 == 10.0


BAD_FILES = {
    # id: (edit of satI.toml's text, words the message must contain)
    "unknown-top-level-key": (lambda s: 'colour = "red"\n' + s, ["'colour'", "allowed"]),
    "unknown-key-in-table": (lambda s: _set(s, "m3", "1.0\nm4 = 2.0"),
                             ["m4", "allowed", "'m1'"]),
    "missing-key": (lambda s: _drop(s, r"^m3\s*=.*\n"), ["satellite.m3", "kg"]),
    "missing-name": (lambda s: _drop(s, r"^name\s*=.*\n"), ["name"]),
    "missing-table": (lambda s: _drop(s, r"^\[orbit\]\n|^altitude_km\s*=.*\n"),
                      ["[orbit]", "altitude_km"]),
    "table-not-a-table": (lambda s: "orbit = 200.0\n" + _drop(
        s, r"^\[orbit\]\n|^altitude_km\s*=.*\n"), ["orbit", "must be a table"]),
    "negative-tip-mass": (lambda s: _set(s, "m1", "-10.0"), ["m1", "-10", "> 0"]),
    "negative-balloon-mass": (lambda s: _set(s, "m3", "-1.0"), ["m3", "> 0"]),
    "zero-tether-length": (lambda s: _set(s, "l10", "0.0"), ["l10", "> 0"]),
    "zero-length-b": (lambda s: _set(s, "b", "0.0"), ["b = 0", "> 0"]),
    "zero-balloon-area": (lambda s: _set(s, "A3", "0.0"), ["A3", "> 0"]),
    "negative-area": (lambda s: _set(s, "A1", "-0.1"), ["A1", "> 0"]),
    "nan-mass": (lambda s: _set(s, "m2", "nan"), ["satellite.m2", "finite"]),
    "inf-rate": (lambda s: _set(s, "theta_dot", "inf"), ["initial.theta_dot", "finite"]),
    "string-not-number": (lambda s: _set(s, "m1", '"ten"'), ["satellite.m1", "number"]),
    "bool-not-number": (lambda s: _set(s, "a", "true"), ["satellite.a", "number"]),
    "com-off-the-boom": (lambda s: _set(s, "b", "11.0"), ["COM", "m1*b", "m2*a"]),
    "altitude-1500-km": (lambda s: _set(s, "altitude_km", "1500.0"),
                         ["orbit.altitude_km", "1500", "0-1000 km"]),
    "altitude-minus-5-km": (lambda s: _set(s, "altitude_km", "-5.0"),
                            ["orbit.altitude_km", "-5", "0-1000 km"]),
    "theta0-200-deg": (lambda s: _set(s, "theta0_deg", "200.0"),
                       ["initial.theta0_deg", "200", "-180 to 180"]),
    "negative-modulus": (lambda s: _set(s, "E1_N_per_mm2", "-0.004"),
                         ["tethers.E1_N_per_mm2", ">= 0"]),
    "negative-damping": (lambda s: _set(s, "c2", "-0.0003"), ["c2", ">= 0"]),
    "density-bogus": (lambda s: s + '\n[environment]\ndensity = "bogus"\n',
                      ["density", "bogus", "uniform", "per-body"]),
    "negative-CD": (lambda s: s + "\n[environment]\nCD = -1.0\n", ["CD", ">= 0"]),
    "invalid-toml-syntax": (lambda s: _set(s, "m1", "= 10.0"), ["not valid TOML"]),
}


@pytest.mark.parametrize("edit, words", BAD_FILES.values(), ids=BAD_FILES.keys())
def test_bad_toml_raises_satellite_error_naming_field_and_range(tmp_path, edit, words):
    path = tmp_path / "bad.toml"
    path.write_text(edit(SATI_TEXT))
    with pytest.raises(SatelliteError) as exc:
        load(path)
    msg = str(exc.value)
    for w in words:
        assert w in msg, f"{w!r} not in {msg!r}"
    assert str(path) in msg  # the message names the file
    assert "\n" not in msg
    # the same error through the public entry points
    with pytest.raises(SatelliteError):
        tethersim.load(path)
    with pytest.raises(SatelliteError):
        resolve(str(path))


def test_satellite_error_is_a_value_error():
    assert issubclass(SatelliteError, ValueError)


def test_nonexistent_file_raises_satellite_error_naming_the_path(tmp_path):
    path = tmp_path / "nope.toml"
    with pytest.raises(SatelliteError, match="cannot read") as exc:
        load(path)
    assert str(path) in str(exc.value)
    with pytest.raises(SatelliteError, match="cannot read"):
        resolve(str(path))


@pytest.mark.parametrize("name", ["satIII", "hubble", "sat I"])
def test_unknown_preset_name_lists_the_presets(name):
    with pytest.raises(SatelliteError) as exc:
        load_preset(name)
    msg = str(exc.value)
    assert repr(name) in msg
    for preset in ("satI", "satII", "dumbsat"):
        assert preset in msg
    with pytest.raises(SatelliteError, match="unknown preset"):
        resolve(name)


def test_satellite_replace_validates_again():
    sat = load_preset("satI")
    with pytest.raises(SatelliteError, match=r"m3 = -1.*> 0"):
        sat.replace(m3=-1.0)
    with pytest.raises(SatelliteError, match="COM off the boom"):
        sat.replace(a=2.0)
    with pytest.raises(SatelliteError, match="0-1000 km"):
        sat.replace(altitude=1.5e6)
