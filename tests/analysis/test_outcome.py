"""The one outcome of a run (tethersim.analysis.outcome): one rule, independent of sampling."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.classify import CLASSES, FAILED


@pytest.fixture(scope="module")
def sat():
    return ts.load_preset("satI")


def test_metrics_do_not_depend_on_the_output_sampling(sat):
    dense = ts.simulate(sat, periods=5, samples=1000, progress=False)
    coarse = ts.simulate(sat, periods=5, samples=10, progress=False)
    assert coarse.t.size == 11 and coarse.fine_t is not None
    # the coarse output is exactly every 100th sample of the metrics grid ...
    np.testing.assert_array_equal(coarse.states, coarse.fine_states[::100])
    np.testing.assert_array_equal(coarse.fine_t[::100], np.linspace(0, coarse.t[-1], 11))
    # ... and the metrics are those of the dense run (the two grids' sample times agree
    # to rounding, so the metrics to ~1e-15 relative)
    a, b = ts.outcome(coarse).metrics, ts.outcome(dense).metrics
    assert (a.tumbled, a.upside_down) == (b.tumbled, b.upside_down)
    for name in ("mean_pitch", "steady_state_pitch", "settling_time"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-12, nan_ok=True), name


def test_outcome_of_a_finished_run_counts(sat):
    out = ts.outcome(ts.simulate(sat, periods=1, progress=False))
    # one orbit is too short to decide a class (docs/metrics.md): it counts, undecided
    assert out.counts and out.status == "ok" and out.class_name != CLASSES[FAILED]
    assert abs(out.trail_delta_x - 28.9) < 0.2  # the SatI trail (README)


def test_a_diverged_run_is_failed_with_its_reason_and_finite_metrics(sat):
    with pytest.warns(ts.RK4StepWarning):
        res = ts.simulate(sat.replace(E1=5 * sat.E1, E2=5 * sat.E2), periods=2, steps=60,
                          method="rk4", progress=False)
    assert res.status != "ok"
    out = ts.outcome(res)
    assert not out.counts and out.class_name == "failed" and out.reason
    assert out.metrics is None or math.isfinite(out.metrics.mean_pitch)


def test_an_interrupted_run_follows_the_same_rule(sat):
    from dataclasses import replace
    res = ts.simulate(sat, periods=1, progress=False)
    cut = replace(res, t=res.t[:50], states=res.states[:50], status="interrupted",
                  message="interrupted at t = 1300 s")
    out = ts.outcome(cut)
    assert out.class_name == "failed" and out.reason == "interrupted at t = 1300 s"
