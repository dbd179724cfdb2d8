"""Real (stiff) tethers in plans of many: the implicit scheme's compiled block gives the
records of simulate(method="implicit") then outcome() bit for bit, as the explicit
blocks do theirs (test_sweep_batch.py)."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tethersim.experiments.sweep import Plan, SweepSpec, run_plan, run_point
from tethersim.experiments.sweep.batch import run_block
from tethersim.experiments.sweep.point import STATUS

# the implicit block compiles its own Radau loop (~40 s cold): the slow tier (CI runs it)
pytestmark = pytest.mark.slow

SAT = ts.load_preset("satI")


def _bits(rec):
    return {k: repr(float(v)) for k, v in rec.items()}


def _kevlar(sat, diameter=1e-3):
    t1 = ts.tether_parameters("kevlar49", diameter, sat.l10, sat.m3)
    t2 = ts.tether_parameters("kevlar49", diameter, sat.l20, sat.m3)
    return sat.replace(E1=t1["EA"], c1=t1["c"], E2=t2["EA"], c2=t2["c"],
                       Fb1=t1["breaking_load"], Fb2=t2["breaking_load"])


# lines cut to the thesis's stretched geometry, each point a different line diameter (EA
# 2.2e4 .. 8.8e4 N), in the model whose damper is a line's material loss (the thesis's
# damper turns a real line's boom over at rest: engine/start.py refuses that start)
MODEL = "objective-damper"
STRETCHED = SAT.replace(l10=30.83, l20=28.92)
POINTS = [_kevlar(STRETCHED, d) for d in (0.5e-3, 0.75e-3, 1e-3)]


@pytest.fixture(scope="module")
def plan():
    return Plan(periods=0.05, method="implicit", rtol=1e-6, model=MODEL)


def test_the_implicit_block_gives_simulate_s_records_bit_for_bit(plan):
    recs = run_plan(plan, POINTS, workers=1, progress=False)
    for sat, rec in zip(POINTS, recs):
        spec = SweepSpec(sat, (("A3", [sat.A3]),), periods=plan.periods, method="implicit",
                         rtol=plan.rtol, model=MODEL)
        assert _bits(rec) == _bits(run_point(spec, 0))
        assert rec["status"] == STATUS["ok"] and rec["nfev"] > 0


def test_a_sweep_takes_real_tethers_with_the_implicit_scheme():
    """The explicit schemes refuse the stiff points (test_sweep_stiff_points.py); the
    implicit one sweeps them, the thesis's soft tether too, in one block."""
    spec = SweepSpec(STRETCHED, (("E1", [0.004, 2e4]),), periods=0.02, method="implicit",
                     rtol=1e-6, model=MODEL)
    recs = run_block(spec, [0, 1])
    assert [_bits(r) for _, r in recs] == [_bits(run_point(spec, k)) for k in (0, 1)]
    assert all(math.isclose(r["end_time"], 0.02 * SAT.period, rel_tol=1e-12) for _, r in recs)


def test_the_sweep_command_sweeps_real_tethers_with_method_implicit(tmp_path, capsys):
    from tethersim.cli.main import main

    argv = ["sweep", "satI", "--E1", "0.004,200000", "--set", "l10=30.83", "--set", "l20=28.92",
            "--periods", "0.02", "--rtol", "1e-6", "--workers", "1", "--quiet", "--no-plots",
            "--model", MODEL]
    # DOP853 refuses E1 = 2e5 N (a 1.5 mm Kevlar line)
    assert main([*argv, "--out", str(tmp_path / "a")]) == 2
    assert "--method implicit" in capsys.readouterr().err
    assert main([*argv, "--method", "implicit", "--out", str(tmp_path / "b")]) == 0
    ds = ts.experiments.sweep.open_dataset(tmp_path / "b" / "sweep.zarr")
    assert ds.attrs and int(ds.done.sum()) == 2
    assert "Radau IIA" in capsys.readouterr().out
