"""Feasibility: the verdict logic on constructed outcomes, the runner, the CLI's files."""
from __future__ import annotations

import csv
import json
import math

import pytest

import tethersim as ts
from tethersim.analysis.classify import FAILED, OFFSET, STABLE, TUMBLING, UNSETTLED, UPSIDE_DOWN
from tethersim.analysis.feasibility import VERDICTS, verdict
from tethersim.analysis.metrics import PitchMetrics
from tethersim.analysis.outcome import Outcome
from tethersim.output.plots.feasibility import usable_life_h

NAN3 = (math.nan,) * 3


def _out(theta_ss=0.0, settling_h=40.0, cls=STABLE, status="ok", tumbled=False):
    m = PitchMetrics(mean_pitch=theta_ss, steady_state_pitch=theta_ss,
                     settling_time=settling_h * 3600, tumbled=tumbled,
                     upside_down=cls == UPSIDE_DOWN)
    return Outcome(status=status, reason="" if status == "ok" else status,
                   stability_class=cls, metrics=m, trail_delta_x=29.0, trail_delta_y=0.0,
                   max_force=NAN3, error_estimate=None, converged=None)


H = 3600.0


@pytest.mark.parametrize("life_h, nominal, trims, expected", [
    (100, _out(), [_out(0.01), _out(-0.04)], "feasible"),
    (math.inf, _out(), [_out(0.05)], "feasible"),  # the band's edge is inside
    (10, _out(), [_out()], "re-enters before settling"),
    (39.9, _out(settling_h=40), [_out()], "re-enters before settling"),
    (100, _out(), [_out(0.06, cls=OFFSET)], "trim lost as the air varies"),
    (100, _out(), [_out(-0.2, cls=OFFSET), _out()], "trim lost as the air varies"),
    (100, _out(), [_out(status="diverged", cls=FAILED)], "trim lost as the air varies"),
    (100, _out(), [_out(0.0, cls=TUMBLING, tumbled=True)], "trim lost as the air varies"),
    (100, _out(0.3, cls=OFFSET), [_out()], "trim lost as the air varies"),
    # never settles in a run as long as the life: a fact, named by how the life ends
    (100, _out(settling_h=math.nan, cls=UNSETTLED), [_out()], "re-enters before settling"),
    # ... unless the life outlived the cap: then its end is not known (issue 19)
    (math.inf, _out(settling_h=math.nan, cls=UNSETTLED), [_out()],
     "undecided: raise the lifetime cap"),
    (100, _out(3.0, cls=UPSIDE_DOWN), [_out()], "unstable"),
    (100, _out(status="diverged", cls=FAILED), [_out()], "unstable"),
    (1, _out(cls=TUMBLING, tumbled=True), [_out(0.3, cls=OFFSET)], "unstable"),  # priority
    (1, _out(), [_out(0.3, cls=OFFSET)], "re-enters before settling"),  # priority
])
def test_verdict_logic(life_h, nominal, trims, expected):
    assert expected in VERDICTS
    assert verdict(life_h * H, nominal, trims) == expected


