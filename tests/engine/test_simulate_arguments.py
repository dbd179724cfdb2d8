"""simulate()'s arguments: a wrong type or an out-of-range tolerance or length is one
line naming the argument and what is allowed, before any integration."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.cli.main import main
from tethersim.engine.simulate import ATOL_RANGE, MIN_PERIODS, RTOL_RANGE

SAT = ts.load_preset("satI")
BAD = [
    (dict(method="rk4", locate_switches="no"), TypeError, "locate_switches"),
    (dict(locate_switches=1), TypeError, "locate_switches"),
    (dict(rtol=1e6), ValueError, "rtol"),
    (dict(rtol=RTOL_RANGE[1] * 2), ValueError, "rtol"),
    (dict(rtol=RTOL_RANGE[0] / 2), ValueError, "rtol"),
    (dict(atol=1e6), ValueError, "atol"),
    (dict(atol=1e-300), ValueError, "atol"),
    (dict(atol=ATOL_RANGE[1] * 2), ValueError, "atol"),
    (dict(periods=1e-9), ValueError, "periods"),
    (dict(periods=MIN_PERIODS / 2, method="rk4"), ValueError, "periods"),
]


@pytest.mark.parametrize("kwargs, exc, name", BAD, ids=[str(k) for k, _, _ in BAD])
def test_bad_argument_is_one_line_naming_it(kwargs, exc, name):
    kw = dict(periods=0.1, progress=False) | kwargs
    with pytest.raises(exc) as err:
        ts.simulate(SAT, **kw)
    line = str(err.value)
    assert "\n" not in line and line.startswith(name), line


def test_the_range_ends_are_accepted():
    for kw in (dict(rtol=RTOL_RANGE[1], atol=ATOL_RANGE[1]), dict(periods=MIN_PERIODS)):
        assert ts.simulate(SAT, **(dict(periods=0.01, progress=False) | kw)).status == "ok"


@pytest.mark.parametrize("value", ["0.9", "0.5", "0.002"])
def test_cli_rtol_above_the_range_is_refused(value, capsys, tmp_path):
    assert main(["run", "satI", "--periods", "0.5", "--rtol", value, "--quiet",
                 "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--rtol" in err and "0.001" in err


def test_docs_state_the_integrator_ranges():
    from pathlib import Path
    doc = (Path(__file__).parents[2] / "docs" / "limits.md").read_text()
    for lo, hi in (RTOL_RANGE, ATOL_RANGE):
        assert f"{lo:g}..{hi:g}" in doc
    assert f"at least {MIN_PERIODS:g} orbit (~{MIN_PERIODS * SAT.period:.1f} s at 200 km)" in doc
    assert SAT.altitude == 200e3
