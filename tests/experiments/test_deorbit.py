"""``tethersim.experiments.deorbit``: mc's epochs, the statistics and the refusals."""
import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.deorbit import ballistic
from tethersim.experiments import deorbit as d
from tethersim.experiments.mc import MCSpec
from tethersim.experiments.mc.inputs import default_inputs, observed_days, unit_draws
from tethersim.model import atmosphere
from tethersim.model.air import orbit_mean

SAT = ts.load_preset("satI")


@pytest.fixture
def vallado_history(monkeypatch):
    first, last = orbit_mean.history_span()
    n = int((last - first).astype(int)) + 1
    table = np.tile([atmosphere.density(h) for h in orbit_mean.NODES], (n, 1))
    monkeypatch.setattr(orbit_mean, "history", lambda progress=False: table)


def test_epochs_are_mc_draws_with_the_same_seed_over_every_observed_day():
    # mc's own unit numbers for its epoch input; deorbit's band runs to the last observed
    # day (mc's stops a run's length earlier: deorbit repeats the history instead)
    spec = MCSpec(SAT, n=6, seed=11)
    u = unit_draws(spec.inputs, 6, 11)[:, 0]
    band = default_inputs(observed_days()[1])[0]
    np.testing.assert_array_equal(d.draw_epochs(6, 11), band.value(u))
    assert np.array_equal(d.draw_epochs(9, 11)[:6], d.draw_epochs(6, 11))  # a larger n keeps them


def test_fixed_air_gives_one_life_per_altitude_and_the_ballistic_ratio(vallado_history):
    r = d.deorbit(SAT, [300e3, 450e3], n=5, seed=1, progress=False)
    for row in r["rows"]:
        assert row["with_p10"][0] == pytest.approx(row["with_p90"][0], rel=1e-9)
        assert row["ratio_p50"][0] == pytest.approx(ballistic(SAT, True) / ballistic(SAT, False),
                                                    rel=1e-9)
    assert r["rows"][0]["with_p50"][0] < r["rows"][1]["with_p50"][0]
    assert r["life"]["with"].shape == (2, 5)


def test_a_host_beyond_the_cap_is_censored_and_fails_the_rules(vallado_history):
    r = d.deorbit(SAT, [800e3], n=3, seed=0, max_years=10.0, progress=False)
    row = r["rows"][0]
    assert math.isinf(row["without_p10"][0]) and row["without_25y"] == "failed"
    assert math.isnan(row["ratio_p50"][0]) or math.isinf(row["ratio_p50"][0])


@pytest.mark.parametrize("kwargs, message", [
    ({"max_years": 0.0}, r"^max_years = 0.0: must be in \(0, 1000\] years$"),
    ({"n": 0}, r"^n = 0: epochs must be a whole number 1..10000$"),
    ({"line_length": -2.0}, r"^line_length = -2.0 m: must be > 0"),
])
def test_bad_arguments_are_refused_in_one_line(kwargs, message, vallado_history):
    with pytest.raises(ValueError, match=message):
        d.deorbit(SAT, [400e3], **{"n": 2, **kwargs}, progress=False)


def test_flight_life_refuses_a_start_outside_the_law():
    with pytest.raises(ValueError, match=r"^from: 1100:1100 km must satisfy"):
        d.flight_life(1.0, 1100e3, "2017-06-23")
    with pytest.raises(ValueError, match=r"^bc = -1.0 m\^2/kg: must be > 0$"):
        d.flight_life(-1.0, 500e3, "2017-06-23")
