"""Size and worker refusals come before any work or file, and name the command's own options.

A refused sweep used to leave a store that blocked the corrected rerun; a run of 10
samples over 10^6 orbits passed the guard and allocated 15 GiB; feasibility blamed
'--steps/--periods' (it has no --steps) for its --max-lifetime.
"""
from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from tests.messages import one_line
from tethersim.cli.main import main
from tethersim.cli.preflight import max_workers

ROOT = Path(__file__).parents[2]



def _refused(argv, capsys) -> str:
    t0 = time.perf_counter()
    assert main(argv) == 2
    assert time.perf_counter() - t0 < 5.0, "refused before any run"
    return one_line(capsys.readouterr().err)


def test_run_of_few_samples_over_many_orbits_is_refused_before_its_folder(tmp_path, capsys):
    out = tmp_path / "r"
    line = _refused(["run", "satI", "--periods", "1e6", "--steps", "10", "--no-plots",
                     "--out", str(out)], capsys)
    assert line.startswith("tethersim: error: --periods/--steps: ") and "metrics grid" in line
    assert not out.exists()


@pytest.mark.parametrize("command", [["compare", "satI"], ["forces", "satI"]])
def test_compare_and_forces_refuse_before_their_folder(tmp_path, capsys, command):
    out = tmp_path / "c"
    line = _refused([*command, "--periods", "1e6", "--steps", "10", "--out", str(out)], capsys)
    assert line.startswith("tethersim: error: --periods/--steps: ")
    assert not out.exists()


def test_feasibility_blames_max_lifetime_not_steps(tmp_path, capsys):
    out = tmp_path / "f"
    line = _refused(["feasibility", "satI", "--altitude", "200", "--max-lifetime", "1e12",
                     "--out", str(out), "--quiet"], capsys)
    assert line.startswith("tethersim: error: --max-lifetime: ") and "--steps" not in line
    assert not out.exists()
    line = _refused(["feasibility", "satI", "--altitude", "200", "--periods", "1e9",
                     "--out", str(out), "--quiet"], capsys)
    assert line.startswith("tethersim: error: --periods: ") and "--steps" not in line


def test_a_command_without_steps_never_blames_steps(capsys):
    # validate's runs are simulate()'s own: its refusal names validate's --periods
    line = _refused(["validate", "satI", "--periods", "1e7"], capsys)
    assert line.startswith("tethersim: error: --periods: ") and "steps" not in line.split(":")[2]


def test_refused_sweep_leaves_nothing_and_the_corrected_rerun_runs(tmp_path, capsys):
    out = tmp_path / "s"
    line = _refused(["sweep", "satI", "--E1", "0:0.01:3", "--periods", "1e6", "--out",
                     str(out), "--quiet"], capsys)
    assert line.startswith("tethersim: error: --periods: ") and "--steps" not in line
    assert not out.exists(), "no folder, store or lock to block the rerun"
    assert main(["sweep", "satI", "--E1", "0.003,0.004", "--periods", "0.1", "--workers", "1",
                 "--no-plots", "--out", str(out), "--quiet"]) == 0
    assert "holds a different sweep" not in capsys.readouterr().err


@pytest.mark.parametrize("argv", [
    ["sweep", "satI", "--E1", "0.001,0.004", "--periods", "0.2", "--dask-workers", "{n}"],
    ["sweep", "satI", "--E1", "0.001,0.004", "--periods", "0.2", "--workers", "{n}"],
    ["tune", "satI", "--workers", "{n}"],
    ["report", "--workers", "{n}"],
    ["feasibility", "satI", "--altitude", "200", "--workers", "{n}"],
])
def test_worker_counts_are_capped_inone_line(tmp_path, capsys, argv):
    cap = max_workers()
    assert cap == 4 * (os.cpu_count() or 1)
    args = [a.format(n=cap + 1) for a in argv] + ["--out", str(tmp_path / "o")]
    line = _refused(args, capsys)
    option = argv[argv.index("{n}") - 1]
    assert line == (f"tethersim: error: {option} {cap + 1}: allowed 1..{cap} "
                    f"(4 per core, {os.cpu_count() or 1} cores)")
    assert not (tmp_path / "o").exists()


def test_interrupted_sweep_says_how_to_continue_once(tmp_path, monkeypatch, capsys):
    import tethersim.experiments.sweep as sweep_pkg
    from tethersim.experiments.sweep.runner import SweepInterrupted

    def interrupted(spec, out, **kwargs):
        raise SweepInterrupted(SimpleNamespace(done=np.array([True, False]), path=out))

    monkeypatch.setattr(sweep_pkg, "run_sweep", interrupted)
    rc = main(["sweep", "satI", "--E1", "0.003,0.004", "--periods", "0.1", "--out",
               str(tmp_path / "s"), "--quiet"])
    assert rc == 130
    line = one_line(capsys.readouterr().err)
    assert line.count("again") == 1 and "run the same command again to continue" in line
    assert "1 of 2 points" in line


def test_sigterm_while_a_million_points_are_checked_exits_at_once(tmp_path):
    """The grid's points are checked with a bar; SIGTERM there exits within 2 s, no folder."""
    out = tmp_path / "big"
    proc = subprocess.Popen([sys.executable, "-m", "tethersim", "sweep", "satI", "--E1",
                             "0:0.01:1000000", "--periods", "0.2", "--no-plots", "--out",
                             str(out)], cwd=ROOT, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, bufsize=0)
    try:
        seen = ""
        deadline = time.monotonic() + 60
        while "checking sweep points" not in seen:  # the bar: after a second of checks
            assert time.monotonic() < deadline and proc.poll() is None, seen
            seen += proc.stderr.read(1)
        t0 = time.monotonic()
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=10)
        assert time.monotonic() - t0 < 2.0
        err = seen + proc.stderr.read()
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.stdout.close()
        proc.stderr.close()
    assert proc.returncode == 130
    assert "Traceback" not in err
    # the last thing a terminal shows (the bar rewrites its line with \r)
    shown = [seg.strip() for seg in re.split(r"[\r\n]", err) if seg.strip()]
    assert shown[-1].endswith("tethersim: interrupted")  # nothing started: no hint
    assert not out.exists()


def test_a_grid_leaving_the_allowed_range_at_its_end_is_refused_at_once(tmp_path, capsys):
    # a million altitudes whose last is past the 1000-km table: found among the corners,
    # before the million-point check (which takes most of a minute)
    out = tmp_path / "s"
    line = _refused(["sweep", "satI", "--altitude", "200:1001:1000000", "--periods", "0.1",
                     "--out", str(out), "--quiet"], capsys)
    assert "sweep point altitude = 1001 km is not a valid satellite" in line
    assert not out.exists()
