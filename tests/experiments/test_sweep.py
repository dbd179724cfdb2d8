"""Sweeps: grid = points run one by one; resume (Ctrl-C and kill) = uninterrupted; Dask = threads."""
from __future__ import annotations

import math
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import tethersim as ts
from tethersim import load_preset, simulate
from tethersim.analysis.classify import classify
from tethersim.experiments.sweep import StoreMismatch, SweepInterrupted, SweepSpec, run_sweep, sweep
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL, DEFAULT_RTOL, SAMPLES_PER_PERIOD
from tethersim.model.params import parse_grid
from tethersim.model.satellite import SatelliteError

SAT = load_preset("satI")
# E1 x E2 around the preset (E1 0.004, E2 0.0427 N/mm^2): both sides of the stable band
AXES = {"E1": [0.0038, 0.0042], "E2": [0.041, 0.043, 0.045]}
PERIODS = 2.0


def _spec(**kw):
    return SweepSpec(SAT, tuple(AXES.items()), periods=PERIODS, **kw)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """An uninterrupted sweep on the default thread pool."""
    out = tmp_path_factory.mktemp("ref") / "sweep.zarr"
    return run_sweep(_spec(), out, progress=False).dataset()


def test_sweep_points_equal_the_same_runs_simulated_one_by_one(reference):
    ds = reference
    assert ds.stability_class.dims == ("E2", "E1")
    for e1 in AXES["E1"]:
        for e2 in AXES["E2"]:
            sat = SAT.replace(E1=e1, E2=e2)  # N/mm^2 x 1 mm^2 = N
            res = simulate(sat, PERIODS, rtol=DEFAULT_RTOL, atol=DEFAULT_RTOL * ATOL_PER_RTOL,
                           samples=round(SAMPLES_PER_PERIOD * PERIODS), check=False,
                           progress=False)
            out = ts.outcome(res)  # the one outcome: metrics on the metrics grid
            m = out.metrics
            point = ds.sel(E1=e1, E2=e2)
            assert point.done.item()
            assert point.steady_state_pitch.item() == m.steady_state_pitch
            assert point.mean_pitch.item() == m.mean_pitch
            assert (point.stability_class.item() == classify(m, run_orbits=PERIODS)
                    == out.stability_class)
            np.testing.assert_equal(point.settling_time.item(), m.settling_time)
            assert point.nfev.item() == res.nfev
            assert point.max_force_theta.item() == out.max_force[2]  # peaks on the metrics grid


def test_sweep_grid_labels_carry_units_and_class_meanings(reference):
    assert reference.E1.attrs["units"] == "N/mm^2"
    assert reference.settling_time.attrs["units"] == "s"
    assert reference.stability_class.attrs["flag_meanings"].split()[0] == "stable"


def paced(monkeypatch, seconds=0.05):
    """Points that take ``seconds`` longer (data unchanged): an interruption then lands
    while points are pending, however fast the machine computes them."""
    from tethersim.experiments.sweep import runner
    fast = runner.run_points
    monkeypatch.setattr(runner, "run_points", lambda *a: (time.sleep(seconds), fast(*a))[1])


def test_interrupted_sweep_resumes_to_the_uninterrupted_data(reference, tmp_path, monkeypatch):
    out = tmp_path / "sweep.zarr"
    paced(monkeypatch)
    with pytest.raises(SweepInterrupted) as info:
        run_sweep(_spec(), out, workers=2, progress=False, stop_after=2)
    partial = xr.open_zarr(out).load()
    n_done = int(partial.done.sum())
    assert 2 <= n_done < partial.done.size, "the interruption kept the finished points only"
    assert str(out) in str(info.value)
    monkeypatch.undo()
    resumed = run_sweep(_spec(), out, workers=1, progress=False).dataset()
    xr.testing.assert_identical(resumed, reference)


def test_killed_sweep_resumes_to_the_uninterrupted_data(reference, tmp_path):
    """SIGKILL (no clean-up at all) mid-sweep: finished, flushed points survive."""
    out = tmp_path / "sweep.zarr"
    script = (
        "import time, tethersim.experiments.sweep.runner as r\n"
        "r.FLUSH_SECONDS = 0.0\n"
        # pace the points (data unchanged) so that the kill lands mid-sweep
        "fast = r.run_points\n"
        "r.run_points = lambda *a: (fast(*a), time.sleep(1.0))[0]\n"
        "from tethersim.experiments.sweep import run_sweep\n"
        "from tests.experiments.test_sweep import _spec\n"
        f"run_sweep(_spec(), {str(out)!r}, workers=1, progress=False)\n")
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=Path(__file__).parents[2])
    try:
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline:
            time.sleep(0.05)
            if (out / ".zmetadata").exists():
                try:
                    done = xr.open_zarr(out).done.values
                except (OSError, ValueError, KeyError):
                    continue
                if done.sum() >= 1:
                    break
        else:
            pytest.fail("the sweep subprocess produced no point")
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
    partial = xr.open_zarr(out).load()
    finished = partial.done.values
    assert 1 <= finished.sum() < finished.size, "killed before the end, after a flush"
    # every point marked done holds its data: compare with the reference right away
    np.testing.assert_array_equal(partial.steady_state_pitch.values[finished],
                                  reference.steady_state_pitch.values[finished])
    resumed = run_sweep(_spec(), out, progress=False).dataset()
    xr.testing.assert_identical(resumed, reference)


def test_dask_local_cluster_gives_the_thread_pool_data(reference, tmp_path):
    ds = run_sweep(_spec(), tmp_path / "sweep.zarr", dask_workers=2, progress=False).dataset()
    xr.testing.assert_identical(ds, reference)


