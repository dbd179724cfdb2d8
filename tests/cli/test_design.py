"""``tethersim design``: files, the summary, resuming, and one-line refusals."""
from __future__ import annotations

import csv

import pytest

from tethersim.cli.main import main

ARGS = ["design", "satI", "--vary", "c1=0.001:0.1", "--vary", "c2=0.001:0.1",
        "--altitude", "200:215", "--budget", "6", "--population", "3", "--periods", "4",
        "--max-lifetime", "6", "--workers", "1", "--quiet"]


@pytest.mark.slow  # a search: the free-orbit kernels compile (~30 s cold)
def test_design_writes_its_tables_and_plot_and_a_rerun_reads_the_store(tmp_path, capsys):
    out = tmp_path / "d"
    assert main(ARGS + ["--out", str(out)]) == 0
    text = capsys.readouterr().out
    with (out / "designs.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 6
    assert {"c1 [N s/m]", "c2 [N s/m]", "altitude [km]", "verdict",
            "margin life - settling [h]", "worst |theta_ss| [rad]"} <= set(rows[0])
    assert all(200 <= float(r["altitude [km]"]) <= 215 for r in rows)
    header = (out / "pareto.csv").read_text().splitlines()[0]
    assert "verified" in header and "bound: settling/life >= [1]" in header
    assert (out / "design.png").stat().st_size > 10_000
    # SatI's trim leaves the thesis band in these airs: the summary says so, with the reason
    assert "no design qualifies" in text and "trail bound" in text
    assert main(ARGS + ["--out", str(out)]) == 0
    assert "6 design(s) evaluated (6 read from the store)" in capsys.readouterr().out


@pytest.mark.parametrize("extra, named", [
    (["--vary", "nosuch=1:2"], "nosuch"),
    (["--vary", "c1=0.1:0.01"], "c1"),
    (["--vary", "c1=abc"], "c1"),
    (["--vary", "A3=1:1e9"], "A3"),
    (["--choice", "A3=6"], "A3"),
    (["--set", "density_scale=2"], "density_scale"),
])
def test_a_bad_design_variable_is_refused_in_one_line_naming_it(extra, named, tmp_path,
                                                                  capsys):
    argv = ["design", "satI", "--budget", "2", "--out", str(tmp_path / "x"), "--quiet",
            *extra]
    if "--vary" not in extra and "--choice" not in extra:
        argv += ["--vary", "c1=0.001:0.01"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("tethersim: error:") and named in err and "\n" not in err
    assert not (tmp_path / "x").exists()  # refused before any store or run
