"""End-body inertias of the 3-D models: Satellite.inertia, I1, I2 (tethersim/model/inertia.py).

Truths: the thesis's Eq 4.4 box, I = m · 2A / 12 about every axis; a uniform
cuboid of sides x, y, z has I_x = m (y² + z²) / 12 (and cyclic), whose moments
satisfy the triangle inequality of any rigid body; a body's override replaces
that body's moments only.
"""
from __future__ import annotations

import math
import tomllib
from importlib import resources

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import tethersim
from tethersim.model import params
from tethersim.model.inertia import AXES, body_inertias, moments
from tethersim.model.inputs import parameter_vector
from tethersim.model.presets import from_dict
from tethersim.model.presets.write import dumps
from tethersim.model.registry import get_model
from tethersim.model.satellite import SatelliteError

SAT = tethersim.load_preset("satI")


def _doc(**satellite):
    doc = tomllib.loads((resources.files("tethersim.model.presets") / "satI.toml").read_text())
    doc["satellite"].update(satellite)
    return doc


def _p3d(sat) -> dict:
    """The 3-D model's inertia parameters for ``sat``, by name."""
    names = get_model("3d").parameters
    p = parameter_vector(sat, "3d")
    return {n: float(p[names.index(n)]) for n in names if n.startswith("I")}


def test_default_is_the_thesis_eq44_box_about_every_axis():
    got = _p3d(SAT)
    for k, m, area in ((1, SAT.m1, SAT.A1), (2, SAT.m2, SAT.A2)):
        for axis in AXES:
            assert got[f"I{k}_{axis}"] == m * 2 * area / 12
    assert SAT.inertia == "boxes" and SAT.I1 is None and SAT.I2 is None


def test_points_are_zero_and_an_override_replaces_its_own_body_only():
    assert set(_p3d(SAT.replace(inertia="points")).values()) == {0.0}
    over = _p3d(SAT.replace(I2=[10, 12, 3]))
    assert (over["I2_roll"], over["I2_pitch"], over["I2_yaw"]) == (10.0, 12.0, 3.0)
    assert over["I1_roll"] == SAT.m1 * 2 * SAT.A1 / 12  # body 1 keeps its box
    mixed = _p3d(SAT.replace(inertia="points", I1=(1, 1, 2)))
    assert (mixed["I1_roll"], mixed["I1_yaw"], mixed["I2_pitch"]) == (1.0, 2.0, 0.0)


def test_an_override_is_stored_as_a_tuple_and_the_satellite_stays_hashable():
    sat = SAT.replace(I1=np.array([1.0, 2.0, 3.0]))
    assert sat.I1 == (1.0, 2.0, 3.0) and isinstance(sat.I1, tuple)
    assert hash(sat) == hash(SAT.replace(I1=[1, 2, 3])) and sat == SAT.replace(I1=(1, 2, 3))


def test_defaults_are_absent_from_the_stored_dict_and_overrides_round_trip():
    assert not {"inertia", "I1", "I2"} & set(SAT.to_dict())  # old stores resume unchanged
    sat = SAT.replace(inertia="points", I2=(4, 5, 6))
    d = sat.to_dict()
    assert d["inertia"] == "points" and d["I2"] == (4.0, 5.0, 6.0)
    assert type(SAT)(**{**d, "I2": list(d["I2"])}) == sat  # as a JSON store reads it back


def test_preset_keys_and_the_writer_round_trip_the_inertias():
    sat = from_dict(_doc(inertia="points", I1=[1.5, 2.5, 3.5]), "f.toml")
    assert sat.inertia == "points" and sat.I1 == (1.5, 2.5, 3.5) and sat.I2 is None
    text = dumps(sat.replace(I2=(0.1, 0.2, 0.3)))
    assert 'inertia = "points"' in text and "I2 = [0.1, 0.2, 0.3]" in text
    assert from_dict(tomllib.loads(text), "w.toml") == sat.replace(I2=(0.1, 0.2, 0.3))
    assert "inertia" not in dumps(SAT) and "I1" not in dumps(SAT)


def test_set_takes_three_moments_none_and_the_mode():
    sat = params.apply_overrides(SAT, ["I1=1,2,3", "inertia=Points"])
    assert sat.I1 == (1.0, 2.0, 3.0) and sat.inertia == "points"
    assert params.apply_overrides(sat, ["I1=none"]).I1 is None


def test_shapes_on_the_triangle_inequality_are_rigid_bodies():
    assert moments([2, 2, 0]) == (2.0, 2.0, 0.0)  # a thin rod along the boom (yaw axis)
    assert moments([1, 2, 3]) == (1.0, 2.0, 3.0)  # a flat plate: yaw = roll + pitch
    assert moments([0, 0, 0]) == (0.0, 0.0, 0.0)  # a point
    assert moments([0.1, 0.2, 0.3]) == (0.1, 0.2, 0.3)  # decimal rounding is no violation


