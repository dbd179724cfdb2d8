"""The command line on runs too short to decide a class (issue 19): each says "undecided"
and how long to run, in its table, summary or one-line refusal."""
from __future__ import annotations

import csv
import json

from tests.tiers import VARIANT_LOOP
from tethersim.analysis.metrics import min_run_orbits

HINT = f"run at least {min_run_orbits():.4g} orbits"


def test_run_summary_of_a_tenth_of_an_orbit_is_undecided(cli, tmp_path):
    out = tmp_path / "r"
    code, stdout, _ = cli(["run", "satI", "--periods", "0.1", "--no-plots", "--no-check",
                           "--out", str(out)])
    assert code == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["class"] == "undecided"
    assert s["run at least [orbits] to decide the class"] == min_run_orbits()


def test_a_short_sweep_writes_undecided_in_its_csv_and_counts(cli, tmp_path):
    out = tmp_path / "s"
    code, stdout, _ = cli(["sweep", "satI", "--E2", "0.042,0.0427", "--periods", "0.2",
                           "--out", str(out), "--quiet"])
    assert code == 0
    with (out / "sweep.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert [r["class"] for r in rows] == ["undecided", "undecided"]
    assert {r["stability_class [1]"] for r in rows} == {"6"}
    assert f"undecided    2: {HINT}" in stdout


@VARIANT_LOOP
def test_compare_of_short_runs_says_how_long_to_run(cli, tmp_path):
    code, stdout, _ = cli(["compare", "satI", "--periods", "0.1", "--models", "derived,printed",
                           "--out", str(tmp_path / "c"), "--quiet"])
    assert code == 0
    assert f"all variants end undecided: {HINT}" in stdout


def test_tune_refuses_a_run_too_short_to_decide_in_one_line(cli, tmp_path):
    code, _, err = cli(["tune", "satI", "--periods", "0.05", "--out", str(tmp_path / "t")])
    assert code == 2
    assert err.count("\n") == 1 and "periods = 0.05" in err and f"{min_run_orbits():.4g}" in err
