"""Bad inputs, as a hostile new user would type them: every one refused with a one-line
message naming the field and its allowed (or plausible) range, never a traceback.

Three families of fixed cases (preset file values, --set/--scale, other CLI options),
then property-based attacks (hypothesis) on the preset loader and the --set and grid
parsers.  Nothing here simulates: every refusal happens before a run.
"""
from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.messages import one_line
from tethersim import Satellite, load_preset
from tethersim.cli.main import main
from tethersim.model.params import NAMES, apply_overrides, parse_grid
from tethersim.model.presets import SCHEMA, from_dict, load
from tethersim.model.satellite import SatelliteError

TEXT = (Path(__file__).parents[2] / "tethersim" / "model" / "presets" / "satI.toml").read_text()
SAT = load_preset("satI")
PLAUSIBLE = "plausible range"


def _set(text: str, key: str, value: str) -> str:
    new, n = re.subn(rf"^{key}\s*=[^#\n]*", f"{key} = {value} ", text, flags=re.M)
    assert n == 1, key
    return new



# --- preset file values: (key, value, what the message must say) -------------------------
PRESET_CASES = [
    ("m3", "1e-5", ["satellite.m3 = 1e-05 kg", PLAUSIBLE, "0.001..100000 kg"]),
    ("m3", "2e5", ["satellite.m3 = 200000 kg", "0.001..100000 kg"]),
    ("m3", "0.0", ["satellite.m3 = 0.0 kg", "must be > 0"]),
    ("A1", "1e-8", ["satellite.A1 = 1e-08 m^2", "1e-06..10000 m^2"]),
    ("A2", "-1.0", ["satellite.A2 = -1.0 m^2", "must be > 0"]),
    ("A3", "2e4", ["satellite.A3 = 20000 m^2", "1e-06..10000 m^2"]),
    ("l10", "2e4", ["tethers.l10 = 20000 m", "0.001..10000 m"]),
    ("l20", "1e-4", ["tethers.l20 = 0.0001 m", "0.001..10000 m"]),
    ("E1_N_per_mm2", "2e6", ["tethers.E1_N_per_mm2 = 2e+06 N/mm^2", "0..1e+06 N/mm^2"]),
    ("E2_N_per_mm2", "-1.0", ["tethers.E2_N_per_mm2 = -1.0 N/mm^2", "must be >= 0"]),
    ("c1", "2e4", ["tethers.c1 = 20000 N s/m", "0..10000 N s/m"]),
    ("c1", "nan", ["tethers.c1 = nan", "finite number in N s/m"]),
    ("l10", "true", ["tethers.l10 = True", "must be a number in m"]),
    ("altitude_km", "50.0", ["orbit.altitude_km = 50 km", "120..1000 km", "re-enters"]),
    ("altitude_km", "119.9", ["orbit.altitude_km = 119.9 km", "120..1000 km"]),
    ("altitude_km", "1500.0", ["orbit.altitude_km = 1500 km", "allowed range 0-1000 km"]),
    ("altitude_km", '"high"', ["orbit.altitude_km = 'high'", "must be a number in km"]),
    ("delta_x", "1e9", ["delta_x, delta_y = (1e+09, 0) m", "<= 165 m"]),
    ("delta_y", "-5e3", ["delta_x, delta_y = (29, -5000) m", "<= 165 m"]),
    ("theta0_deg", "400.0", ["initial.theta0_deg = 400 deg", "allowed range -180 to 180 deg"]),
    ("theta_dot", "inf", ["initial.theta_dot = inf", "finite number in rad/s"]),
    ("m1", "-10.0", ["satellite.m1 = -10.0 kg", "must be > 0"]),
]


@pytest.mark.parametrize("key, value, expected", PRESET_CASES,
                         ids=[f"preset-{k}={v}" for k, v, _ in PRESET_CASES])
def test_bad_preset_value_names_key_and_range(tmp_path, key, value, expected):
    path = tmp_path / "bad.toml"
    path.write_text(_set(TEXT, key, value))
    with pytest.raises(SatelliteError) as info:
        load(path)
    line = one_line(str(info.value))
    assert line.startswith(f"{path}: ")
    for text in expected:
        assert text in line, line


