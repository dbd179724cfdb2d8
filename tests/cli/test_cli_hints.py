"""A refusal says the way out: scaling an unset index says to set it first, a negative grid
value says to write --X=VALUE, an equilibrium without drag says why there is none."""
from __future__ import annotations

import pytest


@pytest.mark.parametrize("argv, expected", [
    (["run", "satI", "--scale", "f107=2"], ["--scale f107", "unset", "--set f107="]),
    (["run", "satI", "--set", "atmosphere=nrlmsise00", "--scale", "ap=2"],
     ["--scale ap", "unset", "--set ap="]),
    (["sweep", "satI", "--c1", "-1,0.004"], ["--c1=VALUE", "starts with '-'"]),
    (["equilibrium", "satI", "--set", "CD=0"], ["CD = 0", "without drag", "no trailing"]),
])
def test_refusal_names_the_way_out(argv, expected, cli, tmp_path):
    out = ["--out", str(tmp_path / "o"), "--quiet"] if argv[0] != "equilibrium" else []
    code, _, err = cli([*argv, *out])
    assert code == 2
    line = err.strip()
    assert len(line.splitlines()) == 1
    for text in expected:
        assert text in line, line
