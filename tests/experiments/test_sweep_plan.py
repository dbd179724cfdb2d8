"""A plan of many: any list of satellites, run in compiled blocks, in order.

The truth for a record is the block of that satellite alone (itself equal to
simulate() then outcome(): test_sweep_batch.py); a plan's records must not depend on
the other satellites of a block, on the threads, or on the order they finish in.
"""
from __future__ import annotations

import pytest

from tethersim import load_preset, simulate
from tethersim.experiments.sweep import Plan, run_plan
from tethersim.experiments.sweep.batch import run_satellites
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL

SAT = load_preset("satI")
# unrelated satellites: other presets, altitudes (other periods and air), moduli
SATS = [SAT, load_preset("satII"), SAT.replace(altitude=250e3), SAT.replace(E1=0.006),
        load_preset("dumbsat"), SAT.replace(initial=(29.0, 0.0, 1.0, 0.0, 0.0, 0.0))]
PLAN = Plan(periods=2.0)


def _bits(rec):
    return {k: repr(float(v)) for k, v in rec.items()}


@pytest.fixture(scope="module")
def alone():
    return [_bits(run_satellites(PLAN, [s])[0]) for s in SATS]


@pytest.mark.parametrize("workers", [1, 2])
def test_a_plan_s_records_equal_each_satellite_run_alone_in_order(alone, workers):
    recs = run_plan(PLAN, SATS, workers=workers, progress=False)
    assert [_bits(r) for r in recs] == alone


def test_the_end_time_is_the_run_s_last_sample():
    rec = run_plan(PLAN, [SAT], workers=1, progress=False)[0]
    res = simulate(SAT, PLAN.periods, rtol=PLAN.rtol, atol=PLAN.rtol * ATOL_PER_RTOL,
                   progress=False)
    assert rec["end_time"] == float(res.t[-1]) == pytest.approx(PLAN.periods * SAT.period,
                                                               rel=1e-12)


@pytest.mark.parametrize("field, value, words", [
    ("method", "euler", "method = 'euler': allowed values adaptive, faithful"),
    ("periods", -1.0, "periods = -1.0: must be a finite number > 0"),
    ("rtol", 1.0, "rtol = 1: allowed range"),
    ("atol", 1.0, "atol = 1.0: allowed range 1e-20 <= atol <= 0.001"),
    ("atol", 0.0, "atol = 0.0: must be a finite number > 0"),
    ("samples_per_period", 0, "samples_per_period = 0: must be an integer in 1.."),
    ("model", "nosuch", "nosuch"),
])
def test_a_plan_refuses_a_bad_field_in_one_line_naming_it(field, value, words):
    with pytest.raises(ValueError) as err:
        Plan(**{field: value})
    assert words in str(err.value) and "\n" not in str(err.value)
