"""Feasibility verdicts that do not depend on how they were asked (issue 19): long enough
to decide or "undecided: run longer"; "sensitive" when two tolerances disagree; balloon
lost and re-entry reported apart; grids capped like the sweep's."""
from __future__ import annotations

import csv
import math

import pytest

from tethersim.analysis.classify import OFFSET, STABLE, TUMBLING, UNSETTLED
from tethersim.analysis.feasibility import (
    CAPPED,
    LOST,
    REENTERS,
    SENSITIVE,
    TRIM_LOST,
    UNDECIDED,
    UNSTABLE,
    VERDICTS,
    combine,
    periods_to_decide,
    verdict,
)
from tethersim.analysis.metrics import SS_FRACTION, PitchMetrics, long_enough
from tethersim.analysis.outcome import Outcome
from tethersim.cli.main import main

H = 3600.0
NAN3 = (math.nan,) * 3


def _out(theta_ss=0.0, settling_h=40.0, cls=STABLE, tumbled=False):
    m = PitchMetrics(mean_pitch=theta_ss, steady_state_pitch=theta_ss,
                     settling_time=settling_h * H, tumbled=tumbled, upside_down=False)
    return Outcome(status="ok", reason="", stability_class=cls, metrics=m, trail_delta_x=29.0,
                   trail_delta_y=0.0, max_force=NAN3, error_estimate=None, converged=None)


UNSETTLED_RUN = _out(settling_h=math.nan, cls=UNSETTLED)
WINDOW = 1 - SS_FRACTION  # the share of a run in which the settling criterion sees settling


@pytest.mark.parametrize("lost", [False, True])
def test_a_run_too_short_to_see_a_settling_is_undecided_not_unstable(lost):
    life = 100 * H
    short = life / WINDOW - H  # sees a settling up to just before the end of life
    assert verdict(life, UNSETTLED_RUN, [_out()], run_s=short, lost=lost) == UNDECIDED
    # long enough: not settled while it lasted is then a fact, named by how it ended
    long = life / WINDOW + H
    assert verdict(life, UNSETTLED_RUN, [_out()], run_s=long, lost=lost) == \
        (LOST if lost else REENTERS)


def test_a_life_past_the_cap_is_decided_against_the_cap():
    cap = 240 * H
    assert verdict(math.inf, UNSETTLED_RUN, [_out()], run_s=75 * H, cap_s=cap) == UNDECIDED
    # not settled within the cap, but the life goes on past it: not a fact (issue 19)
    assert verdict(math.inf, UNSETTLED_RUN, [_out()], run_s=cap / WINDOW, cap_s=cap) == CAPPED


def test_a_tumble_decides_at_any_run_length():
    tumbled = _out(cls=TUMBLING, tumbled=True)
    assert verdict(100 * H, tumbled, [_out()], run_s=H) == UNSTABLE


def test_a_settled_run_decides_at_any_run_length():
    assert verdict(10 * H, _out(settling_h=40), [_out()], run_s=50 * H) == REENTERS
    assert verdict(10 * H, _out(settling_h=40), [_out()], run_s=50 * H, lost=True) == LOST


def test_an_unsettled_trim_run_needs_the_run_to_cover_the_life():
    life = 100 * H
    trim = _out(0.01, settling_h=math.nan, cls=UNSETTLED)
    assert verdict(life, _out(settling_h=5), [trim], run_s=life / WINDOW - H) == UNDECIDED
    assert verdict(life, _out(settling_h=5), [trim], run_s=life / WINDOW + H) == TRIM_LOST
    # a settled trim outside the band is lost whatever the length
    assert verdict(life, _out(settling_h=5), [_out(0.2, cls=OFFSET)], run_s=H) == TRIM_LOST


@pytest.mark.parametrize("horizon_h, period_h", [(2.23, 1.474), (12.5, 1.474), (240, 1.6),
                                                 (0.8 * 1.5 * 7, 1.5)])
def test_periods_to_decide_is_the_fewest_orbits_whose_window_covers_the_horizon(horizon_h,
                                                                                 period_h):
    n = periods_to_decide(horizon_h * H, period_h * H)
    assert WINDOW * n * period_h >= horizon_h - 1e-9
    assert long_enough(n)  # and long enough to have a class at all (issue 19)
    assert WINDOW * (n - 1) * period_h < horizon_h or not long_enough(n - 1)


def test_verdicts_that_differ_between_tolerances_are_sensitive():
    assert combine([UNSTABLE, UNSTABLE]) == UNSTABLE
    assert combine([UNSTABLE, TRIM_LOST]) == SENSITIVE
    assert SENSITIVE in VERDICTS and UNDECIDED in VERDICTS


