"""The faithful sweep block on SIMD lanes (sweep/lanes.py) gives the scalar block's
records bit for bit.

The truth is kernel.sweep_block point by point (batch.USE_LANES off), itself checked
against simulate() + outcome() in test_sweep_batch.py.  The grid mixes points that
settle, tumble, leave the domain mid-run (a lane finishes early and takes the next
point) and start outside it (recorded at load, before any step), with more points
than lanes and each point its own step (altitude), so the lanes' refill and per-lane
steps are exercised.
"""
from __future__ import annotations

import math
from collections import Counter

import pytest

from tests.tiers import RK4_LANES
from tethersim import load_preset
from tethersim.engine.domain import reach
from tethersim.engine.integrators.lanes import lane_count
from tethersim.experiments.sweep import Plan, batch
from tethersim.experiments.sweep.point import STATUS

SAT = load_preset("satI")
pytestmark = RK4_LANES  # the RK4 lane block compiles for these tests only (tests/tiers.py)


def _sats():
    # the balloon beyond its reach (engine/domain.py): stopped before the first step
    far = SAT.replace(initial=(SAT.initial[0], 1.5 * reach(SAT), 0.5, 0.0, 0.0, 0.0),
                      allow_implausible=True)
    out = [far, far]
    for theta0 in (0.0, math.pi / 6, 3.0):
        base = SAT.replace(initial=(SAT.initial[0], SAT.initial[1], theta0, 0.0, 0.0, 0.0))
        for e1, e2 in ((0.004, 0.0427), (0.3, 0.5), (3.0, 50.0), (30.0, 0.0427)):
            for alt in (200e3, 230e3):  # m
                out.append(base.replace(E1=e1, E2=e2, altitude=alt))
        out.append(far)
    return out


def _bits(rec):
    return {k: repr(float(v)) for k, v in rec.items()}


@pytest.fixture(scope="module")
def records():
    plan = Plan(periods=3.0, method="faithful")
    sats = _sats()
    lanes = batch.run_satellites(plan, sats)
    batch.USE_LANES = False
    try:
        scalar = batch.run_satellites(plan, sats)
    finally:
        batch.USE_LANES = True
    return lanes, scalar


def test_lane_block_records_equal_the_scalar_block_bit_for_bit(records):
    lanes, scalar = records
    assert len(lanes) == len(scalar) > 2 * lane_count()
    for j, (a, b) in enumerate(zip(lanes, scalar)):
        assert _bits(a) == _bits(b), j


def test_the_lane_grid_mixes_outcomes(records):
    seen = Counter(r["status"] for r in records[0])
    assert seen[STATUS["ok"]] > 0 and seen[STATUS["left-domain"]] > 0
    assert len({r["stability_class"] for r in records[0]}) >= 3
    assert sum(r["end_time"] == 0.0 for r in records[0]) == 5  # the starts outside
