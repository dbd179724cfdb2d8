"""Sweep stores record every engine status by its name; old or edited stores are refused
in one line (issue 19)."""
from __future__ import annotations

import csv
import json

import pytest

from tethersim import load_preset
from tethersim.cli.main import main
from tethersim.engine.events import EVENTS
from tethersim.engine.result import STATUSES
from tethersim.experiments.sweep import (
    StoreDamaged,
    StoreMismatch,
    SweepSpec,
    kernel,
    open_dataset,
    run_sweep,
    status_names,
)
from tethersim.experiments.sweep.analysis import status_counts
from tethersim.experiments.sweep.point import STATUS

AXES = (("E1", [0.0038, 0.0042]), ("E2", [0.041, 0.043]))
PERIODS = 0.05  # short runs: the bookkeeping, not the physics, is under test


def _spec():
    return SweepSpec(load_preset("satI"), AXES, periods=PERIODS)


@pytest.fixture
def store(tmp_path):
    out = tmp_path / "sweep.zarr"
    run_sweep(_spec(), out, workers=1, progress=False)
    return out


def test_stored_codes_are_the_engine_statuses_in_both_paths():
    assert {STATUSES[c]: c for c in STATUS.values()} == STATUS  # per-point path
    assert set(STATUS) == set(STATUSES)
    # the compiled block path writes the same codes
    assert [STATUSES[c] for c in (kernel.STATUS_OK, kernel.STATUS_NONFINITE,
                                  kernel.STATUS_FAILED)] == ["ok", "diverged", "failed"]
    # a run stopped by an event: the event table's status (engine/events.py)
    assert [STATUSES[c] if c >= 0 else None for c in kernel.EVENT_STATUS] == \
        [e.status if e.terminal else None for e in EVENTS]


def test_a_balloon_blown_away_is_stored_as_left_domain_in_the_store_and_the_csv(tmp_path,
                                                                                capsys):
    """At 115 km the drag blows the balloon past its tethers' stretch limit within seconds
    (test_domain)."""
    out = tmp_path / "low"
    rc = main(["sweep", "satI", "--E1", "0.0038", "--E2", "0.041,0.043", "--set",
               "altitude=115", "--allow-implausible", "--periods", str(PERIODS), "--out",
               str(out), "--quiet", "--workers", "1"])
    assert rc == 0
    stdout = capsys.readouterr().out
    assert "2 left-domain" in stdout and "integrator_failed" not in stdout
    ds = open_dataset(out / "sweep.zarr")
    assert list(status_names(ds).ravel()) == ["left-domain", "left-domain"]
    assert status_counts(ds)["left-domain"] == 2
    assert ds.status.attrs["flag_meanings"].split() == list(STATUSES)
    with open(out / "sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["status"] for r in rows] == ["left-domain", "left-domain"]
    assert (out / "stability_map.png").exists()


def test_ok_points_read_back_as_ok(store):
    ds = open_dataset(store)
    assert (status_names(ds) == "ok").all()
    assert status_counts(ds) == {s: (4 if s == "ok" else 0) for s in STATUSES}


def _edit_metadata(store, key, change):
    """Change one metadata document in its file and in the consolidated metadata."""
    path = store / key
    doc = json.loads(path.read_text())
    change(doc)
    path.write_text(json.dumps(doc))
    meta = json.loads((store / ".zmetadata").read_text())
    change(meta["metadata"][key])
    (store / ".zmetadata").write_text(json.dumps(meta))


def test_a_store_with_the_old_status_codes_is_refused_in_one_line(store):
    def old(attrs):
        attrs["flag_values"] = [0, 1, 2]
        attrs["flag_meanings"] = "ok diverged integrator_failed"

    _edit_metadata(store, "status/.zattrs", old)
    with pytest.raises(StoreMismatch, match="status codes.*--restart") as info:
        open_dataset(store)
    assert "\n" not in str(info.value)
    with pytest.raises(StoreMismatch, match="status codes.*--restart"):
        run_sweep(_spec(), store, workers=1, progress=False)


@pytest.mark.parametrize("name, dtype", [("stability_class", "<f8"), ("status", "<i8"),
                                         ("mean_pitch", "<f4"), ("done", "|i1")])
def test_an_edited_dtype_is_refused_not_repaired(store, name, dtype, capsys):
    _edit_metadata(store, f"{name}/.zarray", lambda d: d.update(dtype=dtype))
    with pytest.raises(StoreDamaged, match=f"{name}.*edited.*--restart"):
        run_sweep(_spec(), store, workers=1, progress=False)
    with pytest.raises(StoreDamaged, match=f"{name}.*edited.*--restart"):
        open_dataset(store)
    # the CLI: one line, exit 2, and the store is left as it was (nothing "repaired")
    before = (store / f"{name}/.zarray").read_text()
    argv = ["sweep", "satI", "--E1", "0.0038,0.0042", "--E2", "0.041,0.043", "--periods",
            str(PERIODS), "--out", str(store.parent), "--quiet", "--workers", "1"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1 and name in err
    assert (store / f"{name}/.zarray").read_text() == before
    assert main(argv + ["--restart"]) == 0
    assert (status_names(open_dataset(store)) == "ok").all()


@pytest.mark.slow  # compiles the free-orbit loop; three orbits to re-enter
def test_a_free_orbit_that_re_enters_is_stored_as_re_entered(tmp_path):
    sat = load_preset("satI").replace(orbit="free", density_mode="per-body",
                                      reentry_altitude=170e3)
    spec = SweepSpec(sat, (("E2", [0.041]),), periods=3, model="free")
    ds = run_sweep(spec, tmp_path / "free.zarr", workers=1, progress=False).dataset()
    assert list(status_names(ds)) == ["re-entered"]
