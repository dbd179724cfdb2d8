"""The compiled drag make-up equals its numpy definition, and a plan's records carry it.

The truth is orbit_life.along_track_drag: numpy, each body's drag from body_states and,
in per-body air, each body's density at its own longitude; the kernel takes the
densities where the dynamics take them (every body at the reference point's longitude:
the bodies sit within ~100 m of it, 1.5e-5 rad, 0.2 s of local time, engine/dynamics.py),
so NRLMSISE-00 air agrees to that (its day-night swing, a factor of about 2 in 12 h,
moves a density by ~1e-5 in 0.2 s at most; 4e-8 measured), Vallado's (no longitude)
and uniform air to rounding.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.orbit_life import along_track_drag, drag_makeup
from tethersim.experiments.sweep import Plan, run_plan

SAT = ts.load_preset("satI")
MSIS = dict(density_mode="per-body", atmosphere="nrlmsise00", f107=150.0, f107a=150.0, ap=4.0)


def _numpy_makeup(res) -> float:
    f = along_track_drag(res)
    ok = np.isfinite(f)
    t, f = res.t[ok], f[ok]
    return float(np.trapezoid(f, t) / (t[-1] - t[0])) / (SAT.m1 + SAT.m2 + SAT.m3) * 86400


@pytest.mark.parametrize(("air", "rel"), [({}, 1e-13), (dict(density_mode="per-body"), 1e-13),
                                          (MSIS, 1e-6)])
def test_the_kernel_equals_the_numpy_trapezoid_of_the_along_track_drag(air, rel):
    res = ts.simulate(SAT.replace(**air), periods=0.3, progress=False)
    assert drag_makeup(res) == pytest.approx(_numpy_makeup(res), rel=rel)


def test_non_finite_samples_are_skipped_as_numpy_masks_them():
    res = ts.simulate(SAT, periods=0.3, progress=False)
    states = res.states.copy()
    states[[3, 10, 11], 0] = np.nan  # δx of three samples
    cut = replace(res, states=states)
    assert drag_makeup(cut) == pytest.approx(_numpy_makeup(cut), rel=1e-13)
    assert drag_makeup(cut) != drag_makeup(res)
    states[1:, :] = np.nan  # one finite sample left: no mean
    assert math.isnan(drag_makeup(replace(res, states=states)))


def test_a_plans_record_carries_outcomes_drag_makeup():
    sats = [SAT, SAT.replace(A3=SAT.A3 * 2)]
    recs = run_plan(Plan(periods=0.3), sats, workers=1, progress=False)
    outs = [ts.outcome(ts.simulate(s, periods=0.3, rtol=1e-9, atol=1e-11, samples=30,
                                   progress=False)) for s in sats]
    assert [r["drag_makeup"] for r in recs] == [o.drag_makeup for o in outs]
    assert 1.9 < recs[1]["drag_makeup"] / recs[0]["drag_makeup"] < 2.0  # the balloon dominates
    # a free orbit's record is NaN, as its outcome: tests/experiments/test_sweep_batch.py's
    # free-orbit block (slow tier: it compiles that block)
