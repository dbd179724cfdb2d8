"""Monte Carlo inputs and specs: each input draws from its own stream, the bands and the
epoch span, one-line refusals (no runs: the stores are tested in test_montecarlo_store.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.experiments.mc import MCSpec
from tethersim.experiments.mc.inputs import observed_days, sample_satellites, unit_draws

SAT = ts.load_preset("satI")


def _spec(**kw):
    # 2 orbits (about 3 h) of settling and a free run capped at 4 h: SatI loses its
    # balloon within that, so each sample is two short runs
    return MCSpec(SAT, **{"n": 8, "seed": 11, "periods": 2.0, "max_lifetime_h": 4.0, **kw})


def test_changing_one_inputs_band_leaves_the_others_draws_unchanged():
    base = _spec()
    other = _spec(ranges=(("CD", 0.5, 0.6), ("theta0", -1.0, 1.0)))
    a = sample_satellites(SAT, base.inputs, base.units("sample"))
    b = sample_satellites(SAT, other.inputs, other.units("sample"))
    for (va, *_), (vb, *_) in zip(a, b):
        assert va["CD"] != vb["CD"] and va["theta0"] != vb["theta0"]
        assert {k: v for k, v in va.items() if k not in ("CD", "theta0")} == \
               {k: v for k, v in vb.items() if k not in ("CD", "theta0")}


def test_an_inputs_stream_does_not_depend_on_the_table_or_on_n():
    ins = _spec().inputs
    full = unit_draws(ins, 50, seed=5)
    # a table of fewer inputs in another order: each column is its own input's stream
    assert np.array_equal(unit_draws(ins[::-3], 50, seed=5), full[:, ::-3])
    assert np.array_equal(unit_draws(ins, 20, seed=5), full[:20])  # larger n keeps the first
    assert not np.array_equal(unit_draws(ins, 50, seed=6), full)


def test_samples_carry_their_drawn_values_and_the_tables_daily_air():
    spec = _spec(n=64)
    first = np.datetime64(spec.inputs[0].low)
    last = np.datetime64(spec.inputs[0].high) + np.timedelta64(1, "D")
    for vals, circ, free in sample_satellites(SAT, spec.inputs, spec.units("sample")):
        for k in ("CD", "A3", "E1", "E2", "c1", "c2"):
            assert getattr(circ, k) == getattr(free, k) == vals[k]
        lo, hi = {i.name: (i.low, i.high) for i in spec.inputs}["A3"]
        assert lo * SAT.A3 <= vals["A3"] <= hi * SAT.A3
        assert circ.initial[2] == pytest.approx(vals["theta0"])
        assert abs(vals["theta0"] - SAT.initial[2]) <= math.radians(15) + 1e-12
        assert first <= np.datetime64(vals["epoch"]) < last
        assert circ.epoch == free.epoch == vals["epoch"]
        assert circ.f107 is None and circ.atmosphere == free.atmosphere == "nrlmsise00"
        assert (circ.orbit, circ.density_mode) == ("circular", "uniform")
        assert (free.orbit, free.density_mode) == ("free", "per-body")


def test_the_epoch_span_leaves_room_for_the_longest_run_in_observed_days():
    spec = _spec(max_lifetime_h=100.0)
    last_run_day = np.datetime64(spec.inputs[0].high) + np.timedelta64(1 + 5, "D")
    assert last_run_day <= np.datetime64(observed_days()[1])


def test_bad_specs_are_refused_in_one_line():
    for kw, match in ((dict(n=0), "n = 0"), (dict(sobol=3), "power of two"),
                      (dict(max_lifetime_h=1.0), "max_lifetime_h = 1.0"),
                      (dict(ranges=(("CD", 2.0, 1.0),)), "range of CD"),
                      (dict(ranges=(("foo", 1.0, 2.0),)), "unknown input"),
                      (dict(ranges=(("CD", 1.0, 3.0),)), "range of CD = 1.0:3.0: at its high end"),
                      (dict(ranges=(("theta0", 0.0, 200.0),)), "range of theta0"),
                      (dict(ranges=(("epoch", "1950-01-01", "1960-01-01"),)), "allowed days")):
        with pytest.raises(ValueError, match=match) as e:
            _spec(**kw)
        assert "\n" not in str(e.value)
    with pytest.raises(ValueError, match="f107"):
        MCSpec(SAT.replace(f107=150.0, f107a=150.0, ap=4.0), n=2, seed=0)


def test_epoch_days_left_out_are_exactly_those_msis_refuses():
    from tethersim.experiments.mc.inputs import usable_days
    first, last = "2001-01-01", "2006-12-31"  # two radio-burst days inside
    kept = set(usable_days(first, last).astype(np.int64).astype("datetime64[s]")
               .astype("datetime64[D]"))
    every = np.arange(np.datetime64(first), np.datetime64(last) + 1)
    left_out = [d for d in every if d not in kept]
    assert 1 <= len(left_out) < 10
    for d in left_out:
        with pytest.raises(ValueError, match="f107|ap"):
            SAT.replace(atmosphere="nrlmsise00", epoch=f"{d}T12:00:00")
    for d in every[::97]:  # and a spread of kept days load
        if d in kept:
            SAT.replace(atmosphere="nrlmsise00", epoch=f"{d}T12:00:00")


def test_real_lines_deploy_from_their_own_equilibrium_as_a_whole_formation():
    """On real lines a sample starts at its own equilibrium, boom and balloon turned
    together by the θ0 offset (each line keeps its length), turning at the θ̇0 offset,
    the balloon moving off the COM at the δẋ0 offset; the samples record that start."""
    from tethersim.engine.start import equilibrium_satellite
    from tethersim.experiments.deployment import line_lengths
    from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
    sat = real_lines(SAT, STRETCHED_LENGTHS)
    spec = MCSpec(sat, n=3, seed=2, model="objective-damper", periods=3.0,
                  max_lifetime_h=10.0)
    for vals, circ, free in sample_satellites(sat, spec.inputs, spec.units("sample"),
                                              spec.model):
        eq = equilibrium_satellite(circ, "objective-damper").initial
        x, y, theta, vx, vy, rate = circ.initial
        turn = theta - eq[2]
        assert abs(turn) <= math.radians(15) + 1e-12
        assert line_lengths(circ, x, y, theta) == pytest.approx(
            line_lengths(circ, *eq[:3]), rel=1e-12)
        assert (theta, rate, vx) == (vals["theta0"], vals["theta_dot0"], vals["delta_x_dot0"])
        # the velocity: the formation's turn, ω (y, −x), plus a speed along u = (x, y) / r
        # within the δẋ0 band
        r = math.hypot(x, y)
        away = (vx - rate * y) * r / x
        assert vy == pytest.approx(-rate * x + away * y / r, rel=1e-12, abs=1e-15)
        assert abs(away) <= 0.05 + 1e-15
        assert free.initial == circ.initial


def test_real_lines_under_the_thesis_damper_are_refused_before_any_run():
    from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
    with pytest.raises(ValueError, match="turns the boom over at its equilibrium"):
        MCSpec(real_lines(SAT, STRETCHED_LENGTHS), n=2, seed=1, periods=3.0,
               max_lifetime_h=10.0)
