"""A free orbit that outlived --max-lifetime has no known end (issue 19): a verdict that
turns on it is "undecided: raise the lifetime cap", never "unstable" or "trim lost"."""
from __future__ import annotations

import csv
import math

from tethersim.analysis.classify import STABLE, UNDECIDED, UNSETTLED
from tethersim.analysis.feasibility import (
    CAPPED,
    FEASIBLE,
    REENTERS,
    TRIM_LOST,
    VERDICTS,
    verdict,
)
from tethersim.analysis.feasibility import UNDECIDED as RUN_LONGER
from tethersim.analysis.metrics import SS_FRACTION, PitchMetrics
from tethersim.analysis.outcome import Outcome
from tethersim.cli.main import main

H = 3600.0
CAP = 10 * H
LONG = 2 * CAP / (1 - SS_FRACTION)  # circular runs that can show a settling past the cap


def _out(settling_h=5.0, cls=STABLE, theta_ss=0.0):
    m = PitchMetrics(mean_pitch=theta_ss, steady_state_pitch=theta_ss,
                     settling_time=settling_h * H, tumbled=False, upside_down=False)
    return Outcome(status="ok", reason="", stability_class=cls, metrics=m, trail_delta_x=29.0,
                   trail_delta_y=0.0, max_force=(math.nan,) * 3, error_estimate=None,
                   converged=None)


UNSETTLED_RUN = _out(settling_h=math.nan, cls=UNSETTLED)


def test_not_settled_within_a_capped_life_is_undecided_not_unstable():
    assert CAPPED in VERDICTS
    assert verdict(math.inf, UNSETTLED_RUN, [_out()], run_s=LONG, cap_s=CAP) == CAPPED
    # the same run with a life that really ended: a fact
    assert verdict(CAP, UNSETTLED_RUN, [_out()], run_s=LONG, cap_s=CAP) == REENTERS


def test_a_trim_not_settled_within_a_capped_life_is_undecided_not_lost():
    trim = _out(settling_h=math.nan, cls=UNSETTLED, theta_ss=0.01)
    assert verdict(math.inf, _out(), [trim], run_s=LONG, cap_s=CAP) == CAPPED
    assert verdict(CAP, _out(), [trim], run_s=LONG, cap_s=CAP) == TRIM_LOST


def test_what_the_capped_life_already_shows_is_still_decided():
    assert verdict(math.inf, _out(), [_out()], run_s=LONG, cap_s=CAP) == FEASIBLE
    assert verdict(math.inf, _out(), [_out(theta_ss=0.3)], run_s=LONG, cap_s=CAP) == TRIM_LOST


def test_a_nominal_run_too_short_for_a_class_is_undecided_whatever_the_cap():
    short = _out(settling_h=0.01, cls=UNDECIDED)
    for life in (math.inf, 0.1 * H):
        assert verdict(life, short, [short], run_s=0.1 * H, cap_s=0.1 * H) == RUN_LONGER


def test_feasibility_with_a_cap_shorter_than_the_run_is_not_unstable(tmp_path, capsys):
    """Issue 19: `--periods 0.1 --max-lifetime 0.1` at 200 km said "unstable"."""
    rows = {}
    for periods, name in (("0.1", "short"), ("3", "capped")):
        out = tmp_path / name
        assert main(["feasibility", "satI", "--altitude", "200", "--periods", periods,
                     "--max-lifetime", "0.1", "--solar", "min", "--out", str(out),
                     "--quiet"]) == 0
        with (out / "feasibility.csv").open() as fh:
            (rows[name],) = list(csv.DictReader(fh))
    assert rows["short"]["verdict"] == RUN_LONGER  # 0.1 orbit: no class yet
    assert rows["capped"]["verdict"] == CAPPED
    assert rows["capped"]["reentry_capped"] == "true"
    assert "outlived --max-lifetime 0.1 h" in capsys.readouterr().out
