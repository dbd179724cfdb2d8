"""Sweep stores under attack: truncated, deleted and altered chunks, damaged metadata,
two writers; every resume equals an uninterrupted run.  SIGKILL mid-write, then
resume: tests/experiments/test_sweep.py::test_killed_sweep_resumes_to_the_uninterrupted_data, whose
resume also shows that a killed writer's lock does not block the next one."""
from __future__ import annotations

import os
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import zarr

from tethersim import load_preset
from tethersim.cli.main import main
from tethersim.experiments.sweep import (
    StoreDamaged,
    StoreLocked,
    StoreMismatch,
    StoreRepaired,
    SweepSpec,
    run_sweep,
)
from tethersim.experiments.sweep import store as store_module
from tethersim.experiments.sweep.lock import StoreLock

ROOT = Path(__file__).parents[2]
AXES = (("E1", [0.0038, 0.0042]), ("E2", [0.041, 0.043, 0.045]))  # rows are E2 values
PERIODS = 0.2  # short runs: the faults, not the physics, are under test


@pytest.fixture(autouse=True)
def row_chunks(monkeypatch):
    # one chunk per grid row, as a sweep of more than CHUNK_POINTS points has: a fault
    # then hits one row (this 2 x 3 grid is otherwise one chunk per variable)
    monkeypatch.setattr(store_module, "CHUNK_POINTS", 1)


def _spec():
    return SweepSpec(load_preset("satI"), AXES, periods=PERIODS)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    out = tmp_path_factory.mktemp("ref") / "sweep.zarr"
    return run_sweep(_spec(), out, workers=1, progress=False).dataset()


@pytest.fixture
def store(tmp_path):
    out = tmp_path / "sweep.zarr"
    run_sweep(_spec(), out, workers=1, progress=False)
    return out


def _resume_repairs(out, n_points, reference):
    with pytest.warns(StoreRepaired, match=f"{n_points} point\\(s\\) had damaged or missing data"):
        resumed = run_sweep(_spec(), out, workers=1, progress=False).dataset()
    xr.testing.assert_identical(resumed, reference)
    # and the repaired store is clean: a further resume finds nothing to do, warns nothing
    xr.testing.assert_identical(run_sweep(_spec(), out, progress=False).dataset(), reference)


def test_truncated_chunk_is_recomputed_not_a_traceback(store, reference):
    chunk = store / "mean_pitch" / "1.0"  # row E2 = 0.043
    chunk.write_bytes(chunk.read_bytes()[:7])
    with pytest.raises(Exception):  # noqa: B017  premise: the chunk no longer decompresses
        xr.open_zarr(store).mean_pitch.load()
    _resume_repairs(store, 2, reference)


def test_deleted_chunk_is_recomputed_not_a_silent_nan_row(store, reference):
    (store / "trail_delta_x" / "2.0").unlink()  # row E2 = 0.045
    raw = xr.open_zarr(store).load()
    assert raw.done.values[2].all() and np.isnan(raw.trail_delta_x.values[2]).all(), \
        "premise: Zarr reads a deleted chunk as fill values, marked done"
    _resume_repairs(store, 2, reference)


def test_deleted_int_chunk_and_checksum_chunk_are_both_caught(store, reference):
    (store / "stability_class" / "0.0").unlink()  # reads back as 0: "stable", not NaN
    (store / "checksum" / "1.0").unlink()
    _resume_repairs(store, 4, reference)


def test_altered_value_fails_its_checksum(store, reference):
    group = zarr.open_group(str(store), mode="r+")
    group["settling_time"][0, 1] = 1234.5  # a plausible but wrong number
    _resume_repairs(store, 1, reference)


def test_deleted_done_chunk_only_recomputes_those_points(store, reference):
    (store / "done" / "1.0").unlink()  # reads as not done: pending, nothing silent
    resumed = run_sweep(_spec(), store, workers=1, progress=False).dataset()
    xr.testing.assert_identical(resumed, reference)