@pytest.mark.parametrize("mutate, expected", [
    (lambda s: s.replace("[satellite]\nm1 = 10.0", "[satellite]\nm1 = 1e6").replace(
        "b = 10.5 ", "b = 0.000105 "), ["satellite.m1 = 1e+06 kg", "0.001..100000 kg"]),
    (lambda s: _set(_set(s, "l10", "0.1"), "l20", "0.1"), ["l10 + l20 = 0.2 m", ">= 1.15 m"]),
    (lambda s: s + "\n[environment]\nCD = 0.1\n", ["environment.CD = 0.1", "0 or 0.5..4"]),
    (lambda s: s + "\n[model]\nallow_implausible = \"yes\"\n",
     ["model.allow_implausible = 'yes'", "true or false"]),
], ids=["preset-masses-scaled", "preset-short-tethers", "preset-CD", "preset-flag-type"])
def test_bad_preset_combination_names_fields_and_range(tmp_path, mutate, expected):
    path = tmp_path / "bad.toml"
    path.write_text(mutate(TEXT))
    with pytest.raises(SatelliteError) as info:
        load(path)
    line = one_line(str(info.value))
    for text in expected:
        assert text in line, line


def test_preset_flag_allows_implausible_values_and_says_so(tmp_path):
    path = tmp_path / "low.toml"
    path.write_text(_set(TEXT, "altitude_km", "110.0") + "\n[model]\nallow_implausible = true\n")
    sat = load(path)
    assert sat.allow_implausible and sat.altitude == 110e3
    assert sat.implausible == (
        "altitude = 110 km: plausible range 120..1000 km (circular orbit altitude: below 120 km "
        "the orbit re-enters within hours; above 1000 km is outside Vallado's atmosphere table)",)
    # the hard limits stay: the flag never allows what the model cannot compute
    with pytest.raises(SatelliteError, match="allowed range 0-1000 km"):
        sat.replace(altitude=2000e3)


def test_the_flag_travels_with_the_satellite(tmp_path):
    """Through a written preset (tethersim tune), a sweep spec (stores, Dask) and --set."""
    from tethersim.experiments.sweep import SweepSpec
    from tethersim.model.params import with_values
    from tethersim.model.presets.write import dumps

    low = SAT.replace(altitude=110e3, allow_implausible=True)
    path = tmp_path / "low.toml"
    path.write_text(dumps(low))
    assert load(path) == low
    spec = SweepSpec(low, (("E1", [0.003, 0.004]),), periods=1)
    assert SweepSpec.from_json(spec.to_json()) == spec
    assert with_values(low, {"altitude": 100}).allow_implausible
    # a plausible satellite's spec is unchanged by the flag's existence: old stores resume
    assert "allow_implausible" not in SweepSpec(SAT, (("E1", [0.004]),)).to_json()


