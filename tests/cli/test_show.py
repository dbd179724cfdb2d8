"""tethersim/cli/show.py: values in the units --set takes, exactly."""
from __future__ import annotations

from importlib import resources

import pytest

from tethersim.cli.show import exact
from tethersim.model import params
from tethersim.model.presets import load_preset

SATI_TEXT = (resources.files("tethersim.model.presets") / "satI.toml").read_text()


def _values(out: str) -> dict:
    """{name: (value text, unit)} of the parameter lines of `show`."""
    rows = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[0] in params.NAMES:
            rows[parts[0]] = (parts[1], " ".join(parts[2:]))  # "N s/m" has a space
    return rows


@pytest.mark.parametrize("name", ["satI", "SATII", "dumbsat"])
def test_show_prints_every_parameter_in_the_units_set_takes(name, cli):
    code, out, _ = cli(["show", name])
    assert code == 0
    rows = _values(out)
    # every parameter with a value; unset MSIS indices (the bundled table's) are said so
    assert set(rows) == set(params.NAMES) - {"f107", "f107a", "ap"}
    assert "f107, f107a, ap unset: the bundled table" in out
    for key, (_, unit) in rows.items():
        assert unit == params.unit(key), key
    assert rows["E1"][1] == "N/mm^2" and rows["altitude"][1] == "km" and rows["m1"][1] == "kg"
    assert "units --set takes" in out.splitlines()[1]  # the header says so
    assert "theta [rad]" in out and "rad/s" in out and "kg/m^3" in out
    assert "period 5309.64 s" in out or name != "satI"  # facts.md: ≈ 5310 s at 200 km


def test_show_satI_values_are_the_preset_files(cli):
    rows = _values(cli(["show", "satI"])[1])
    assert rows["E1"][0] == "0.004"  # E1_N_per_mm2 = 0.004 in satI.toml
    assert rows["altitude"][0] == "200"  # altitude_km = 200
    assert rows["m2"][0] == "105"


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_show_values_fed_back_through_set_give_the_same_satellite(name, cli):
    rows = _values(cli(["show", name])[1])
    argv = ["show", name]
    for key, (value, _) in rows.items():
        argv += ["--set", f"{key}={value}"]
    code, again, err = cli(argv)
    assert code == 0, err
    assert _values(again) == rows
    sat = load_preset(name)
    rebuilt = params.apply_overrides(sat, [f"{k}={v}" for k, (v, _) in rows.items()])
    assert rebuilt == sat


def test_show_reflects_set_in_edge_units(cli):
    rows = _values(cli(["show", "satI", "--set", "E1=0.006", "--set", "altitude=250"])[1])
    assert rows["E1"] == ("0.006", "N/mm^2") and rows["altitude"] == ("250", "km")


@pytest.mark.parametrize("value", [0.1 + 0.2, 1 / 3, 4.27e-2, 200.0, 1e-300])
def test_exact_reads_back_as_the_same_float(value):
    assert float(exact(value)) == value


def test_show_accepts_a_user_toml_path(tmp_path, cli):
    path = tmp_path / "mine.toml"
    path.write_text(SATI_TEXT.replace('name = "SatI"', 'name = "Mine"'))
    code, out, _ = cli(["show", str(path)])
    assert code == 0
    assert out.startswith("Mine")


def test_show_prints_the_3d_moments_and_they_read_back_through_set(cli):
    code, out, _ = cli(["show", "satI", "--set", "inertia=points", "--set", "I2=10,12,3"])
    assert code == 0
    lines = {ln.split()[0]: ln.split() for ln in out.splitlines() if ln.split()[:1] in (["I1"],
                                                                                       ["I2"])}
    assert "inertia points" in out
    assert lines["I1"][1] == "0,0,0" and lines["I1"][-2:] == ["(point", "mass)"]
    assert lines["I2"][1] == "10,12,3" and lines["I2"][-1] == "(set)"
    box = cli(["show", "satI"])[1]
    i2 = next(ln.split() for ln in box.splitlines() if ln.split()[:1] == ["I2"])
    assert "box, thesis Eq 4.4" in box
    sat = params.apply_overrides(load_preset("satI"), [f"I2={i2[1]}"])
    assert sat.I2 == (105 * 2 * 1.05 / 12,) * 3  # exactly the box, fed back
