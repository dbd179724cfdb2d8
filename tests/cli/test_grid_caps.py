"""Every command's grid is bounded: feasibility by the sweep's cap, headlines' and
compare's lists by their allowed values without repeats, report's --grid by its range."""
from __future__ import annotations

import pytest

from tests.messages import one_line
from tethersim.cli.main import main
from tethersim.experiments.headlines.cases import BY_NAME


def _one_line_error(capsys) -> str:
    return one_line(capsys.readouterr().err)


def test_repeated_headline_cases_are_refused(capsys, tmp_path):
    case = next(iter(BY_NAME))
    assert main(["headlines", "--cases", case, case, "--out", str(tmp_path / "h")]) == 2
    err = _one_line_error(capsys)
    assert "--cases" in err and case in err and "more than once" in err


def test_repeated_compare_models_are_refused(capsys, tmp_path):
    assert main(["compare", "satI", "--models", "derived,derived", "--out",
                 str(tmp_path / "c")]) == 2
    assert "derived" in _one_line_error(capsys)


@pytest.mark.parametrize("grid", ["1", "202", "100000"])
def test_the_report_grid_is_bounded(capsys, tmp_path, grid):
    assert main(["report", "--grid", grid, "--out", str(tmp_path / "r")]) == 2
    err = _one_line_error(capsys)
    assert "--grid" in err and "2..201" in err