# --- --set / --scale on the command line ----------------------------------------------
SET_CASES = [
    (["--set", "altitude=50"], ["altitude = 50 km", "120..1000 km"]),
    (["--set", "altitude=2000"], ["altitude = 2000 km", "allowed range 0-1000 km"]),
    (["--set", "m3=0"], ["m3 = 0.0 kg", "must be > 0"]),
    (["--set", "m3=1e9"], ["m3 = 1e+09 kg", "0.001..100000 kg"]),
    (["--set", "A3=-1"], ["A3 = -1.0 m^2", "must be > 0"]),
    (["--set", "A3=1e5"], ["A3 = 100000 m^2", "1e-06..10000 m^2"]),
    (["--set", "E1=-0.1"], ["E1 = -0.1", "must be >= 0"]),
    (["--set", "E1=1e7"], ["E1 = 1e+07 N/mm^2", "0..1e+06 N/mm^2"]),
    (["--set", "c2=1e5"], ["c2 = 100000 N s/m", "0..10000 N s/m"]),
    (["--set", "c1=-1"], ["c1 = -1.0 N s/m", "must be >= 0"]),
    (["--set", "CD=0.1"], ["CD = 0.1", "0 or 0.5..4"]),
    (["--set", "CD=9"], ["CD = 9", "0 or 0.5..4"]),
    (["--set", "l10=1e5"], ["l10 = 100000 m", "0.001..10000 m"]),
    (["--set", "l20=0.0001"], ["l20 = 0.0001 m", "0.001..10000 m"]),
    (["--set", "E1=nan"], ["--set E1=nan", "must be finite", "0..1e+06"]),
    (["--set", "E1=inf"], ["--set E1=inf", "must be finite", "0..1e+06"]),
    (["--set", "E1=abc"], ["--set E1=abc", "not a number", "0..1e+06"]),
    (["--set", "nosuch=1"], ["'nosuch'", "allowed: m1, m2"]),
    (["--set", "E1"], ["--set 'E1'", "NAME=VALUE"]),
    (["--set", "b=20"], ["m1*b = 200 kg m", "must equal m2*a"]),
    (["--set", "I1=1,1,5"], ["I1 = (1.0, 1.0, 5.0)", "yaw 5 > roll + pitch 2 kg m^2"]),
    (["--set", "I2=-1,1,1"], ["I2 = (-1.0, 1.0, 1.0)", "each finite and >= 0"]),
    (["--set", "I1=1,2"], ["--set I1=1,2", "roll,pitch,yaw in kg m^2 (three numbers)"]),
    (["--set", "inertia=rods"], ["--set inertia=rods", "allowed values boxes, points"]),
    (["--scale", "altitude=0.1"], ["altitude = 20 km", "120..1000 km"]),
    (["--scale", "m3=1e9"], ["m3 = 1e+09 kg", "0.001..100000 kg"]),
    (["--scale", "E1=x"], ["--scale E1=x", "not a number"]),
]


@pytest.mark.parametrize("argv, expected", SET_CASES, ids=[" ".join(a) for a, _ in SET_CASES])
def test_bad_set_is_one_line_naming_field_and_range(argv, expected, capsys):
    assert main(["show", "satI", *argv]) == 2
    line = one_line(capsys.readouterr().err)
    assert line.startswith("tethersim: error: ")
    for text in expected:
        assert text in line, line


