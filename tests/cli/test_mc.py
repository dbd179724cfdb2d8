"""``tethersim mc``: outputs, resume, the summary's counts, and one-line refusals.

The refusals come before any run (fast tier); the runs compile the free-orbit block
(slow tier)."""
from __future__ import annotations

import csv

import pytest

FAST = ["--n", "8", "--seed", "4", "--periods", "2", "--max-lifetime", "4", "--quiet",
        "--workers", "2"]


@pytest.fixture(scope="module")
def done(tmp_path_factory):
    from tests.cli.conftest import call
    out = tmp_path_factory.mktemp("mc")
    code, text, err = call(["mc", "satI", *FAST, "--out", str(out)])
    assert code == 0, err
    return out, text


@pytest.mark.slow
def test_mc_writes_samples_summary_and_plots(done):
    out, text = done
    for name in ("samples.csv", "summary.csv", "distributions.png", "store/rows.jsonl"):
        assert (out / name).stat().st_size > 0
    with (out / "samples.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert [int(r["i"]) for r in rows] == list(range(8))
    tumbles = sum(r["tumbled"] == "true" for r in rows)
    assert f"{tumbles} of 8" in (out / "summary.csv").read_text()
    assert "P(tumbles)" in text and "P50 lifetime_h" in text


@pytest.mark.slow
def test_mc_rerun_resumes_to_the_same_samples(done, cli):
    out, _ = done
    before = (out / "samples.csv").read_bytes()
    code, _, err = cli(["mc", "satI", *FAST, "--out", str(out)])
    assert code == 0, err
    assert (out / "samples.csv").read_bytes() == before


@pytest.mark.slow
def test_mc_with_sobol_writes_the_index_plot(cli, tmp_path):
    code, text, err = cli(["mc", "satI", *FAST[:-2], "--n", "2", "--sobol", "2", "--range",
                           "CD=0.9:1.1", "--out", str(tmp_path)])
    assert code == 0, err
    assert (tmp_path / "sobol.png").stat().st_size > 0
    assert "Sobol' lifetime_h: epoch S1" in text


@pytest.mark.parametrize("extra, words", [
    (["--n", "0"], "--n"),
    (["--sobol", "3"], "--sobol: sobol = 3: the base sample size must be a power of two"),
    (["--max-lifetime", "1"], "--max-lifetime: max_lifetime_h = 1.0: must be >="),
    (["--range", "CD=2:1"], "--range: range of CD = 2.0:1.0"),
    (["--range", "nosuch=1:2"], "unknown input"),
    (["--range", "CD"], "--range CD: expected NAME=LOW:HIGH"),
    (["--range", "epoch=1900-01-01:1990-01-01"], "allowed days"),
    (["--set", "epoch=2003-01-01T00:00:00"], "epoch"),
    (["--set", "atmosphere=vallado"], "atmosphere"),
    (["--model", "free"], "--model free"),
    (["--workers", "1", "--dask-workers", "2"], "alternatives"),
])
def test_mc_bad_input_is_one_line_naming_the_option(cli, tmp_path, extra, words):
    code, _, err = cli(["mc", "satI", *FAST[:-2], *extra, "--out", str(tmp_path)])
    assert code == 2
    assert words in err and err.count("\n") == 1 and err.startswith("tethersim: error:")


@pytest.mark.slow
def test_mc_refuses_another_spec_in_the_same_store(done, cli):
    out, _ = done
    code, _, err = cli(["mc", "satI", *FAST, "--seed", "5", "--out", str(out)])
    assert code == 2 and "holds a Monte Carlo of other settings" in err
