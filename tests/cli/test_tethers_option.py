"""--tethers MATERIAL:DIAMETER_MM[:KNOCKDOWN]: the CLI's shorthand for with_tethers."""
from __future__ import annotations

import pytest

import tethersim as ts
from tests.messages import one_line
from tethersim.cli import options
from tethersim.cli.main import build_parser, main

BASE = ["show", "satI", "--set", "l10=30.83", "--set", "l20=28.92"]


def test_the_option_sets_what_with_tethers_sets_after_the_rest_lengths():
    args = build_parser().parse_args(["run", "satI", "--set", "l10=30.83", "--tethers",
                                      "kevlar49:1:0.8", "--set", "l20=28.92"])
    got = options.satellite(args)
    want = ts.with_tethers(ts.load_preset("satI").replace(l10=30.83, l20=28.92), "kevlar49",
                           1e-3, knockdown=0.8)
    for key in ("l10", "l20", "E1", "E2", "c1", "c2", "Fb1", "Fb2"):
        assert getattr(got, key) == getattr(want, key), key


@pytest.mark.parametrize("extra, words", [
    (["--tethers", "kevlar49"], "--tethers 'kevlar49': expected MATERIAL:DIAMETER_MM"),
    (["--tethers", "kevlar49:x"], "expected MATERIAL:DIAMETER_MM[:KNOCKDOWN]"),
    (["--tethers", "steel:1"], "--tethers: tether material 'steel': allowed kevlar49"),
    (["--tethers", "kevlar49:1", "--set", "E1=0.004"],
     "--set E1: --tethers sets it from the material"),
])
def test_bad_tethers_are_one_line_naming_the_option(extra, words, capsys):
    assert main([*BASE, *extra]) == 2
    line = one_line(capsys.readouterr().err)
    assert line.startswith("tethersim: error: ") and words in line
