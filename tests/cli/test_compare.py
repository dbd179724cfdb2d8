"""tethersim/cli/compare.py: the comparison's files, table, overrides and integrator."""
from __future__ import annotations

import csv

import pytest

from tests.tiers import VARIANT_LOOP
from tethersim.analysis.classify import CLASSES
from tethersim.cli.main import main
from tethersim.model.registry import THESIS_VARIANTS as MODEL_NAMES

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@VARIANT_LOOP
def test_compare_writes_png_and_csv_and_prints_the_table(tmp_path, capsys):
    out = tmp_path / "cmp"
    code = main(["compare", "satI", "--periods", "1", "--out", str(out), "--quiet"])
    stdout = capsys.readouterr().out
    assert code == 0
    assert (out / "compare.png").read_bytes()[:8] == PNG_MAGIC
    rows = _read_csv(out / "compare.csv")
    assert [r["model"] for r in rows] == list(MODEL_NAMES)  # default: all four, in order
    for header in ("mean pitch [rad]", "steady-state pitch [rad]", "settling time [h]",
                   "tumbled", "upside down", "trail delta_x [m]", "converged",
                   "estimated final error theta [rad]", "class", "status"):
        assert header in rows[0], header
    assert all(r["status"] == "ok" and r["converged"] == "true" for r in rows)
    assert all(r["class"] in CLASSES for r in rows)
    assert float(rows[0]["max |theta - theta_first| [rad]"]) == 0.0
    # the trail is near the SatI equilibrium, 28.9 m in the wake (README)
    assert all(abs(float(r["trail delta_x [m]"]) - 28.9) < 0.1 for r in rows)
    for m in MODEL_NAMES:
        assert m in stdout
    for text in ("steady-state pitch [rad]", "compare.png", "compare.csv"):
        assert text in stdout
    assert "all variants end" in stdout or "outcome classes differ" in stdout


@VARIANT_LOOP
def test_compare_applies_overrides_to_every_model(tmp_path, capsys):
    """--set c2=0 removes erratum E1: printed then tracks derived (θ to ~1e-10 rad)."""
    argv = ["compare", "satI", "--models", "derived,printed", "--periods", "1", "--quiet"]
    assert main(argv + ["--set", "c2=0", "--out", str(tmp_path / "a")]) == 0
    assert main(argv + ["--out", str(tmp_path / "b")]) == 0
    capsys.readouterr()
    with_set = _read_csv(tmp_path / "a" / "compare.csv")
    without = _read_csv(tmp_path / "b" / "compare.csv")
    key = "max |theta - theta_first| [rad]"
    assert float(with_set[1][key]) < 1e-9
    assert float(without[1][key]) > 1e-3


def test_compare_faithful_uses_fixed_step_rk4(tmp_path, capsys):
    # the default model alone: a variant's loop is slow-tier (tests/tiers.py)
    code = main(["compare", "satI", "--models", "derived", "--periods", "1",
                 "--faithful", "--steps", "300", "--out", str(tmp_path), "--quiet"])
    stdout = capsys.readouterr().out
    assert code == 0
    assert "RK4, fixed step 17.7 s (faithful)" in stdout  # 5309.64 s / 300
    assert len(_read_csv(tmp_path / "compare.csv")) == 1


def test_compare_unknown_model_exits_2_naming_allowed_values(tmp_path, capsys):
    code = main(["compare", "satI", "--models", "derived,newtonian", "--periods", "1",
                 "--out", str(tmp_path / "out"), "--quiet"])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert err.startswith("tethersim: error:") and "\n" not in err
    assert "newtonian" in err
    for m in MODEL_NAMES:
        assert m in err
    assert not (tmp_path / "out").exists()  # checked before anything ran or was written


def test_compare_help_exits_zero(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["compare", "--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert "--models" in out and "--scale" in out



def test_compare_faithful_without_steps_runs_at_the_thesis_ch5_step(in_tmp, cli):
    code, out, err = cli(["compare", "satI", "--models", "derived", "--periods",
                          "0.05", "--faithful", "--quiet"])
    assert code == 0, err
    assert "RK4, fixed step 26.55 s (faithful)" in out  # the runs' own label
    assert "RK4 step 26.55 s (200 per orbit, thesis ch. 5; 10 steps)" in out
    assert (in_tmp / "results" / "satI" / "compare" / "compare.csv").is_file()
