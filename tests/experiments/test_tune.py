"""tethersim tune: the band edges are where the steady pitch crosses ±0.05 rad; presets round-trip."""
from __future__ import annotations

import pytest

from tethersim import load_preset
from tethersim.analysis.classify import STABLE
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.experiments.sweep import SweepSpec, run_point
from tethersim.experiments.tune import EDGE_RTOL, stable_band_E2
from tethersim.model.params import from_si
from tethersim.model.presets import load
from tethersim.model.presets.write import dumps

PERIODS = 10.0  # short runs: the pitch trim is set by the moduli, not the run length


def theta_ss(sat, E2):
    spec = SweepSpec(sat, (("E2", [from_si("E2", E2)]),), periods=PERIODS)
    return run_point(spec, 0)


def test_band_edges_are_where_the_steady_pitch_leaves_the_band():
    sat = load_preset("satI")
    lo, hi, runs = stable_band_E2(sat, periods=PERIODS)
    assert lo < sat.E2 * 1.02 and hi > sat.E2 * 0.98
    d = 3 * EDGE_RTOL * hi
    for inside, outside in ((lo + d, lo - d), (hi - d, hi + d)):
        assert abs(theta_ss(sat, inside)["steady_state_pitch"]) <= SETTLING_TOL
        assert abs(theta_ss(sat, outside)["steady_state_pitch"]) > SETTLING_TOL
    centre = theta_ss(sat, 0.5 * (lo + hi))
    assert abs(centre["steady_state_pitch"]) < SETTLING_TOL


def test_written_preset_loads_back_to_the_same_satellite(tmp_path):
    sat = load_preset("satII").replace(E2=0.0471234, c1=1.5e-3)
    path = tmp_path / "t.toml"
    path.write_text(dumps(sat, {"E2": "tuned"}, header="test"))
    back = load(path)
    for f in ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b", "l10", "l20", "E1", "E2", "c1",
              "c2", "altitude", "CD"):
        assert getattr(back, f) == pytest.approx(getattr(sat, f), rel=1e-14), f
    assert (back.name, back.density_mode) == (sat.name, sat.density_mode)
    assert back.initial == pytest.approx(sat.initial, rel=1e-14)
    assert "# tuned" in path.read_text()


def test_tuned_satellite_is_centred_in_its_band_at_its_final_damping():
    """The damper's torque at rest shifts the trim: the final E2 must be centred *with* it."""
    from tethersim.experiments.tune import tune
    r = tune(load_preset("satI"), periods=PERIODS)
    lo, hi = r.band
    assert lo < r.satellite.E2 < hi
    assert r.satellite.E2 == pytest.approx(0.5 * (lo + hi))
    final = theta_ss(r.satellite, r.satellite.E2)
    assert final["stability_class"] == STABLE
    assert abs(final["steady_state_pitch"]) < 0.5 * SETTLING_TOL
    # the edges of the band found at the final damping are where the trim leaves ±tol
    d = 3 * EDGE_RTOL * hi
    assert abs(theta_ss(r.satellite, lo - d)["steady_state_pitch"]) > SETTLING_TOL
    assert abs(theta_ss(r.satellite, hi + d)["steady_state_pitch"]) > SETTLING_TOL