def test_a_point_row_reports_a_flip_between_tolerances_as_sensitive(monkeypatch):
    from tethersim.experiments import feasibility as fe
    from tethersim.model.presets import load_preset
    from tethersim.output.plots.feasibility import _marker

    spec = fe.FeasibilitySpec(load_preset("satI"), (300.0,), solar=("mean",), periods=2,
                              max_lifetime_h=1)
    seen = []

    def fake(spec_, h, a3, rtol):  # the 300 km case of issue 19: upright at one rtol only
        seen.append(rtol)
        ends = {"lost": math.nan, "reentry": math.inf, "life": math.inf, "end": "capped",
                "end_altitude": 3e5}
        out = _out(2.557 if rtol == spec.rtol else 0.587)
        return {"ends": ends, "nominal": out, "trims": {"mean": out}, "scales": {"mean": 1.0},
                "verdict": UNSTABLE if rtol == spec.rtol else TRIM_LOST, "period": 5400.0}

    monkeypatch.setattr(fe, "_decide", fake)
    monkeypatch.setattr(fe, "free_ends", lambda *a: {"lost": math.nan, "reentry": math.inf})
    a3 = spec.satellite.A3
    row = fe.point_row(spec, 300.0, a3,
                       {k: task() for k, task in fe.point_tasks(spec, 300.0, a3).items()})
    assert seen == [spec.rtol, spec.rtol / fe.CHECK_FACTOR]
    assert row["verdict"] == SENSITIVE
    assert (row["verdict_rtol"], row["verdict_check_rtol"]) == (UNSTABLE, TRIM_LOST)
    assert row["theta_ss_rad"] == 2.557 and row["theta_ss_check_rad"] == 0.587
    assert _marker(row) == "D" and _marker({**row, "verdict": UNSTABLE}) != "D"


def test_the_check_tolerance_stays_within_double_precision():
    from tethersim.experiments.feasibility import MIN_RTOL, FeasibilitySpec
    from tethersim.model.presets import load_preset
    sat = load_preset("satI")
    assert FeasibilitySpec(sat, (200.0,), rtol=1e-10).check_rtol == pytest.approx(1e-12)
    assert FeasibilitySpec(sat, (200.0,), rtol=1e-13).check_rtol == pytest.approx(1e-11)
    with pytest.raises(ValueError, match="rtol"):
        FeasibilitySpec(sat, (200.0,), rtol=MIN_RTOL / 10)


def test_five_orbits_at_200_km_decide_that_the_balloon_is_lost_first(tmp_path):
    """Issue 19: `--periods 5` called 200 km "unstable".  The free orbit loses its balloon
    after ~2.2 h, within what 5 orbits can show, so not settling is decided."""
    out = tmp_path / "f"
    assert main(["feasibility", "satI", "--altitude", "200,250", "--periods", "5",
                 "--max-lifetime", "20", "--solar", "mean", "--out", str(out), "--quiet"]) == 0
    with (out / "feasibility.csv").open() as fh:
        r200, r250 = list(csv.DictReader(fh))
    assert r200["verdict"] == LOST
    assert r200["free_end"] == "left-domain" and r200["nominal_status"] == "ok"
    lost, reentry = float(r200["balloon_lost_h"]), float(r200["reentry_h"])
    assert 0 < lost < reentry < 20 and r200["reentry_capped"] == "false"
    # 250 km: the balloon lasts longer than 5 orbits can judge; the run says how long to run
    assert r250["verdict"] == UNDECIDED
    needed = int(r250["periods_to_decide"])
    assert needed > 5
    assert float(r250["balloon_lost_h"]) <= WINDOW * needed * _period_h(250.0)
    assert float(r250["balloon_lost_h"]) > WINDOW * (needed - 1) * _period_h(250.0)


def _period_h(h_km: float) -> float:
    from tethersim.model.presets import load_preset
    return load_preset("satI").replace(altitude=h_km * 1e3).period / 3600


def test_a_huge_feasibility_grid_is_refused_at_once_in_one_line(capsys):
    import time
    t0 = time.perf_counter()
    assert main(["feasibility", "satI", "--altitude", "200:400:100000", "--out",
                 "/nonexistent/never-written"]) == 2
    err = capsys.readouterr().err.strip()
    assert time.perf_counter() - t0 < 5
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    assert "--altitude" in err and "TETHERSIM_MAX_SWEEP_POINTS" in err


def test_the_feasibility_cap_counts_runs_per_point(monkeypatch):
    from tethersim.engine.guards import SizeLimitError
    from tethersim.experiments.feasibility import FeasibilitySpec
    from tethersim.model.presets import load_preset
    sat = load_preset("satI")
    per_point = FeasibilitySpec(sat, (200.0,)).runs_per_point()
    monkeypatch.setenv("TETHERSIM_MAX_SWEEP_POINTS", str(2 * per_point))
    FeasibilitySpec(sat, (200.0, 210.0))  # exactly at the cap
    with pytest.raises(SizeLimitError, match="3 points x .* runs.*--altitude"):
        FeasibilitySpec(sat, (200.0, 210.0, 220.0))
    with pytest.raises(SizeLimitError, match="--altitude and --A3"):
        FeasibilitySpec(sat, (200.0, 210.0), areas=(10.0, 12.0))


def test_a_point_stopped_by_ctrl_c_is_not_recorded(monkeypatch, tmp_path):
    from dataclasses import replace

    from tethersim.experiments import feasibility as fe
    from tethersim.model.presets import load_preset

    spec = fe.FeasibilitySpec(load_preset("satI"), (200.0,), solar=("mean",), periods=0.1,
                              max_lifetime_h=0.1)
    real = fe.simulate
    monkeypatch.setattr(fe, "simulate",
                        lambda *a, **k: replace(real(*a, **k), status="interrupted"))
    with pytest.raises(KeyboardInterrupt):
        fe.run_feasibility(spec, tmp_path, workers=2, log=lambda *a: None, progress=False)
    points = tmp_path / fe.POINTS_FILE
    assert not points.exists() or points.read_text() == ""
