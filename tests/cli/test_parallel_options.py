"""--workers, --dask-workers and --scheduler: declared once (cli/parallel.py), the same
refusals in one line for every command that takes them."""
from __future__ import annotations

import pytest

from tests.messages import one_line
from tethersim.cli.main import main

COMMANDS = {
    "sweep": ["sweep", "satI", "--E1", "0.004", "--periods", "1"],
    "mc": ["mc", "satI", "--n", "2", "--periods", "1"],
    "design": ["design", "satI", "--vary", "c1=0.001:0.01", "--budget", "2", "--periods", "1"],
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("extra, words", [
    (["--workers", "1", "--scheduler", "tcp://127.0.0.1:1"],
     "--workers, --dask-workers and --scheduler are alternatives: give one"),
    (["--dask-workers", "1000"], "--dask-workers 1000: allowed 1.."),
])
def test_each_command_refuses_in_one_line(command, extra, words, tmp_path, capsys):
    assert main([*COMMANDS[command], *extra, "--out", str(tmp_path)]) == 2
    line = one_line(capsys.readouterr().err)
    assert line.startswith("tethersim: error: ") and words in line, line
