"""A plan of many's end_time of a run stopped by an event is simulate()'s located time."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL, Plan
from tethersim.experiments.sweep.runner import run_plan


@pytest.mark.slow  # compiles the free-orbit block
@pytest.mark.parametrize("hours", [3.0, 4.0])
def test_end_time_of_a_stopped_free_run_is_the_located_event_time(hours):
    sat = ts.load_preset("satI").replace(orbit="free")  # loses its balloon within 3 h
    plan = Plan(periods=hours * 3600 / sat.period)
    rec = run_plan(plan, [sat], workers=1, progress=False)[0]
    res = ts.simulate(sat, plan.periods, method="adaptive", rtol=plan.rtol,
                      atol=plan.rtol * ATOL_PER_RTOL, samples=round(100 * plan.periods),
                      check=False, progress=False)
    assert res.status == "left-domain" and res.event_time < hours * 3600
    # before, the block kernel gave the last grid sample before the event (up to one
    # output step early)
    assert rec["end_time"] == res.event_time == float(res.t[-1])