def test_allow_implausible_runs_and_the_summary_says_so(tmp_path, capsys):
    # (an implausible altitude such as 115 km now ends "left-domain": the dense air blows
    # the balloon away, tests/engine/test_domain.py; CD = 0.3 runs and is only implausible)
    rc = main(["run", "satI", "--set", "CD=0.3", "--allow-implausible", "--periods", "0.02",
               "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert rc == 0
    assert "implausible inputs (allowed)     CD = 0.3: plausible range 0 or 0.5..4" in out


# --- other CLI options: refused before any run -------------------------------------------
CLI_CASES = [
    (["run", "satI", "--periods", "-1"], ["--periods", "> 0", "got -1"]),
    (["run", "satI", "--periods", "nan"], ["--periods", "finite number > 0", "got nan"]),
    (["run", "satI", "--steps", "0"], ["--steps", "integer >= 1", "got 0"]),
    (["run", "satI", "--rtol", "1e-20"], ["--rtol", "allowed range 1e-14 <= rtol <= 0.001"]),
    (["run", "satI", "--method", "rk4", "--steps", "-5"], ["--steps", "integer >= 1", "got -5"]),
    (["run", "satI", "--steps", "100000000"], ["--steps", "allowed at most 2 GiB"]),
    (["run", "satI", "--set", "altitude=50"], ["altitude = 50 km", "120..1000 km"]),
    (["run", "nosuch"], ["preset 'nosuch'", "available: satI, satII, dumbsat"]),
    (["sweep", "satI", "--E1", "0:1:0"], ["--E1 0:1:0", "count 0 must be in 1..1000000"]),
    (["sweep", "satI", "--E1", "0:1:2000000"], ["--E1", "must be in 1..1000000"]),
    (["sweep", "satI", "--E1", "1:2:x"], ["--E1 1:2:x", "integer >= 1"]),
    (["sweep", "satI", "--E1", "a,b"], ["--E1 a,b", "not a number", "0..1e+06"]),
    (["sweep", "satI", "--E2", "0.04,inf"], ["--E2", "must be finite", "0..1e+06"]),
    (["sweep", "satI", "--E1", "0:1:1000000", "--E2", "0:1:1000000"],
     ["1e+12 points", "allowed at most 1e+06 points"]),
    (["sweep", "satI", "--periods", "0", "--E1", "0.004"], ["--periods", "> 0", "got 0"]),
    (["sweep", "satI", "--rtol", "1e-20", "--E1", "0.004"], ["--rtol", "1e-14 <= rtol <= 0.001"]),
    (["sweep", "satI", "--altitude", "50,200"], ["altitude = 50 km", "120..1000 km"]),
    (["sweep", "satI", "--c1=-1,0.001"], ["c1 = -1", "must be >= 0"]),
    (["sweep", "satI", "--E1", "1e7"], ["E1 = 1e+07 N/mm^2", "0..1e+06 N/mm^2"]),
    (["sweep", "satI", "--E1", "0.004", "--workers", "0"], ["--workers", ">= 1", "got 0"]),
    (["equilibrium", "satI", "--set", "E1=0", "--set", "E2=0"],
     ["E1 = E2 = 0", "allowed range for an equilibrium: E1 > 0 or E2 > 0"]),
    (["tune", "satI", "--E1", "-1"], ["--E1", "> 0", "got -1"]),
    (["headlines", "--periods", "-1"], ["--periods", "> 0", "got -1"]),
    (["validate", "satI", "--periods", "-1"], ["--periods", "> 0", "got -1"]),
    (["forces", "satI", "--periods", "0"], ["--periods", "> 0", "got 0"]),
    (["compare", "satI", "--models", "nosuch"], ["'nosuch'", "allowed values derived"]),
    (["forces", "satI", "--set", "l10=1e5"], ["l10 = 100000 m", "0.001..10000 m"]),
]


@pytest.mark.parametrize("argv, expected", CLI_CASES, ids=[" ".join(a) for a, _ in CLI_CASES])
def test_bad_cli_option_is_one_line_naming_field_and_range(argv, expected, tmp_path, capsys):
    out = ["--out", str(tmp_path / "out")] if argv[0] in ("run", "sweep", "compare", "forces",
                                                          "headlines") else []
    assert main([*argv, *out]) == 2
    line = one_line(capsys.readouterr().err)
    for text in expected:
        assert text in line, line


def test_there_are_at_least_60_distinct_bad_inputs():
    cases = ([("preset", k, v) for k, v, _ in PRESET_CASES] + [("set", *a) for a, _ in SET_CASES]
             + [tuple(a) for a, _ in CLI_CASES])
    assert len(set(cases)) == len(cases) and len(cases) + 4 >= 60  # + the 4 combinations


# --- property-based: the preset loader -------------------------------------------------
_VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.floats(-1e3, 1e3),
    st.integers(-10**30, 10**30), st.booleans(), st.text(max_size=6),
    st.lists(st.floats(), max_size=2), st.dictionaries(st.text(max_size=3), st.integers(), max_size=1))
_KEYS = [(t, k) for t, keys in SCHEMA.items() for k in keys] + [
    ("environment", "CD"), ("environment", "density"), ("model", "allow_implausible"),
    ("satellite", "inertia"), ("satellite", "I1"), ("satellite", "I2")]
# keys whose bad value may first break the COM-on-the-boom rule (m1 b = m2 a)
_COM = {"m1", "m2", "a", "b"}


def _doc():
    return tomllib.loads(TEXT)


@settings(max_examples=150, deadline=None)
@given(key=st.sampled_from(_KEYS), value=_VALUES, drop=st.booleans())
def test_any_preset_value_loads_or_is_one_line_naming_the_key(key, value, drop):
    table, name = key
    doc = _doc()
    sub = doc.setdefault(table, {})
    if drop and table in SCHEMA:
        sub.pop(name, None)
    else:
        sub[name] = value
    try:
        sat = from_dict(doc, "h.toml")
    except SatelliteError as exc:  # the only documented error type
        line = one_line(str(exc))
        assert line.startswith("h.toml: ")
        leaf = name.split("_N_per")[0].removesuffix("_km").removesuffix("_deg")
        assert leaf in line or (name in _COM and "COM off the boom" in line), line
        return
    assert isinstance(sat, Satellite)
    assert not sat.implausible or sat.allow_implausible


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=st.text(max_size=40))
def test_any_preset_text_loads_or_isone_line(text, tmp_path_factory):
    path = tmp_path_factory.getbasetemp() / "fuzz.toml"
    path.write_text(text)
    try:
        load(path)
    except SatelliteError as exc:
        assert one_line(str(exc)).startswith(f"{path}: ")


