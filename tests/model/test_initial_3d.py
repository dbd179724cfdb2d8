"""The out-of-plane start of the 3-D models: Satellite.initial_3d, preset keys, --set."""
from __future__ import annotations

import math
import tomllib
from importlib import resources

import numpy as np
import pytest

import tethersim
from tethersim.model import params
from tethersim.model.inputs import initial_model_state
from tethersim.model.presets import from_dict
from tethersim.model.presets.write import dumps
from tethersim.model.satellite import SatelliteError


def _doc(**initial):
    text = (resources.files("tethersim.model.presets") / "satI.toml").read_text()
    doc = tomllib.loads(text)
    doc["initial"].update(initial)
    return doc


def test_preset_keys_set_the_3d_initial_state_in_si():
    sat = from_dict(_doc(phi0_deg=5.0, psi0_deg=-4.0, delta_z=1.0, phi_dot=1e-4), "f.toml")
    y = dict(zip(tethersim.model.registry.get_model("3d").state, initial_model_state(sat, "3d")))
    assert y["phi"] == math.radians(5.0) and y["psi"] == math.radians(-4.0)
    assert y["delta_z"] == 1.0 and y["phi_dot"] == 1e-4 and y["psi_dot"] == 0.0
    assert y["theta"] == math.radians(30.0)


def test_planar_models_ignore_the_out_of_plane_start():
    sat = from_dict(_doc(phi0_deg=5.0), "f.toml")
    np.testing.assert_array_equal(initial_model_state(sat, "derived"),
                                  initial_model_state(tethersim.load_preset("satI"), "derived"))


@pytest.mark.parametrize("key, value, message", [
    ("phi0_deg", 90.0, "initial.phi0_deg = 90 deg: allowed range -80 to 80 deg"),
    ("phi0_deg", -80.5, "initial.phi0_deg = -80.5 deg: allowed range -80 to 80 deg"),
    ("psi0_deg", 200.0, "initial.psi0_deg = 200 deg: allowed range -180 to 180 deg"),
    ("delta_z", "1", "initial.delta_z = '1': must be a number in m"),
    ("roll0_deg", 1.0, "unknown key initial.'roll0_deg'"),
])
def test_bad_3d_start_is_a_one_line_error_naming_the_key(key, value, message):
    with pytest.raises(SatelliteError, match=None) as exc:
        from_dict(_doc(**{key: value}), "f.toml")
    assert message in str(exc.value) and "\n" not in str(exc.value)


def test_a_start_on_the_roll_limit_is_allowed():
    from tethersim.model.satellite import ROLL_LIMIT_DEG

    sat = from_dict(_doc(phi0_deg=-ROLL_LIMIT_DEG), "f.toml")
    assert sat.initial_3d["phi"] == -math.radians(ROLL_LIMIT_DEG)


def test_satellite_rejects_unknown_or_non_finite_3d_start():
    sat = tethersim.load_preset("satI")
    with pytest.raises(SatelliteError, match="initial_3d\\['roll'\\]: unknown"):
        sat.replace(initial_3d={"roll": 0.1})
    with pytest.raises(SatelliteError, match="must be a finite number"):
        sat.replace(initial_3d={"phi": math.nan})


def test_set_option_and_writer_round_trip_the_3d_start():
    sat = params.apply_overrides(tethersim.load_preset("satI"), ["phi0_deg=5", "delta_z=1"])
    assert sat.initial_3d == {"phi": math.radians(5), "delta_z": 1.0}
    assert params.edge_value(sat, "phi0_deg") == pytest.approx(5.0, rel=1e-15)
    back = from_dict(tomllib.loads(dumps(sat)), "w.toml")
    assert back.initial_3d == pytest.approx(sat.initial_3d, rel=1e-14)
    assert hash(back) == hash(back.replace())  # still hashable (initial_3d not hashed)