@pytest.mark.parametrize("damage", ["garbage", "deleted", "no-zgroup"])
def test_damaged_metadata_stops_naming_restart(store, reference, damage, capsys):
    meta = store / ".zmetadata"
    if damage == "garbage":
        meta.write_text("{not json")
    elif damage == "deleted":
        meta.unlink()
    else:
        (store / ".zgroup").unlink()
    with pytest.raises(StoreDamaged, match="metadata is damaged.*--restart"):
        run_sweep(_spec(), store, progress=False)
    # the CLI says it in one line, then --restart recovers
    argv = ["sweep", "satI", "--E1", "0.0038,0.0042", "--E2", "0.041,0.043,0.045",
            "--periods", str(PERIODS), "--out", str(store.parent), "--quiet", "--no-plots",
            "--workers", "1"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1 and "--restart" in err
    assert main(argv + ["--restart"]) == 0
    xr.testing.assert_identical(xr.open_zarr(store).drop_vars("checksum").load(), reference)


def test_store_without_checksums_is_refused_naming_restart(store):
    import shutil

    shutil.rmtree(store / "checksum")
    zarr.consolidate_metadata(str(store))  # a consistent store, as an older tethersim wrote
    with pytest.raises(StoreMismatch, match="no per-point checksums.*--restart"):
        run_sweep(_spec(), store, progress=False)


def test_cli_resume_of_a_damaged_store_warns_in_one_line(store, capsys):
    (store / "nfev" / "0.0").unlink()
    rc = main(["sweep", "satI", "--E1", "0.0038,0.0042", "--E2", "0.041,0.043,0.045",
               "--periods", str(PERIODS), "--out", str(store.parent), "--quiet", "--no-plots",
               "--workers", "1"])
    assert rc == 0
    err = capsys.readouterr().err
    assert "Traceback" not in err
    warning = [line for line in err.splitlines() if "StoreRepaired" in line]
    assert len(warning) == 1 and "2 point(s)" in warning[0] and "recomputed" in warning[0]


def test_second_writer_stops_naming_the_first_and_the_store_stays_valid(tmp_path, reference):
    out = tmp_path / "sweep.zarr"
    with StoreLock(out):  # a first writer, in this process
        with pytest.raises(StoreLocked) as info:
            run_sweep(_spec(), out, progress=False)
        msg = str(info.value)
        assert f"pid {os.getpid()} on host {socket.gethostname()}" in msg
        assert "\n" not in msg
        assert not out.exists(), "the refused writer touched nothing"
    # the lock is free again: the sweep runs and equals the reference
    xr.testing.assert_identical(run_sweep(_spec(), out, progress=False).dataset(), reference)


def test_second_writer_process_gets_a_one_line_error(tmp_path):
    out = tmp_path / "s"
    with StoreLock(out / "sweep.zarr"):
        proc = subprocess.run(
            [sys.executable, "-m", "tethersim", "sweep", "satI", "--E1", "0.004", "--periods",
             "0.1", "--out", str(out), "--quiet", "--no-plots"],
            cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and f"pid {os.getpid()}" in lines[0], proc.stderr


def test_two_writers_creating_one_store_at_once(tmp_path, reference):
    """The race that used to corrupt a new store (a KeyError, then a broken store): two
    writers start together; each ends cleanly or is refused, and the store is right.
    Threads, not processes, to stay fast: the lock is an OS file lock per open file, so
    two writers in one process exclude each other exactly as two processes do."""
    import threading

    out = tmp_path / "sweep.zarr"
    barrier = threading.Barrier(2)
    outcomes = []

    def writer():
        barrier.wait()
        try:
            run_sweep(_spec(), out, workers=1, progress=False)
            outcomes.append("ok")
        except StoreLocked as exc:
            outcomes.append(str(exc))

    threads = [threading.Thread(target=writer) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert len(outcomes) == 2 and "ok" in outcomes
    for o in outcomes:
        assert o == "ok" or f"being written by another tethersim process (pid {os.getpid()}" in o
    xr.testing.assert_identical(run_sweep(_spec(), out, progress=False).dataset(), reference)


def test_a_flush_writes_each_run_of_adjacent_rows_at_once():
    from tethersim.experiments.sweep.store import _runs
    assert _runs([]) == []
    assert _runs([0, 1, 2, 5, 7, 8]) == [(0, 3), (5, 6), (7, 9)]
