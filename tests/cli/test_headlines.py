"""tethersim/cli/headlines.py: help text and the cases it names."""
from __future__ import annotations

import pytest

from tethersim.cli import headlines
from tethersim.cli.main import main


def test_headlines_help_has_no_doubled_percent_signs(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["headlines", "--help"])
    assert exc.value.code == 0
    text = capsys.readouterr().out
    assert "%%" not in text
    assert "E1 +50 % tumble" in " ".join(text.split())  # the description's percent
    assert "E1+50%," in text  # the --cases help's percent


def test_help_case_names_are_the_experiments_cases():
    from tethersim.experiments.headlines import BY_NAME
    assert headlines.CASES == tuple(BY_NAME)


def test_headlines_without_out_writes_under_the_satellites_folder(in_tmp, cli):
    code, _out, err = cli(["headlines", "--cases", "nominal", "--models", "derived",
                          "--periods", "0.05", "--no-plots", "--quiet"])
    assert code == 0, err
    folder = in_tmp / "results" / "satI" / "headlines"
    assert (folder / "headlines.csv").is_file() and (folder / "satellite.json").is_file()


def test_headlines_tiny_case_exits_zero_and_writes(tmp_path, cli):
    out = tmp_path / "hl"
    code, stdout, _ = cli(["headlines", "--cases", "nominal", "--models", "derived",
                           "--periods", "0.2", "--out", str(out), "--quiet"])
    assert code == 0
    assert "nominal" in stdout and "thesis" in stdout
    assert (out / "headlines.csv").read_text().splitlines()[0].startswith("case,")
    assert (out / "headlines_verdicts.csv").is_file()
    assert (out / "headlines_nominal.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_headlines_rejects_an_unknown_case(tmp_path, cli):
    code, _, err = cli(["headlines", "--cases", "no-such-case", "--out", str(tmp_path),
                        "--quiet"])
    assert code == 2
    assert "allowed values" in err and "no-such-case" in err