def test_closing_a_local_cluster_drops_only_the_heartbeat_race_record():
    import logging

    from tethersim.experiments.sweep.runner import _not_heartbeat_race

    def record(msg):
        return logging.LogRecord("distributed.worker", logging.ERROR, __file__, 1, msg, (), None)

    assert not _not_heartbeat_race(record("Failed to communicate with scheduler during heartbeat."))
    assert _not_heartbeat_race(record("Worker stream died during communication: tcp://127.0.0.1:1"))


def test_faithful_sweep_uses_the_thesis_step_and_differs_from_adaptive(tmp_path):
    spec = SweepSpec(SAT, (("E2", [0.0427]),), periods=PERIODS, method="faithful")
    ds = run_sweep(spec, tmp_path / "f.zarr", progress=False).dataset()
    res = simulate(SAT, PERIODS, steps=round(200 * PERIODS), method="rk4", check=False,
                   progress=False)
    assert math.isclose(res.step, 26.55, rel_tol=1e-3)  # thesis p. 5-7
    assert ds.steady_state_pitch.item() == ts.outcome(res).metrics.steady_state_pitch
    assert ds.nfev.item() == res.nfev


def test_resuming_a_different_sweep_in_the_same_store_is_refused(reference, tmp_path):
    out = tmp_path / "sweep.zarr"
    run_sweep(SweepSpec(SAT, (("E2", [0.0427]),), periods=1.0), out, progress=False)
    with pytest.raises(StoreMismatch, match="periods"):
        run_sweep(SweepSpec(SAT, (("E2", [0.0427]),), periods=2.0), out, progress=False)


def test_a_grid_with_an_invalid_satellite_fails_before_any_run_naming_the_point():
    with pytest.raises(SatelliteError, match=r"sweep point .*l10 = -1"):
        SweepSpec(SAT, (("l10", [6.0, -1.0]),))


def test_a_workers_copy_of_a_checked_spec_does_not_check_its_points_again(monkeypatch):
    from tethersim.experiments.sweep import point
    text = SweepSpec(SAT, (("E2", [0.03, 0.0427]),), periods=2.0).to_json()
    point._spec.cache_clear()

    def refuse(*args, **kwargs):
        raise AssertionError("the points were checked again")

    monkeypatch.setattr(SweepSpec, "check_points", refuse)
    copy = point._spec(text)
    assert copy.to_json() == text
    point._spec.cache_clear()
    with pytest.raises(AssertionError, match="checked again"):  # a spec made afresh checks
        SweepSpec.from_json(text)


@pytest.mark.parametrize("spec, values", [
    ("0:0.02:5", [0, 0.005, 0.01, 0.015, 0.02]),
    ("0.1,0.3", [0.1, 0.3]),
    ("2:2:1", [2.0]),
])
def test_grid_specs_parse_to_inclusive_values(spec, values):
    np.testing.assert_allclose(parse_grid("E1", spec), values)


@pytest.mark.parametrize("spec, message", [
    ("0:1", "start:stop:count"), ("0:1:x", "count"), ("0:1:0", "count"),
    ("a,b", "not a number"), ("1,1", "repeat"), ("0:nan:3", "finite"),
])
def test_bad_grid_specs_are_refused_naming_the_option(spec, message):
    with pytest.raises(ValueError, match=message) as info:
        parse_grid("E1", spec)
    assert "--E1" in str(info.value)


def test_sweep_function_returns_the_store_dataset(tmp_path):
    ds = sweep(SAT, {"c1": [3e-4]}, tmp_path / "s.zarr", periods=1.0, progress=False)
    assert ds.c1.values.tolist() == [3e-4] and bool(ds.done.all())


@pytest.mark.parametrize("block", [4, 5])
def test_the_block_size_does_not_change_the_data(reference, tmp_path, block):
    ds = run_sweep(_spec(), tmp_path / "b.zarr", workers=2, block=block, progress=False).dataset()
    xr.testing.assert_identical(ds, reference)


def test_blocks_hold_about_forty_orbits_and_keep_every_worker_busy():
    from tethersim.experiments.sweep.runner import block_size
    assert block_size(5.0, 10_000, 2) == 8
    assert block_size(50.0, 10_000, 2) == 1
    assert block_size(50.0, 10_000, 2, lanes=4) == 4  # never fewer points than lanes
    assert block_size(50.0, 40, 2, lanes=8) == 5  # balance first: >= 4 tasks per thread
    assert block_size(5.0, 10_000, 2, lanes=4) == 8
    assert block_size(0.1, 10_000, 2) == 64  # capped
    assert block_size(5.0, 20, 2) == 3  # 20 points on 2 threads: >= 4 tasks each
    assert block_size(50.0, 100, 2, minimum=4) == 4  # Dask's smallest task


def test_a_sweep_of_long_runs_fills_the_simd_lanes(monkeypatch):
    """A 50-orbit sweep (the report's maps) gives each compiled block at least the lanes'
    points: blocks of one point ran point by point, never on the lanes.  Ten lanes' worth
    of points on two threads, whatever the CPU's lanes (4 with AVX2, 8 with AVX-512):
    fewer points are cut for balance first (block_size)."""
    from tethersim.experiments.sweep import batch, runner
    from tethersim.experiments.sweep.plan import Plan
    sizes = []
    monkeypatch.setattr(batch, "run_satellites",
                        lambda plan, sats: sizes.append(len(sats)) or [{}] * len(sats))
    lanes = batch.lane_width(Plan(periods=50.0))
    runner.run_plan(Plan(periods=50.0), [SAT] * (10 * lanes), workers=2, progress=False)
    assert lanes >= 4
    assert sum(sizes) == 10 * lanes and min(sizes) >= lanes
    assert batch.lane_width(Plan(periods=50.0, method="implicit")) == 1