def test_atlas_runs_resumes_and_writes_the_csv(tmp_path, capsys):
    from tethersim.cli.main import main
    out = tmp_path / "f"
    argv = ["feasibility", "satI", "--altitude", "200,300", "--periods", "2",
            "--max-lifetime", "3", "--out", str(out), "--quiet"]
    assert main(argv) == 0
    with (out / "feasibility.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert [float(r["altitude_km"]) for r in rows] == [200.0, 300.0]
    for key in ("altitude_km", "balloon_lost_h", "reentry_h", "settling_h", "verdict"):
        assert key in rows[0]
    assert all(r["verdict"] in VERDICTS for r in rows)
    # 200 km: the balloon is lost before the 3 h cap; 300 km outlives it (capped)
    assert float(rows[0]["balloon_lost_h"]) < 3 and rows[0]["free_end"] == "left-domain"
    assert rows[1]["reentry_capped"] == "true" and float(rows[1]["reentry_h"]) == 3.0
    assert rows[1]["balloon_lost_h"] == ""  # not lost: NaN, written empty
    # the solar-cycle runs are free runs in MSIS air: denser air, shorter usable life
    life = {c: usable_life_h({k: _number(v) for k, v in rows[0].items()}, c)
            for c in ("min", "mean", "max")}
    assert life["max"] < life["mean"] < life["min"] <= 3.0
    assert rows[0]["balloon_lost_max_h"] != ""
    assert (out / "feasibility.png").stat().st_size > 10_000
    # resumable: a finished store is not rerun (its lines are kept byte for byte)
    store = out / "store" / "points.jsonl"
    before = store.read_text()
    assert main(argv) == 0
    assert store.read_text() == before and len(before.splitlines()) == 2
    # another setting in the same store is refused in one line
    capsys.readouterr()
    assert main(argv[:-3] + ["--periods", "3", "--out", str(out), "--quiet"]) != 0
    err = capsys.readouterr().err.strip()
    assert "holds a feasibility atlas of other settings" in err and "\n" not in err


def test_rows_do_not_depend_on_the_threads_that_run_a_points_tasks(tmp_path):
    """run_feasibility puts every point's runs (verdict runs at two tolerances, the solar
    cases' free orbits: point_tasks) in one pool; one thread or two, the rows are the
    same bits and the store holds them in point order."""
    import json

    import tethersim as ts
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    spec = FeasibilitySpec(ts.load_preset("satI"), (200.0, 300.0), periods=2.0,
                           max_lifetime_h=3.0)
    rows = {w: run_feasibility(spec, tmp_path / f"w{w}", workers=w, log=lambda *a: None,
                               progress=False) for w in (1, 2)}
    assert json.dumps(rows[1], sort_keys=True) == json.dumps(rows[2], sort_keys=True)
    stored = [json.loads(line)["altitude_km"]
              for line in (tmp_path / "w2" / "points.jsonl").read_text().splitlines()]
    assert stored == [200.0, 300.0]


def _number(text: str):
    if text in ("true", "false"):
        return text == "true"
    try:
        return float(text) if text else math.nan
    except ValueError:
        return text


def test_density_scales_are_msis_over_vallado():
    from tethersim.experiments.feasibility import solar_scales
    from tethersim.model.air import solar_cycle_densities
    k = solar_scales(200.0)
    rho = solar_cycle_densities(200e3, local_time_h=None)
    assert k["max"] * 2.789e-10 == pytest.approx(rho["max"], rel=1e-12)
    assert k["min"] < k["mean"] < k["max"]


def test_atlas_settings_are_checked_before_any_run():
    from tethersim.experiments.feasibility import FeasibilitySpec
    sat = ts.load_preset("satI")
    with pytest.raises(ValueError, match="solar = high: allowed cases min, mean, max"):
        FeasibilitySpec(sat, (200.0,), solar=("high",))
    with pytest.raises(ts.SatelliteError, match="altitude"):
        FeasibilitySpec(sat, (1500.0,))
    assert json.loads(FeasibilitySpec(sat, (200.0,)).to_json())["areas"] == [12.0]


def _dyneema(sat, lengths=(30.83, 28.92)):
    """SatI on 1 mm Dyneema lines, by default at the thesis's stretched geometry
    (docs/real-tethers.md)."""
    return ts.with_tethers(sat.replace(l10=lengths[0], l20=lengths[1]), "dyneema-sk75", 1e-3)


def test_real_lines_need_the_implicit_scheme_and_say_so_before_any_run(tmp_path):
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    sat = _dyneema(ts.load_preset("satI"), (6.0, 6.0))  # axial period 0.05 s
    with pytest.raises(ValueError) as exc:
        run_feasibility(FeasibilitySpec(sat, (200.0,)), tmp_path / "store")
    assert "method='implicit'" in str(exc.value) and "\n" not in str(exc.value)
    assert not (tmp_path / "store").exists()
    with pytest.raises(ValueError, match="method = 'rk4': allowed values adaptive, implicit"):
        FeasibilitySpec(sat, (200.0,), method="rk4")
    spec = FeasibilitySpec(sat, (200.0,), method="implicit", rtol=1e-6)
    # real lines' runs keep their atol floor (engine/start.py), whatever the rtol
    assert spec.run_options(1e-8)["atol"] == pytest.approx(1e-10)
    assert json.loads(spec.to_json())["method"] == "implicit"
    # an atlas of the default scheme writes the spec it wrote before the option existed
    assert "method" not in json.loads(FeasibilitySpec(ts.load_preset("satI"), (200.0,)).to_json())


@pytest.mark.slow
def test_real_lines_atlas_runs_implicit_and_keeps_its_balloon(tmp_path):
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    spec = FeasibilitySpec(_dyneema(ts.load_preset("satI")), (300.0,), solar=("mean",),
                           periods=0.5, max_lifetime_h=1.0, model="objective-damper",
                           rtol=1e-6, method="implicit")
    (row,) = run_feasibility(spec, tmp_path / "store", log=lambda *a: None, progress=False)
    # a line of a few per cent failure strain is never stretched 20x: the balloon stays on,
    # the free run reaches the cap, and the held circular runs end ok at their trim
    assert math.isnan(row["balloon_lost_h"]) and row["free_end"] == "capped"
    assert row["reentry_capped"] and row["nominal_status"] == "ok"
    assert abs(row["theta_ss_rad"]) < 0.05 and row["verdict"] in VERDICTS


# the implicit block compiles its own Radau loop (~40 s cold): that case in the slow tier
@pytest.mark.parametrize("method", ["adaptive", pytest.param("implicit", marks=pytest.mark.slow)])
def test_a_points_circular_runs_are_one_plan_whose_outcomes_are_simulates(monkeypatch, method):
    """_decide runs the nominal and trim runs as one plan of many (run_satellites, one
    call, no simulate() per run); each outcome it judges equals outcome(simulate()) with
    the atlas's run options, bit for bit, drag make-up included."""
    from tethersim.experiments import feasibility as fe
    from tethersim.experiments.sweep import batch
    spec = fe.FeasibilitySpec(ts.load_preset("satI"), (250.0,), solar=("min", "max"),
                              periods=1.0, max_lifetime_h=0.5, method=method, rtol=1e-8)
    calls, real_run, real_sim = [], batch.run_satellites, fe.simulate

    def circular_not_simulated(sat, *a, **k):
        assert sat.orbit == "free", "a circular run went through simulate()"
        return real_sim(sat, *a, **k)

    monkeypatch.setattr(fe, "run_satellites", lambda plan, sats: calls.append(len(sats))
                        or real_run(plan, sats))
    monkeypatch.setattr(fe, "simulate", circular_not_simulated)
    got = fe._decide(spec, 250.0, spec.satellite.A3, spec.rtol)
    assert calls == [3]
    monkeypatch.undo()
    for out, scale in [(got["nominal"], 1.0), *((got["trims"][c], k) for c, k in
                                                  got["scales"].items())]:
        res = ts.simulate(spec.circular(250.0, spec.satellite.A3, scale), periods=1.0,
                          model=spec.model, progress=False, **spec.run_options(spec.rtol))
        want = ts.outcome(res, forces=False)
        assert (out.status, out.stability_class, repr(out.metrics), repr(out.drag_makeup)) == (
            want.status, want.stability_class, repr(want.metrics), repr(want.drag_makeup))
