"""Compiled blocks of sweep points give the per-point path's records, bit for bit.

The truth is point.run_point: simulate() then outcome() in Python, one point at
a time.  The grids below reach every stability class and both failure statuses
that occur (a diverging RK4 step leaves the domain first), for the adaptive
and the faithful method.
"""
from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest

from tests.tiers import RK4_LANES
from tethersim import load_preset
from tethersim.analysis.classify import CLASSES
from tethersim.experiments.sweep import SweepSpec, run_point
from tethersim.experiments.sweep.batch import run_block
from tethersim.experiments.sweep.point import STATUS

SAT = load_preset("satI")
GRIDS = {
    "faithful": (("E1", [0.004, 0.3, 3.0, 30.0]), ("E2", [0.0427, 0.5, 50.0])),
    "adaptive": (("E1", [0.002, 0.004, 0.006]), ("E2", [0.02, 0.0427, 0.06])),
    "damping": (("c1", [0.0, 0.01, 1.0]), ("c2", [0.0, 0.01, 1.0])),
}


def _bits(rec):
    """A record as exact text: repr of each value (NaN equal to NaN, -0.0 not 0.0)."""
    return {k: repr(float(v)) for k, v in rec.items()}


def _specs(methods=("faithful", "adaptive")):
    for theta0 in (0.0, math.pi / 6, 3.0):  # upright, the preset's start, nearly inverted
        base = SAT.replace(initial=(SAT.initial[0], SAT.initial[1], theta0, 0.0, 0.0, 0.0))
        for name, axes in GRIDS.items():
            method = "faithful" if name == "faithful" else "adaptive"
            if method not in methods:
                continue
            # 3 orbits: long enough to decide a class (metrics.long_enough)
            yield SweepSpec(base, axes, periods=3.0, method=method)
    if "adaptive" in methods:  # and one too short to decide: undecided points, equal too
        yield SweepSpec(SAT, GRIDS["adaptive"], periods=1.0)


def _blocks(methods):
    return [(spec, run_block(spec, list(range(spec.size)))) for spec in _specs(methods)]


# the faithful blocks run on the RK4 lanes, compiled for them alone: slow tier (tests/tiers.py)
@pytest.fixture(scope="module", params=["adaptive", pytest.param("faithful", marks=RK4_LANES)])
def blocks(request):
    return _blocks((request.param,))


def test_block_records_equal_the_per_point_records_bit_for_bit(blocks):
    for spec, recs in blocks:
        assert [k for k, _ in recs] == list(range(spec.size))
        for k, rec in recs:
            assert _bits(rec) == _bits(run_point(spec, k)), (spec.method, spec.values_at(k))


@RK4_LANES
def test_the_grids_reach_every_class_and_failure():
    seen = Counter((rec["stability_class"], rec["status"]) for _, recs in _blocks(("faithful",
                   "adaptive")) for _, rec in recs)
    assert {c for c, _ in seen} == set(range(len(CLASSES)))
    # left the domain (an unstable RK4 step), stored as the engine's status
    assert (CLASSES.index("failed"), STATUS["left-domain"]) in seen


def test_a_record_does_not_depend_on_its_block(blocks):
    spec, recs = blocks[0]
    ks = list(range(spec.size))
    rng = np.random.default_rng(3)
    for size in (1, 2, 5):
        order = rng.permutation(ks).tolist()
        for start in range(0, len(order), size):
            part = order[start:start + size]
            assert [_bits(r) for _, r in run_block(spec, part)] == \
                [_bits(recs[k][1]) for k in part]


@pytest.mark.parametrize("air", [dict(density_mode="per-body"),
                                 dict(density_mode="per-body", atmosphere="nrlmsise00")])
def test_per_body_air_runs_in_the_block_with_the_per_point_records(monkeypatch, air):
    """Each body's own density (Vallado's table or NRLMSISE-00): no fallback to simulate()."""
    from tethersim.experiments.sweep import point
    base = SAT.replace(**air)
    spec = SweepSpec(base, (("E2", [0.04, 0.0427]), ("altitude", [200.0, 210.0])), periods=0.5)
    with monkeypatch.context() as m:
        m.setattr(point, "simulate", lambda *a, **k: pytest.fail("a point ran simulate()"))
        recs = run_block(spec, [3, 0, 1, 2])
    assert [_bits(r) for _, r in recs] == [_bits(run_point(spec, k)) for k in (3, 0, 1, 2)]


@pytest.mark.slow  # compiles the free-orbit block
@pytest.mark.parametrize("method", ["adaptive", "faithful"])
def test_a_free_orbit_runs_in_the_block_with_its_re_entry(method):
    """A free orbit (its free twin model, per-body air), one point re-entering (the
    re-entry altitude 1 km under the start): the block gives the per-point records."""
    free = SAT.replace(orbit="free")
    spec = SweepSpec(free, (("reentry_altitude", [120.0, 199.0]),), periods=1.0, method=method)
    recs = run_block(spec, [0, 1])
    assert [_bits(r) for _, r in recs] == [_bits(run_point(spec, k)) for k in (0, 1)]
    assert recs[1][1]["status"] == STATUS["re-entered"]


@pytest.mark.parametrize("method", ["adaptive", "faithful"])
def test_a_block_refuses_an_output_too_large_as_a_point_does(monkeypatch, method):
    from tethersim.engine.guards import SizeLimitError
    spec = SweepSpec(SAT, (("E2", [0.0427]),), periods=2.0, method=method)
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", "1000")
    for run in (lambda: run_point(spec, 0), lambda: run_block(spec, [0])):
        with pytest.raises(SizeLimitError, match="TETHERSIM_MAX_OUTPUT_BYTES"):
            run()


@pytest.mark.slow
@pytest.mark.parametrize("method", ["adaptive", "faithful"])
def test_a_3d_model_runs_in_the_block_with_its_roll_limit(method):
    """The 3-D models' roll limit is an event of the loops (engine/events.py), so their
    points run in the block; a block of them, one point rolling past 80°, gives the
    per-point records."""
    for base in (SAT, SAT.replace(initial_3d={"phi_dot": 10 * SAT.omega})):
        spec = SweepSpec(base, (("E2", [0.0427, 0.06]),), periods=0.5, model="3d",
                         method=method)
        recs = run_block(spec, [0, 1])
        assert [_bits(r) for _, r in recs] == [_bits(run_point(spec, k)) for k in (0, 1)]
    assert {r["status"] for _, r in recs} == {STATUS["left-domain"]}


def test_the_block_kernel_releases_the_gil():
    from tethersim.experiments.sweep.kernel import sweep_block
    assert sweep_block.targetoptions["nogil"]
