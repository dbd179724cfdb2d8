"""An output folder holds one run's results: another model's run is refused unless --force,
and a run into the folder leaves none of the previous run's files it did not write again
(issue 19: a run of another model was accepted and left the first model's roll/yaw plots
beside its summary).  Nothing else in the folder is ever removed.
"""
from __future__ import annotations

import json

import pytest

from tests.cli.conftest import call

QUICK = ["--periods", "0.05", "--quiet", "--no-check"]
DATA = {"timeseries.csv", "timeseries.nc", "summary.json"}
PLANAR_RUN_FILES = DATA | {"theta.png", "delta_x.png", "delta_y.png", "overview.png",
                            "tensions.png"}  # issue 21: the tethers' tensions


def _run(out, *extra, plots=False):
    """``tethersim run satI`` into ``out`` (without plots unless asked: they cost ~1 s)."""
    return call(["run", "satI", *QUICK, "--out", str(out), *extra,
                 *([] if plots else ["--no-plots"])])


def _as_if(out, **changes):
    """Edit the folder's record as another run would have written it."""
    path = out / "summary.json"
    record = json.loads(path.read_text())
    record.update(changes)
    path.write_text(json.dumps(record))


def test_a_run_records_the_model_and_exactly_the_files_it_wrote(tmp_path):
    code, out, err = _run(tmp_path / "o", plots=True)
    assert code == 0, err
    record = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert record["model"] == "derived"
    assert set(record["files"]) == PLANAR_RUN_FILES == {p.name for p in (tmp_path / "o").iterdir()}


def test_a_run_of_another_model_into_the_folder_is_refused_in_one_line(tmp_path):
    out = tmp_path / "o"
    assert _run(out)[0] == 0
    _as_if(out, model="3d")  # the record a 3-D run leaves
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    code, _, err = _run(out)
    assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert "model 3d" in err and "model derived" in err and "--force" in err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before  # nothing touched


def test_forcing_a_run_over_another_models_removes_only_that_runs_own_leftovers(tmp_path):
    out = tmp_path / "o"
    assert _run(out)[0] == 0
    # what a 3-D run wrote besides the planar files, and a file of the user's own
    for name in ("roll.png", "yaw.png", "delta_z.png", "notes.txt"):
        (out / name).write_bytes(b"x")
    _as_if(out, model="3d", files=sorted(DATA | {"roll.png", "yaw.png", "delta_z.png"}))
    code, _, err = _run(out, "--force")
    assert code == 0, err
    assert {p.name for p in out.iterdir()} == DATA | {"notes.txt"}


def test_a_rerun_of_the_same_question_with_other_numerics_replaces_the_folders_run(tmp_path):
    out = tmp_path / "o"
    assert _run(out, plots=True)[0] == 0
    code, _, err = _run(out, "--faithful")  # same satellite, model, overrides; no plots
    assert code == 0, err
    # its summary says which integrator made the results; the previous run's plots are gone
    record = json.loads((out / "summary.json").read_text())
    assert record["integrator"].startswith("RK4 step 26.55 s")
    assert {p.name for p in out.iterdir()} == {"timeseries.csv", "timeseries.nc",
                                               "summary.json"}


@pytest.mark.parametrize("listed", ["../outside.txt", "ABSOLUTE", "sub/../../outside.txt"])
def test_a_record_naming_files_outside_the_folder_removes_nothing_there(tmp_path, listed):
    out = tmp_path / "o"
    outside = tmp_path / "outside.txt"
    outside.write_text("keep")
    assert _run(out)[0] == 0
    _as_if(out, files=[str(outside) if listed == "ABSOLUTE" else listed])
    assert _run(out)[0] == 0
    assert outside.read_text() == "keep"


def test_a_record_from_before_the_model_was_recorded_is_taken_as_this_model(tmp_path):
    out = tmp_path / "o"
    assert _run(out)[0] == 0
    record = json.loads((out / "summary.json").read_text())
    del record["model"], record["files"]
    (out / "summary.json").write_text(json.dumps(record))
    code, _, err = _run(out)
    assert code == 0, err  # and with no file list, nothing is removed but what it rewrote
    assert {p.name for p in out.iterdir()} == DATA


def test_forces_into_a_folder_of_another_model_is_refused_too(tmp_path):
    out = tmp_path / "f"
    argv = ["forces", "satI", "--periods", "0.05", "--quiet", "--out", str(out)]
    assert call(argv)[0] == 0
    record = json.loads((out / "satellite.json").read_text())
    assert record["model"] == "derived" and "forces.csv" in record["files"]
    record["model"] = "3d"
    (out / "satellite.json").write_text(json.dumps(record))
    code, _, err = call(argv)
    assert code == 2 and "model 3d" in err and len(err.strip().splitlines()) == 1


@pytest.mark.slow
def test_a_planar_run_forced_over_a_3d_run_leaves_no_roll_or_yaw_plot(tmp_path):
    out = tmp_path / "o"
    code, _, err = _run(out, "--model", "3d", plots=True)
    assert code == 0, err
    three_d = {p.name for p in out.iterdir()}
    assert {"roll.png", "yaw.png", "delta_z.png"} <= three_d
    code, _, err = _run(out, plots=True)
    assert code == 2 and "model 3d" in err
    assert _run(out, "--force", plots=True)[0] == 0
    assert {p.name for p in out.iterdir()} == PLANAR_RUN_FILES
