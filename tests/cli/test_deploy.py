"""tethersim/cli/deploy.py: the deployment table, its plot, its refusals and its
interruption."""
from __future__ import annotations

import csv
import json
from dataclasses import replace

import pytest

from tests.tiers import VARIANT_LOOP
from tethersim.analysis.classify import CLASSES
from tethersim.experiments import deployment
from tethersim.experiments.deployment import arrival, catch_closed_form
from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
from tethersim.model.presets import load_preset

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
LINES = ["--set", "l10=30.83", "--set", "l20=28.92", "--tethers", "dyneema-sk75:1"]
# 26.5 s: the first catches; settling runs of 3 orbits
SHORT = ["--periods", "0.005", "--sample", "0.002", "--settle-periods", "3", "--quiet"]


def _rows(path):
    with path.open() as fh:
        return list(csv.DictReader(fh))


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_deploy_writes_a_row_per_start_and_the_plot(tmp_path, cli):
    out = tmp_path / "d"
    code, stdout, _ = cli(["deploy", "satI", *LINES, *SHORT, "--speeds", "0.1,1",
                           "--release", "3", "--out", str(out)])
    assert code == 0, stdout
    rows = _rows(out / "deployment.csv")
    assert [(r["start"], float(r["arrival speed [m/s] or release distance [m]"]))
            for r in rows] == [("arrival", 0.1), ("arrival", 1.0), ("release", 3.0)]
    arrive, release = rows[1], rows[2]
    assert float(arrive["first catch [s]"]) == 0.0  # an arrival starts on taut lines
    assert 10 < float(release["first catch [s]"]) < 26.5  # drag carries it ~26 m in ~17 s
    # the catch grows as D + v √(k μ) (catch_closed_form): 1 m/s against 0.1 m/s, to the
    # 3 % that the dampers, the boom's turn and the line's share of the pull leave out
    sat = real_lines(load_preset("satI"), STRETCHED_LENGTHS)
    expected = catch_closed_form(arrival(sat, 1.0)) / catch_closed_form(arrival(sat, 0.1))
    ratio = float(arrive["first catch's peak tension [N]"]) / float(
        rows[0]["first catch's peak tension [N]"])
    assert ratio == pytest.approx(expected, rel=0.03)
    # the settling runs: a braked arrival settles upright at once; where a free release
    # ends after its tumbling is chaotic (docs/real-tethers.md), but it is a class
    assert rows[0]["class after the settling run"] == "stable"
    assert float(rows[0]["settling time [h]"]) == 0.0
    assert release["class after the settling run"] in CLASSES
    assert (out / "deployment.png").read_bytes()[:8] == PNG_MAGIC
    record = json.loads((out / "satellite.json").read_text())
    assert "deployment.csv" in " ".join(record["files"])
    assert "first peak [N]" in stdout and "deployment.png" in stdout


@pytest.mark.parametrize("argv, message", [
    (["--speeds", "-1"], "--speeds: arrival speed = -1 m/s: allowed 0 to 100 m/s"),
    (["--release", "40"], "--release: release distance = 40 m: a free release starts with "
                          "the balloon (radius 1.95 m) clear of the boom and both lines "
                          "slack, 1.95 < distance < 28.9 m"),
    (["--speeds", "", "--release", ""], "--speeds and --release are both empty"),
    (["--speeds", "fast"], "--speeds fast: 'fast' is not a number (expected speeds 0 to 100"),
    (["--periods", "50", "--sample", "0.0001"], "--periods/--sample: sample = 0.0001 s over "
                                                "50 orbits"),
    (["--settle-periods", "1"], "--settle-periods 1: 0 (no settling run) or at least 3 orbits"),
    (["--sample", "0.5"], "--periods/--sample: sample = 0.5 s: a catch on these lines lasts"),
    (["--model", "free"], "argument --model: invalid choice: 'free'"),
    (["--settle-periods", "nan"], "--settle-periods nan: 0 (no settling run)"),
])
def test_deploy_refuses_bad_starts_in_one_line_before_any_output(tmp_path, cli, argv,
                                                                 message):
    out = tmp_path / "never"
    code, _, stderr = cli(["deploy", "satI", *LINES, "--quiet", "--out", str(out), *argv])
    assert code == 2 and message in stderr, stderr
    assert stderr.count("\n") == 1
    assert not out.exists()


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_an_interrupted_deploy_keeps_the_starts_it_finished(tmp_path, cli, monkeypatch):
    # Ctrl-C inside a run: simulate() returns it "interrupted" (it keeps what it has); the
    # second start's catch run is one such
    calls = []
    real = deployment.simulate

    def ctrl_c_in_the_third_run(*args, **kwargs):  # 1: catch, 2: settling, 3: next catch
        calls.append(1)
        res = real(*args, **kwargs)
        return replace(res, status="interrupted") if len(calls) == 3 else res

    monkeypatch.setattr(deployment, "simulate", ctrl_c_in_the_third_run)
    out = tmp_path / "d"
    code, _, stderr = cli(["deploy", "satI", *LINES, *SHORT, "--speeds", "0.1,1",
                           "--release", "", "--out", str(out)])
    assert code == 130 and "1 of 2 starts written" in stderr, stderr
    assert len(_rows(out / "deployment.csv")) == 1
    assert (out / "satellite.json").is_file()


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_the_default_release_is_left_out_where_the_lines_cannot_reach_it(tmp_path, cli):
    # the thesis's 6 m tethers cannot hold a balloon released clear of the boom
    out = tmp_path / "d"
    code, stdout, _ = cli(["deploy", "satI", "--speeds", "0.1", "--periods", "0.005",
                           "--settle-periods", "0", "--quiet", "--out", str(out)])
    assert code == 0
    assert "no free release: release distance = 3 m" in stdout
    assert [r["start"] for r in _rows(out / "deployment.csv")] == ["arrival"]
