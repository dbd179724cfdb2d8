"""``tethersim deorbit``: refusals in one line, and a small run's files and lines."""
import csv

import numpy as np
import pytest

from tethersim.cli.main import main
from tethersim.model import atmosphere
from tethersim.model.air import orbit_mean


@pytest.fixture
def vallado_history(monkeypatch):
    """Every day of the history in Vallado's air (no 35-s MSIS build): the law's plumbing."""
    first, last = orbit_mean.history_span()
    n = int((last - first).astype(int)) + 1
    table = np.tile([atmosphere.density(h) for h in orbit_mean.NODES], (n, 1))
    monkeypatch.setattr(orbit_mean, "history", lambda progress=False: table)


@pytest.mark.parametrize("args, message", [
    (["--from", "300:800"], "--from 300:800: expected LOW:HIGH:N"),
    (["--from", "100:800:3"], "--from: 100:800 km must satisfy re-entry 120 km < LOW <= HIGH <= 1000 km"),
    (["--from", "300:1200:3"], "--from: 300:1200 km must satisfy"),
    (["--from", "500:300:3"], "--from: 500:300 km must satisfy"),
    (["--from", "300:800:0"], "--from: N = 0 must be a whole number 1..200"),
    (["--from", "300:800:1"], "--from: N = 1 needs LOW = HIGH"),
    (["--n", "0"], "--n"),
    (["--max-years", "5000"], "--max-years 5000: at most 1000 years"),
    (["--line-length", "-1"], "--line-length"),
    (["--from", "300:500:3", "--runs", "4"], "--runs 4: at most the 3 altitudes of --from"),
    (["--runs", "21"], "--runs"),
    (["--model", "free"], "--model"),
])
def test_bad_input_is_refused_in_one_line_naming_the_option(args, message, capsys, tmp_path):
    try:
        code = main(["deorbit", "satI", *args, "--out", str(tmp_path)])
    except SystemExit as e:  # argparse's own refusals
        code = e.code
    assert code == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("tethersim: error:")
    assert message in err


def test_a_small_run_writes_its_table_plot_and_verdicts(vallado_history, capsys, tmp_path):
    assert main(["deorbit", "satI", "--from", "300:500:3", "--n", "7", "--quiet",
                 "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "trails below" in out and "verdicts: met = P90" in out
    rows = list(csv.DictReader((tmp_path / "deorbit.csv").read_text().splitlines()))
    assert [float(r["altitude_km"]) for r in rows] == [300.0, 400.0, 500.0]
    for r in rows:
        # the same air every day: every epoch's life is the same, and the ratio is B's
        assert float(r["with_p10_years"]) == pytest.approx(float(r["with_p90_years"]), rel=1e-6)
        assert float(r["ratio_p50"]) == pytest.approx((2.0 * 13.15 / 116) / (2.0 * 1.15 / 115),
                                                      rel=1e-6)
    lives = list(csv.DictReader((tmp_path / "lifetimes.csv").read_text().splitlines()))
    assert len(lives) == 3 * 7
    assert (tmp_path / "deorbit.png").stat().st_size > 10_000


def test_coupled_runs_write_their_table_and_lines(vallado_history, capsys, tmp_path):
    assert main(["deorbit", "satI", "--from", "200:800:4", "--n", "3", "--runs", "2",
                 "--periods", "1", "--model", "derived", "--quiet", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert out.count(" km ok: trail ") == 2
    rows = list(csv.DictReader((tmp_path / "runs.csv").read_text().splitlines()))
    assert [float(r["altitude_km"]) for r in rows] == [200.0, 800.0]  # the ends of --from
    # SatI at 200 km trails level behind, as the closed form says (epsilon >> 1)
    assert float(rows[0]["epsilon"]) > 1 and float(rows[0]["trail_angle_deg"]) > 80
    assert float(rows[0]["closed_form_angle_deg"]) == 90.0


@pytest.mark.slow  # the real orbit-mean history: built once (~35 s) where the cache lacks it
def test_a_run_in_the_real_history_gives_ordered_quantiles_and_a_balloon_that_shortens_life(
        capsys, tmp_path):
    assert main(["deorbit", "satI", "--from", "350:500:2", "--n", "9", "--quiet",
                 "--out", str(tmp_path)]) == 0
    rows = list(csv.DictReader((tmp_path / "deorbit.csv").read_text().splitlines()))
    for r in rows:
        for k in ("with", "without"):
            p10, p50, p90 = (float(r[f"{k}_{p}_years"]) for p in ("p10", "p50", "p90"))
            assert p10 <= p50 <= p90
        # the same epoch with a ~11x larger B: several times shorter, not exactly 11x (the
        # host alone lives through more of the solar cycle)
        assert 3 < float(r["ratio_p50"]) < 20
    assert float(rows[0]["with_p50_years"]) < float(rows[1]["with_p50_years"])
