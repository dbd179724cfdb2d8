"""The adaptive (DOP853) sweep block on SIMD lanes (sweep/lanes853.py) gives the scalar
block's records bit for bit.

The truth is kernel.sweep_block point by point (batch.USE_LANES off), itself checked
against simulate() + outcome() in test_sweep_batch.py.  The points go slack and taut
(switches located per lane by the scalar code), reject steps, stop on a limit mid-run
(a tether stretch: the lane finishes early and takes the next point) and start outside
the domain (recorded at load, before any step); one block has more points than lanes,
one fewer, and each point its own orbit (altitude), so per-lane step sizes, refills
and idle lanes are exercised.  The lane block's compile takes about a minute: the
fast tier keeps one small block.
"""
from __future__ import annotations

import math
from collections import Counter

import pytest

from tethersim import load_preset, simulate
from tethersim.engine.domain import reach
from tethersim.engine.integrators.lanes import lane_count
from tethersim.experiments.sweep import Plan, batch
from tethersim.experiments.sweep.point import STATUS

SAT = load_preset("satI")
# the balloon beyond its reach (engine/domain.py): stopped before the first step
FAR = SAT.replace(initial=(SAT.initial[0], 1.5 * reach(SAT), 0.5, 0.0, 0.0, 0.0),
                  allow_implausible=True)


def _kicked(v, i):
    """SatI with state rate i (δẋ 3, δẏ 4) set to v [m/s]: the tether stretches past its
    limit within the first minute at 10 m/s."""
    init = list(SAT.initial)
    init[i] = v
    return SAT.replace(initial=tuple(init), allow_implausible=True)


def _bits(rec):
    return {k: repr(float(v)) for k, v in rec.items()}


def _both(sats, periods):
    plan = Plan(periods=periods)
    lanes = batch.run_satellites(plan, sats)
    batch.USE_LANES = False
    try:
        scalar = batch.run_satellites(plan, sats)
    finally:
        batch.USE_LANES = True
    return lanes, scalar


def test_a_block_smaller_than_the_lanes_equals_the_scalar_block_bit_for_bit():
    slack = SAT.replace(E1=0.3, E2=0.5)  # soft tethers: they go slack and taut again
    sats = [slack, FAR, _kicked(10.0, 3)]
    assert len(sats) < lane_count()
    assert simulate(slack, 0.5, progress=False).n_switches > 0
    lanes, scalar = _both(sats, 0.5)
    for j, (a, b) in enumerate(zip(lanes, scalar)):
        assert _bits(a) == _bits(b), j
    assert [r["status"] for r in lanes] == [STATUS["ok"]] + 2 * [STATUS["left-domain"]]
    assert 0.0 < lanes[2]["end_time"] < 60.0  # the stretch stops the run mid-way


def _grid():
    out = [FAR, _kicked(10.0, 3), _kicked(10.0, 4)]
    for theta0 in (0.0, math.pi / 6, 3.0):
        base = SAT.replace(initial=(SAT.initial[0], SAT.initial[1], theta0, 0.0, 0.0, 0.0))
        for e1, e2 in ((0.004, 0.0427), (0.3, 0.5), (30.0, 0.0427)):
            for alt in (200e3, 230e3):  # m
                out.append(base.replace(E1=e1, E2=e2, altitude=alt))
        out.append(FAR)
    return out


@pytest.fixture(scope="module")
def records():
    return _both(_grid(), 2.0)


@pytest.mark.slow
def test_lane_block_records_equal_the_scalar_block_bit_for_bit(records):
    lanes, scalar = records
    assert len(lanes) == len(scalar) > 2 * lane_count()
    for j, (a, b) in enumerate(zip(lanes, scalar)):
        assert _bits(a) == _bits(b), j


@pytest.mark.slow
def test_the_lane_grid_mixes_outcomes(records):
    seen = Counter(r["status"] for r in records[0])
    assert seen[STATUS["ok"]] > 0 and seen[STATUS["left-domain"]] > 0
    assert len({r["stability_class"] for r in records[0]}) >= 2
    assert sum(r["end_time"] == 0.0 for r in records[0]) == 4  # the starts outside
    assert sum(0.0 < r["end_time"] < 60.0 for r in records[0]) == 2  # the stretches