@settings(max_examples=100, deadline=None)
@given(key=st.sampled_from(_KEYS), text=st.text(
    alphabet=st.characters(blacklist_categories=("Cs",)), max_size=12))
def test_mutated_preset_text_loads_or_isone_line(key, text, tmp_path_factory):
    table, name = key
    if table in SCHEMA and name not in SCHEMA[table]:  # an optional key: add it to mutate
        base = TEXT.replace(f"[{table}]\n", f"[{table}]\n{name} = 1\n", 1)
    else:
        base = TEXT if table in SCHEMA else TEXT + f"\n[{table}]\n{name} = 1\n"
    path = tmp_path_factory.getbasetemp() / "mutated.toml"
    path.write_text(re.sub(rf"^{name}\s*=[^#\n]*", lambda m: f"{name} = {text}", base,
                           count=1, flags=re.M))
    try:
        load(path)
    except SatelliteError as exc:
        one_line(str(exc))


# --- property-based: --set / --scale and grids ----------------------------------------
_NUMBER_TEXT = st.one_of(st.floats(allow_nan=True, allow_infinity=True).map(repr),
                         st.floats(-1e6, 1e6).map(lambda v: f"{v:g}"), st.text(max_size=8))


@settings(max_examples=200, deadline=None)
@given(name=st.one_of(st.sampled_from(NAMES), st.text(max_size=6).filter(lambda s: "=" not in s)),
       value=_NUMBER_TEXT,
       option=st.sampled_from(["sets", "scales"]))
def test_any_assignment_applies_or_is_one_line_naming_the_field(name, value, option):
    text = f"{name}={value}"
    try:
        sat = apply_overrides(SAT, **{option: [text]})
    except (SatelliteError, ValueError) as exc:  # the documented error types
        line = one_line(str(exc))
        field = name.strip()  # named as typed, or escaped (repr) when unprintable
        assert field in line or repr(field) in line or "COM off the boom" in line, line
        return
    assert isinstance(sat, Satellite)


@settings(max_examples=100, deadline=None)
@given(text=st.text(max_size=30))
def test_any_set_text_applies_or_isone_line(text):
    try:
        apply_overrides(SAT, sets=[text])
    except (SatelliteError, ValueError) as exc:
        one_line(str(exc))


@settings(max_examples=150, deadline=None)
@given(name=st.sampled_from(NAMES), spec=st.one_of(
    st.text(alphabet="0123456789.:,-e+naif ", max_size=16), st.text(max_size=10)))
def test_any_grid_spec_parses_or_is_one_line_naming_the_option(name, spec):
    try:
        values = parse_grid(name, spec)
    except ValueError as exc:
        assert one_line(str(exc)).startswith(f"--{name} ")
        return
    assert values.size >= 1 and all(math.isfinite(v) for v in values)


def test_docs_list_every_plausible_range_of_the_table():
    from tethersim.model.params import PARAMETERS
    from tethersim.model.plausibility import _range_text

    doc = (Path(__file__).parents[2] / "docs" / "limits.md").read_text()
    for name, p in PARAMETERS.items():
        assert f"| `{name}` | `{p.key}` | {p.unit} | {_range_text(p)} |" in doc, name
