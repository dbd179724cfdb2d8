"""tethersim/cli/tune.py: input checks and the refusal to replace another's tuned preset."""
from __future__ import annotations

import pytest

from tethersim.cli import options, tune


def test_tune_refuses_a_non_positive_E1(cli):
    code, _, err = cli(["tune", "satI", "--E1", "0"])
    assert code == 2
    assert "--E1" in err and "> 0" in err


def test_tune_refuses_to_replace_a_preset_tuned_from_another_satellite(tmp_path):
    path = tmp_path / "tuned.toml"
    path.write_text("# SatII tuned by tethersim tune (50-orbit ...) from satII\nname = 'x'\n")
    tune._check_target(path, "from satII", force=False)  # the same origin: may be replaced
    with pytest.raises(options.UsageError, match="--force") as info:
        tune._check_target(path, "from satI --set E1=0.005", force=False)
    assert "from satI --set E1=0.005" in str(info.value) and "\n" not in str(info.value)
    tune._check_target(path, "from satI", force=True)  # --force: replaced
