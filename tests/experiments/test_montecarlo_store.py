"""Monte Carlo stores: the same seed gives the same bytes at 1 and 2 threads, after an
interruption and on a LocalCluster; a sample's row is its own runs' outcome.

The slow tier: every sample runs the free-orbit block (a ~40 s compile on a cold cache;
about 15 s for the file once compiled)."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.experiments.mc import MCInterrupted, MCSpec, run_mc
from tethersim.experiments.mc.inputs import sample_satellites
from tethersim.experiments.mc.run import ROWS_FILE
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL

pytestmark = pytest.mark.slow
SAT = ts.load_preset("satI")


def _spec(**kw):
    # 2 orbits (about 3 h) of settling and a free run capped at 4 h: SatI loses its
    # balloon within that, so each sample is two short runs
    return MCSpec(SAT, **{"n": 8, "seed": 11, "periods": 2.0, "max_lifetime_h": 4.0, **kw})


@pytest.fixture(scope="module")
def threaded(tmp_path_factory):
    out = tmp_path_factory.mktemp("mc1")
    rows = run_mc(_spec(), out, workers=1, progress=False)
    return out, rows


def test_same_seed_gives_identical_store_at_1_and_2_threads(threaded, tmp_path):
    out1, rows = threaded
    run_mc(_spec(), tmp_path, workers=2, progress=False)
    assert (tmp_path / ROWS_FILE).read_bytes() == (out1 / ROWS_FILE).read_bytes()
    assert [r["i"] for r in rows] == list(range(8))


def test_interrupted_then_resumed_store_is_identical(threaded, tmp_path):
    out1, _ = threaded
    with pytest.raises(MCInterrupted, match="resumes"):
        run_mc(_spec(), tmp_path, workers=2, progress=False, stop_after=3)
    kept = (tmp_path / ROWS_FILE).read_text().splitlines()
    assert 3 <= len(kept) < 8
    run_mc(_spec(), tmp_path, workers=1, progress=False)
    assert (tmp_path / ROWS_FILE).read_bytes() == (out1 / ROWS_FILE).read_bytes()


def test_a_cut_line_reruns_its_sample(threaded, tmp_path):
    out1, _ = threaded
    lines = (out1 / ROWS_FILE).read_text().splitlines(keepends=True)
    (tmp_path / "spec.json").write_text((out1 / "spec.json").read_text())
    (tmp_path / ROWS_FILE).write_text("".join(lines[:4]) + lines[4][:30])
    run_mc(_spec(), tmp_path, workers=1, progress=False)
    assert (tmp_path / ROWS_FILE).read_bytes() == (out1 / ROWS_FILE).read_bytes()


def test_another_spec_in_the_same_folder_is_refused(threaded):
    out1, _ = threaded
    with pytest.raises(ValueError, match="other settings"):
        run_mc(_spec(seed=12), out1, workers=1, progress=False)


def test_a_rows_outcomes_are_those_of_its_own_runs(threaded):
    _, rows = threaded
    spec = _spec()
    (vals, circ, free), = sample_satellites(SAT, spec.inputs, spec.units("sample")[[2]])
    # simulate() as a sweep point's definition calls it (sweep/point.py run_point)
    kw = dict(method="adaptive", model=spec.model, rtol=spec.rtol,
              atol=spec.rtol * ATOL_PER_RTOL, check=False, progress=False)
    periods = spec.free_plans[0].periods
    f = ts.simulate(free, periods, samples=round(100 * periods), **kw)
    row = rows[2]
    assert row["free_status"] == f.status != "ok"  # SatI loses its balloon within 4 h
    assert row["lifetime_s"] == float(f.event_time) == float(f.t[-1])  # the located time
    c = ts.outcome(ts.simulate(circ, spec.periods, samples=round(100 * spec.periods), **kw))
    assert row["class"] == c.class_name
    assert row["tumbled"] == bool(c.metrics.tumbled)


def test_local_dask_cluster_gives_the_same_store_as_threads(threaded, tmp_path):
    pytest.importorskip("distributed")
    out1, _ = threaded
    run_mc(_spec(), tmp_path, dask_workers=2, progress=False)
    assert (tmp_path / ROWS_FILE).read_bytes() == (out1 / ROWS_FILE).read_bytes()




def test_a_life_past_the_first_stage_is_that_of_one_run_to_the_cap(tmp_path):
    # at 260 km SatI keeps its balloon for hours: lives end in the second stage or capped
    spec = MCSpec(SAT.replace(altitude=260e3), n=4, seed=2, periods=2.0, max_lifetime_h=12.0)
    assert len(spec.free_plans) == 2
    rows = run_mc(spec, tmp_path, workers=2, progress=False)
    late = [r for r in rows if r["lifetime_s"] > spec.free_plans[0].periods * SAT.period]
    assert late
    for r in late[:2]:
        (_, _, free), = sample_satellites(spec.satellite, spec.inputs,
                                          spec.units("sample")[[r["i"]]])
        periods = spec.free_plans[-1].periods
        res = ts.simulate(free, periods, method="adaptive", model=spec.model, rtol=spec.rtol,
                          atol=spec.rtol * ATOL_PER_RTOL, samples=round(100 * periods),
                          check=False, progress=False)
        assert r["free_status"] == res.status
        assert r["lifetime_s"] == float(res.t[-1])  # the cap itself when capped
