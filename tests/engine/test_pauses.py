"""Where a run pauses (for Ctrl-C and the progress bar) changes nothing in its result.

The compiled loops see Ctrl-C only between calls, so a run pauses every ~0.2 s of wall
time (DOP853) or every RK4_PAUSE_STEPS steps (RK4), whatever its length (issue 19: a
50,000-orbit run paused every 500 orbits).  The truth: the same run in one call.
"""
from __future__ import annotations

import numpy as np
import pytest

import tethersim.engine.guards as guards
import tethersim.engine.simulate as sim
from tethersim import load_preset, simulate

SAT = load_preset("satI")


def _same(a, b):
    assert np.array_equal(a.t, b.t) and np.array_equal(a.states, b.states)
    assert (a.nfev, a.n_accepted, a.n_rejected, a.n_switches) == (
        b.nfev, b.n_accepted, b.n_rejected, b.n_switches)
    assert a.status == b.status == "ok"



@pytest.mark.parametrize("kw", [dict(periods=2), dict(periods=1, rtol=1e-8, samples=37)])
def test_a_dop853_run_paused_hundreds_of_times_is_bit_identical_to_one_call(kw, monkeypatch):
    calls = []
    real = sim.specialised

    def counting(*args, **kwargs):
        loop = real(*args, **kwargs)
        return lambda *a: calls.append(a[-1]) or loop(*a)
    monkeypatch.setattr(sim, "specialised", counting)
    monkeypatch.setattr(sim, "PAUSE_S", 1e-6)  # pause after nearly every step
    monkeypatch.setattr(sim, "QUICK_RUN_S", 0.0)
    paused = simulate(SAT, check=False, progress=False, **kw)
    assert len(calls) > 100
    monkeypatch.setattr(sim, "PAUSE_S", 1e9)
    monkeypatch.setattr(sim, "CHUNKS", 1)
    calls.clear()
    whole = simulate(SAT, check=False, progress=False, **kw)
    # CHUNKS = 1 and the first call's span of one orbit: at most two calls
    assert len(calls) <= 2
    _same(paused, whole)


def test_an_rk4_run_pauses_by_steps_and_its_result_does_not_depend_on_the_bar(monkeypatch):
    quiet = simulate(SAT, periods=1, steps=300, method="rk4", check=False, progress=False)
    shown = simulate(SAT, periods=1, steps=300, method="rk4", check=False, progress=True)
    _same(quiet, shown)


def test_the_step_budget_is_the_runs_not_each_calls(monkeypatch):
    monkeypatch.setattr(sim, "PAUSE_S", 1e-6)
    monkeypatch.setattr(sim, "QUICK_RUN_S", 0.0)
    monkeypatch.setattr(guards, "MAX_STEPS_PER_PERIOD", 50)  # a 2-orbit run needs ~1500 steps
    res = simulate(SAT, periods=2, check=False, progress=False)
    assert res.status == "failed" and "too many steps" in res.message