@settings(max_examples=100, deadline=None)
@given(m=st.floats(1e-3, 1e5), sides=st.tuples(*[st.floats(1e-3, 1e2)] * 3))
def test_every_uniform_cuboid_is_accepted_with_its_moments(m, sides):
    x, y, z = sides
    cuboid = (m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12)
    assert SAT.replace(I1=cuboid).I1 == cuboid


BAD = [
    ({"I1": [1, 2, 4]}, ["I1 = [1, 2, 4]", "yaw 4 > roll + pitch 3 kg m^2", "triangle"]),
    ({"I2": (5, 1, 1)}, ["I2 = (5, 1, 1)", "roll 5 > pitch + yaw 2 kg m^2"]),
    ({"I1": [2, 1, 0]}, ["I1 = [2, 1, 0]", "roll 2 > pitch + yaw 1"]),  # no axial moment
    ({"I1": [1, 2]}, ["I1 = [1, 2]", "3 numbers [roll, pitch, yaw] in kg m^2"]),
    ({"I1": [-1, 1, 1]}, ["I1 = [-1, 1, 1]", "each finite and >= 0"]),
    ({"I2": [1, math.nan, 1]}, ["I2 = [1, nan, 1]", "finite and >= 0"]),
    ({"I2": [1, math.inf, 1]}, ["I2 = [1, inf, 1]", "finite and >= 0"]),
    ({"I1": "1,2,3"}, ["I1 = '1,2,3'", "3 numbers"]),
    ({"I1": [True, 1, 1]}, ["I1 = [True, 1, 1]", "3 numbers"]),
    ({"I1": 5.0}, ["I1 = 5.0", "3 numbers"]),
    ({"inertia": "rods"}, ["inertia = 'rods'", "allowed values boxes, points"]),
    ({"inertia": None}, ["inertia = None", "allowed values boxes, points"]),
]


@pytest.mark.parametrize("change, expected", BAD, ids=[str(c) for c, _ in BAD])
def test_bad_inertia_is_one_line_naming_the_field(change, expected):
    with pytest.raises(SatelliteError) as exc:
        SAT.replace(**change)
    text = str(exc.value)
    assert "\n" not in text
    for part in expected:
        assert part in text, text


@pytest.mark.parametrize("key, value, expected", [
    ("I1", [1.0, 1.0, 5.0], "f.toml: satellite.I1 = [1.0, 1.0, 5.0]: yaw 5 > roll + pitch 2"),
    ("I2", "big", "f.toml: satellite.I2 = 'big': must be 3 numbers"),
    ("inertia", 3, "f.toml: satellite.inertia = 3: must be a string"),
    ("inertia", "cubes", "f.toml: satellite.inertia = 'cubes': allowed values boxes, points"),
    ("I3", [1, 1, 1], "unknown key satellite.'I3'"),
])
def test_bad_preset_inertia_names_the_file_key(key, value, expected):
    with pytest.raises(SatelliteError) as exc:
        from_dict(_doc(**{key: value}), "f.toml")
    assert expected in str(exc.value) and "\n" not in str(exc.value)


@pytest.mark.parametrize("text, expected", [
    ("I1=1,2", "--set I1=1,2: expected roll,pitch,yaw in kg m^2 (three numbers), or none"),
    ("I1=1,x,2", "--set I1=1,x,2: 'x' is not a number"),
    ("I2=1,2,nan", "--set I2=1,2,nan: 'nan' must be finite"),
    ("I1=1,1,9", "I1 = (1.0, 1.0, 9.0): yaw 9 > roll + pitch 2"),
    ("inertia=rods", "--set inertia=rods: allowed values boxes, points"),
])
def test_bad_set_inertia_is_one_line(text, expected):
    with pytest.raises(ValueError) as exc:  # SatelliteError is a ValueError
        params.apply_overrides(SAT, [text])
    assert expected in str(exc.value) and "\n" not in str(exc.value)


def test_scale_refuses_the_moments_naming_how_to_set_them():
    with pytest.raises(ValueError, match="'I1' is an option, not a number: --set I1=VALUE"):
        params.apply_overrides(SAT, scales=["I1=2"])


def test_body_inertias_is_what_the_roll_analysis_reads():
    from tethersim.analysis.roll import boom_inertias

    sat = SAT.replace(I1=(1, 2, 3), I2=(4, 5, 6))
    i = boom_inertias(sat)
    assert i["yaw"] == 3 + 6 and i["roll"] == sat.pitch_inertia + 1 + 4
    assert body_inertias(sat)["I2_pitch"] == 5.0
