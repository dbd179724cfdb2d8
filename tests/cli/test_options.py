"""tethersim/cli/options.py: each shared option means the same in every command."""
from __future__ import annotations

import argparse
import json

import pytest

from tethersim.cli import options
from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD, STEPS_PER_PERIOD
from tethersim.model.presets import load_preset

from .conftest import QUICK

SATI_PERIOD = load_preset("satI").period  # 5309.64 s at 200 km (facts.md)
THESIS_STEP = "RK4 step 26.55 s (200 per orbit, thesis ch. 5"


def _args(**kw):
    base = {"periods": 50.0, "faithful": False, "method": None, "steps": None,
            "locate_switches": False, "rtol": 1e-10}
    return argparse.Namespace(**{**base, **kw})


def test_faithful_is_rk4_at_the_thesis_chapter_5_step_without_switches():
    how = options.integrator(_args(faithful=True))
    assert FAITHFUL_STEPS_PER_PERIOD == 200
    assert (how.method, how.steps, how.locate) == ("rk4", 10_000, False)  # 50 orbits, p. 5-7
    assert SATI_PERIOD * 50 / how.steps == pytest.approx(26.55, abs=0.005)
    assert how.describe(SATI_PERIOD, 50.0) == (
        "RK4 step 26.55 s (200 per orbit, thesis ch. 5; 10000 steps), switches not located")


def test_faithful_with_steps_uses_the_given_steps_and_does_not_claim_the_thesis_step():
    how = options.integrator(_args(faithful=True, periods=5.0, steps=1500))
    assert (how.method, how.steps, how.locate) == ("rk4", 1500, False)
    assert how.describe(SATI_PERIOD, 5.0).startswith("RK4 step 17.70 s (300 per orbit; 1500")
    assert "thesis" not in how.describe(SATI_PERIOD, 5.0)


def test_method_rk4_alone_keeps_the_engine_default_and_may_locate_switches():
    how = options.integrator(_args(method="rk4", periods=2.0, locate_switches=True))
    assert how.steps == 2 * STEPS_PER_PERIOD and how.locate and not how.faithful
    assert how.describe(SATI_PERIOD, 2.0).endswith("switches located")


def test_adaptive_default_locates_switches_and_steps_mean_output_samples():
    how = options.integrator(_args(steps=77, rtol=1e-9))
    assert (how.method, how.steps, how.samples, how.locate) == ("adaptive", None, 77, True)
    assert how.describe(SATI_PERIOD, 1.0) == "DOP853 adaptive, rtol 1e-09, switches located"


@pytest.mark.parametrize("kw, words", [
    ({"method": "adaptive"}, "--method adaptive"),
    ({"locate_switches": True}, "--locate-switches"),
])
def test_faithful_refuses_contradicting_options(kw, words):
    with pytest.raises(options.UsageError, match=words):
        options.integrator(_args(faithful=True, **kw))


def test_faithful_prints_the_same_step_in_run_compare_forces_and_sweep(cli, tmp_path):
    # issue 9: --faithful meant 17.7 s in run/compare and 26.55 s in forces/sweep
    argvs = {
        "run": ["run", "satI", "--no-plots", "--no-check"],
        "compare": ["compare", "satI", "--models", "derived"],
        "forces": ["forces", "satI"],
        "sweep": ["sweep", "satI", "--E1", "0.004", "--no-plots"],
    }
    lines = {}
    for name, argv in argvs.items():
        code, out, err = cli([*argv, "--faithful", *QUICK, "--out", str(tmp_path / name)])
        assert code == 0, (name, err)
        lines[name] = [ln for ln in out.splitlines() if "RK4 step" in ln]
        assert len(lines[name]) == 1, (name, out)
        assert THESIS_STEP in lines[name][0], (name, lines[name][0])
        assert "switches not located" in lines[name][0], name
    steps = {n: ls[0][ls[0].index("RK4 step"):].split(",")[0] for n, ls in lines.items()}
    assert len(set(steps.values())) == 1, steps
    # and the runs really used it: run's record and compare's label
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["integrator"].startswith(THESIS_STEP)
    assert "fixed step 26.55 s" in summary["label"]


@pytest.mark.parametrize("arg, key", [
    ("satI", "satI"), ("SATII", "satII"), ("DumbSat", "dumbsat"),
    ("some/where/mine.toml", "mine"), ("my sat (v2)!.toml", "my_sat__v2__"),
])
def test_satellite_key_is_the_preset_or_toml_name_sanitised(arg, key):
    assert options.satellite_key(arg) == key


def test_default_out_is_one_folder_per_satellite():
    args = argparse.Namespace(satellite="SATII")
    assert options.default_out(args).as_posix() == "results/satII"
    assert options.default_out(args, "compare").as_posix() == "results/satII/compare"


def _claim_args(satellite="satI", sets=(), force=False):
    return argparse.Namespace(satellite=satellite, set=list(sets), scale=[], force=force)


def test_claim_folder_refuses_another_satellites_results_naming_both(tmp_path):
    a = _claim_args("satI")
    options.write_provenance(tmp_path, options.claim_folder(tmp_path, a, load_preset("satI")))
    options.claim_folder(tmp_path, a, load_preset("satI"))  # the same satellite again: fine
    b = _claim_args("satII")
    with pytest.raises(options.UsageError) as info:
        options.claim_folder(tmp_path, b, load_preset("satII"))
    msg = str(info.value)
    assert "SatI (satI)" in msg and "SatII (satII)" in msg
    assert "--out" in msg and "--force" in msg and "\n" not in msg
    forced = _claim_args("satII", force=True)
    assert options.claim_folder(tmp_path, forced, load_preset("satII"))["satellite"] == "SatII"


def test_claim_folder_refuses_other_overrides(tmp_path):
    sat = load_preset("satI")
    options.write_provenance(tmp_path, options.claim_folder(tmp_path, _claim_args(), sat))
    with pytest.raises(options.UsageError, match="--set E1=0.005"):
        options.claim_folder(tmp_path, _claim_args(sets=["E1=0.005"]), sat)


def test_claim_folder_refuses_a_summary_without_a_record(tmp_path):
    (tmp_path / "summary.json").write_text('{"label": "SatII, model derived"}')
    with pytest.raises(options.UsageError, match="unrecorded satellite"):
        options.claim_folder(tmp_path, _claim_args(), load_preset("satI"))


def test_int_range_names_the_allowed_range():
    parse = options.int_range(2, 201)
    assert parse("41") == 41
    for bad in ("1", "202", "x"):
        with pytest.raises(argparse.ArgumentTypeError, match=r"an integer in 2\.\.201"):
            parse(bad)


@pytest.mark.parametrize("text", ["0", "-1", "nan", "inf", "x"])
def test_positive_float_refuses(text):
    with pytest.raises(argparse.ArgumentTypeError, match="finite number > 0"):
        options.positive_float(text)


def test_faithful_help_is_declared_once_and_shown_by_each_integrating_command(capsys):
    from tethersim.cli.main import main
    for name in ("run", "compare", "forces", "sweep"):
        with pytest.raises(SystemExit):
            main([name, "--help"])
        text = " ".join(capsys.readouterr().out.split())
        assert "200 steps per orbit (26.55 s at 200 km)" in text, name
