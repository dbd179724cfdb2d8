"""Bead chains through simulate() and the CLI (docs/beads.md)."""
from __future__ import annotations

import pytest

from tethersim.cli.main import main


@pytest.mark.parametrize("n", ["65", "-1"])
def test_cli_refuses_beads_outside_0_to_64_in_one_line(n, tmp_path, capsys):
    assert main(["run", "satI", "--beads", n, "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"beads = {n}: allowed an integer 0 to 64" in err
