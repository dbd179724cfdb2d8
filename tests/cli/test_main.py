"""tethersim/cli/main.py: the parser of every command, --version, and the one place where
errors and interruptions become one line and an exit code."""
from __future__ import annotations

import subprocess
import sys
from importlib import resources

import pytest

from tethersim._version import __version__
from tethersim.cli.main import COMMANDS, main
from tethersim.cli.main import main as console_main

SATI_TEXT = (resources.files("tethersim.model.presets") / "satI.toml").read_text()
NAMES = ("run", "validate", "show", "equilibrium", "compare", "forces", "sweep", "tune",
         "report", "headlines", "feasibility", "design", "mc", "deorbit", "deploy")


def test_version_prints_the_package_version(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"tethersim {__version__}"


def test_console_script_main_is_the_cli_main():
    assert console_main is main  # pyproject: tethersim = "tethersim.cli:main"


def test_every_command_has_its_module_with_add_parser_run_and_a_docstring():
    assert tuple(c.__name__.rsplit(".", 1)[1] for c in COMMANDS) == NAMES
    for c in COMMANDS:
        assert callable(c.add_parser) and callable(c.run), c.__name__
        assert c.__doc__ and c.__doc__.startswith(f"``tethersim {c.__name__.rsplit('.')[-1]}``")
        assert "Parameters" in c.run.__doc__ and "Returns" in c.run.__doc__


def test_no_cli_module_is_over_400_lines():
    import tethersim.cli as pkg
    for path in resources.files(pkg).iterdir():
        if path.name.endswith(".py"):
            assert len(path.read_text().splitlines()) <= 400, path.name


@pytest.mark.parametrize("argv", [["--help"], *([n, "--help"] for n in NAMES)])
def test_help_of_every_command_exits_zero(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 0
    assert "usage: tethersim" in capsys.readouterr().out


def test_no_command_is_a_one_line_usage_error(cli):
    code, _out, err = cli([])
    assert code == 2
    assert err.startswith("tethersim: error:") and err.count("\n") == 1
    assert "COMMAND" in err or "command" in err
    assert "tethersim --help" in err  # where to look for the usage


def _bad_toml(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(SATI_TEXT.replace("m1 = 10.0", "m1 = -10.0"))
    return path


# every bad input: (argv, words the one line must hold: the option and the allowed range)
BAD_INPUT = {
    "run-unknown-preset": (["run", "satIII"], ["unknown preset", "satIII", "satII"]),
    "show-unknown-preset": (["show", "nosuchsat"], ["unknown preset"]),
    "validate-unknown-preset": (["validate", "satI", "nosuchsat"], ["unknown preset"]),
    "show-bad-toml": (["show", "BAD_TOML"], ["m1", "> 0"]),
    "run-bad-toml": (["run", "BAD_TOML"], ["m1", "> 0"]),
    "show-missing-toml": (["show", "MISSING_TOML"], ["cannot read"]),
    "run-periods-0": (["run", "satI", "--periods", "0"], ["--periods", "> 0", "got 0"]),
    "run-periods-nan": (["run", "satI", "--periods", "nan"], ["--periods", "finite"]),
    "run-periods-text": (["run", "satI", "--periods", "ten"], ["--periods", "'ten'"]),
    "run-steps-0": (["run", "satI", "--method", "rk4", "--steps", "0"], ["--steps", ">= 1"]),
    "run-steps-float": (["run", "satI", "--steps", "2.5"], ["--steps", "integer"]),
    "run-rtol-tiny": (["run", "satI", "--rtol", "1e-20"], ["--rtol", "1e-14"]),
    "run-model": (["run", "satI", "--model", "newtonian"], ["--model", "derived"]),
    "run-method": (["run", "satI", "--method", "euler"], ["--method", "rk4"]),
    "run-faithful-located": (["run", "satI", "--faithful", "--locate-switches"],
                             ["--faithful", "--locate-switches"]),
    "run-faithful-adaptive": (["run", "satI", "--faithful", "--method", "adaptive"],
                              ["--faithful", "--method adaptive"]),
    "run-set-unknown": (["run", "satI", "--set", "E9=1"], ["E9", "allowed", "E1"]),
    "run-set-negative": (["run", "satI", "--set", "E1=-1"], ["--set", "E1"]),
    "run-set-syntax": (["run", "satI", "--set", "E1"], ["--set", "NAME=VALUE"]),
    "run-unknown-option": (["run", "satI", "--bogus"], ["--bogus"]),
    "run-no-satellite": (["run"], ["satellite", "required"]),
    "compare-models": (["compare", "satI", "--models", "derived,newtonian"],
                       ["--models", "newtonian", "printed"]),
    "forces-periods": (["forces", "satI", "--periods", "-1"], ["--periods", "> 0"]),
    "sweep-workers": (["sweep", "satI", "--E1", "0.004", "--workers", "0"],
                      ["--workers", ">= 1"]),
    "sweep-no-grid": (["sweep", "satI"], ["one or two grids"]),
    "report-grid": (["report", "--grid", "1"], ["--grid", "2..201"]),
    "tune-E1": (["tune", "satI", "--E1", "0"], ["--E1", "> 0"]),
    "headlines-cases": (["headlines", "--cases", "nope"], ["--cases", "allowed", "nominal"]),
    "validate-periods": (["validate", "--periods", "0"], ["--periods", "> 0"]),
}


@pytest.mark.parametrize("argv, words", BAD_INPUT.values(), ids=BAD_INPUT.keys())
def test_bad_input_exits_2_with_one_line_naming_the_option(argv, words, tmp_path, cli,
                                                           monkeypatch):
    monkeypatch.chdir(tmp_path)  # a default output folder would land here
    argv = [str(_bad_toml(tmp_path)) if a == "BAD_TOML"
            else str(tmp_path / "missing.toml") if a == "MISSING_TOML" else a for a in argv]
    code, _out, err = cli(argv)
    assert code == 2
    assert err.startswith("tethersim: error:")
    assert err.count("\n") == 1, err
    assert "Traceback" not in err
    for w in words:
        assert w in err, (w, err)
    assert not (tmp_path / "results").exists()  # refused before anything was written


def test_ctrl_c_prints_one_line_and_exits_130(cli, monkeypatch):
    from tethersim.cli import options

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(options, "satellite", interrupted)
    code, _out, err = cli(["show", "satI"])
    assert code == 130
    assert err == "tethersim: interrupted\n"


def test_interrupted_sweep_says_how_to_continue(cli, monkeypatch, tmp_path):
    from tethersim.experiments import sweep as sweep_pkg

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(sweep_pkg, "run_sweep", interrupted)
    code, _out, err = cli(["sweep", "satI", "--E1", "0.004", "--periods", "0.05", "--quiet",
                          "--out", str(tmp_path / "s")])
    assert code == 130
    assert err.count("\n") == 1
    assert err.startswith("tethersim: interrupted") and "run the same command again" in err


def test_console_entry_point_prints_warning_and_error_to_stderr(tmp_path):
    # the real process, python -m tethersim: exit codes and stderr as a user sees them
    proc = subprocess.run(
        [sys.executable, "-m", "tethersim", "run", "satI", "--faithful", "--periods", "5",
         "--steps", "50", "--no-plots", "--no-check", "--quiet", "--out", str(tmp_path)],
        check=False, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1
    assert "RK4StepWarning" in proc.stderr
    assert "Traceback" not in proc.stderr
    proc = subprocess.run([sys.executable, "-m", "tethersim", "run", "satI", "--periods", "0"],
                          check=False, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert proc.stderr.startswith("tethersim: error: argument --periods:")
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr


def test_a_command_without_a_sweep_leaves_xarray_and_zarr_unloaded():
    # `tethersim run` needs neither xarray nor zarr (0.3 s of a warm 2 s run); only the
    # commands that open a sweep store load them
    code = ("import contextlib, io, sys; from tethersim.cli.main import main\n"
            "with contextlib.redirect_stdout(io.StringIO()): main(['show', 'satI'])\n"
            "print(sorted(k for k in ('xarray', 'zarr', 'pandas') if k in sys.modules))")
    proc = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True,
                          text=True, timeout=120)
    assert proc.stdout.strip() == "[]"


def test_sweep_interrupted_is_a_keyboard_interrupt():
    # so the CLI's Ctrl-C branch handles it without importing the sweep package
    from tethersim.experiments.sweep import SweepInterrupted

    assert issubclass(SweepInterrupted, KeyboardInterrupt)
