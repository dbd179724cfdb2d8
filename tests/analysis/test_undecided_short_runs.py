"""A class needs a run long enough to decide it (issue 19): shorter runs are "undecided",
on the numpy path (outcome) and the compiled sweep blocks alike; a tumble is a fact at any
length.  Definitions: docs/metrics.md, "How long a run must be"."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tests.tiers import RK4_LANES
from tethersim.analysis.classify import (
    CLASSES,
    FAILED,
    OFFSET,
    STABLE,
    TUMBLING,
    UNDECIDED,
    UPSIDE_DOWN,
    classify,
    flag_attrs,
)
from tethersim.analysis.metrics import SS_FRACTION, PitchMetrics, long_enough, min_run_orbits

SAT = ts.load_preset("satI")


def _m(ss=0.0, settle=3600.0, tumbled=False, upside=False):
    return PitchMetrics(mean_pitch=ss, steady_state_pitch=ss, settling_time=settle,
                        tumbled=tumbled, upside_down=upside)


def test_the_minimum_puts_one_pitch_libration_in_the_steady_state_window():
    # closed form: the gravity-gradient pitch librates at sqrt(3) x the orbital rate
    libration_s = 2 * math.pi / (math.sqrt(3) * SAT.omega)
    window_s = SS_FRACTION * min_run_orbits() * SAT.period
    assert window_s == pytest.approx(libration_s, rel=1e-12)
    assert long_enough(min_run_orbits()) and not long_enough(math.nextafter(min_run_orbits(), 0))


def test_undecided_is_appended_so_stored_codes_keep_their_numbers():
    assert CLASSES[:6] == ("stable", "unsettled", "offset", "upside_down", "tumbling", "failed")
    assert CLASSES[UNDECIDED] == "undecided" and UNDECIDED == len(CLASSES) - 1
    assert flag_attrs()["flag_meanings"].split()[UNDECIDED] == "undecided"


@pytest.mark.parametrize("metrics, long_class", [
    (_m(), STABLE), (_m(ss=0.3), OFFSET), (_m(ss=3.1, upside=True), UPSIDE_DOWN)])
def test_a_short_run_that_did_not_tumble_is_undecided_whatever_its_metrics(metrics, long_class):
    short = 0.999 * min_run_orbits()
    assert classify(metrics, run_orbits=short) == UNDECIDED
    assert classify(metrics, run_orbits=min_run_orbits()) == long_class


def test_a_tumble_is_decided_at_any_length_and_a_failure_stays_failed():
    tumbled = _m(ss=3.1, upside=True, tumbled=True)
    assert classify(tumbled, run_orbits=0.01) == TUMBLING  # whether it ends inverted: unknown
    assert classify(tumbled, run_orbits=10) == UPSIDE_DOWN
    assert classify(None, run_orbits=0.01) == FAILED


def test_a_tenth_of_an_orbit_is_undecided_not_offset():
    """Issue 19: `run satI --periods 0.1` said "offset" while θ had barely moved."""
    out = ts.outcome(ts.simulate(SAT, periods=0.1, progress=False), forces=False)
    assert out.counts and out.class_name == "undecided"
    long = ts.outcome(ts.simulate(SAT, periods=min_run_orbits(), progress=False), forces=False)
    assert long.class_name != "undecided"


def test_the_run_summary_says_how_long_to_run():
    from tethersim.analysis.summary import run_summary
    s = run_summary(ts.simulate(SAT, periods=0.1, progress=False))
    assert s["class"] == "undecided"
    assert s["run at least [orbits] to decide the class"] == min_run_orbits()


@pytest.mark.parametrize("method", ["adaptive", pytest.param("faithful", marks=RK4_LANES)])
def test_sweep_blocks_and_single_runs_draw_the_same_line(method):
    from tethersim.experiments.sweep import SweepSpec
    from tethersim.experiments.sweep.batch import run_block
    from tethersim.experiments.sweep.point import run_point
    seen = set()
    for periods, decided in ((0.97 * min_run_orbits(), False), (min_run_orbits(), True)):
        spec = SweepSpec(SAT, (("E2", [0.0427, 0.045]),), periods=periods, method=method)
        for k, rec in run_block(spec, [0, 1]):
            assert rec["stability_class"] == run_point(spec, k)["stability_class"]
            # a short run that tumbled is "tumbling": a fact at any length
            assert (rec["stability_class"] == UNDECIDED) == (not decided and not rec["tumbled"])
            seen.add(rec["stability_class"])
    assert UNDECIDED in seen and len(seen) > 1


def test_a_prediction_for_a_run_too_short_to_decide_is_undecided_too():
    from tethersim.analysis.predict import predicted_class
    short = 0.99 * min_run_orbits()
    assert predicted_class(SAT, periods=short)[0] == UNDECIDED
    assert predicted_class(SAT, periods=50)[0] != UNDECIDED
    # nothing predicted at all stays "failed" at any length
    assert predicted_class(SAT.replace(E1=0.0, E2=0.0), periods=short)[0] == FAILED
