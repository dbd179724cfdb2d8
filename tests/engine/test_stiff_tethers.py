"""Real (stiff) tethers: a satellite with one is valid; the explicit schemes refuse it in
one line pointing at the implicit scheme, which runs it (docs/tethers.md)."""
from __future__ import annotations

import pytest

import tethersim as ts
from tests.messages import one_line
from tethersim.cli.main import main

SAT = ts.load_preset("satI")


def _kevlar(sat=SAT):
    t1 = ts.tether_parameters("kevlar49", 1e-3, sat.l10, sat.m3)
    t2 = ts.tether_parameters("kevlar49", 1e-3, sat.l20, sat.m3)
    return sat.replace(E1=t1["EA"], c1=t1["c"], E2=t2["EA"], c2=t2["c"])


def test_a_real_tether_is_a_valid_satellite():
    sat = _kevlar()  # no allow_implausible needed: a real material is plausible
    assert not sat.allow_implausible and sat.E1 > 8e4


@pytest.mark.parametrize("method", ["adaptive", "rk4"])
def test_the_explicit_schemes_refuse_it_in_one_line_naming_the_way_out(method):
    with pytest.raises(ValueError) as e:
        ts.simulate(_kevlar(), periods=0.01, method=method, progress=False)
    line = one_line(str(e.value))
    assert "E1 = 87964.6 N/mm^2: tether 1 would oscillate with period" in line
    assert "method='implicit'" in line


def test_the_implicit_scheme_runs_it():
    """Lines cut to the thesis's stretched geometry (issue 21: rest lengths 30.83 and 28.92 m,
    the balloon's start 29 m behind, given: real lines start at their equilibrium by
    default, engine/start.py): slack/taut snaps included, the run completes."""
    sat = _kevlar(SAT.replace(l10=30.83, l20=28.92))
    res = ts.simulate(sat, periods=0.05, method="implicit", rtol=1e-6, progress=False,
                      start="given")
    assert res.status == "ok" and res.method == "implicit" and res.n_switches > 0


def test_the_command_line_refuses_and_then_runs_it(tmp_path, capsys):
    argv = ["run", "satI", "--set", "E2=3e4", "--periods", "0.002", "--no-plots", "--no-check",
            "--quiet"]
    assert main([*argv, "--out", str(tmp_path / "a")]) == 2
    line = one_line(capsys.readouterr().err)
    assert line.startswith("tethersim: error: E2 = 30000 N/mm^2: tether 2 would oscillate")
    assert "<= 2.348e+04 N/mm^2" in line and "--method implicit" in line
    argv += ["--set", "l10=30.83", "--set", "l20=28.92", "--start", "given"]
    assert main([*argv, "--method", "implicit", "--out", str(tmp_path / "b")]) == 0
    assert "Radau IIA implicit" in capsys.readouterr().out


@pytest.mark.parametrize("change, expected", [
    (dict(E1=5e4), ["E1 = 50000 N/mm^2: tether 1 would oscillate", "<= 2.348e+04 N/mm^2"]),
    (dict(c2=500.0), ["c2 = 500 N s/m: damper time", "<= 99.14 N s/m"]),
])
def test_a_stiff_tether_or_damper_loads_and_the_explicit_run_says_why_not(change, expected):
    sat = SAT.replace(**change)  # a valid satellite (thesis units: E x 1 mm^2 = N)
    with pytest.raises(ValueError) as e:
        ts.simulate(sat, periods=0.01, progress=False)
    line = one_line(str(e.value))
    assert all(text in line for text in expected), line


def test_a_real_tether_is_not_listed_implausible_unless_an_explicit_run_was_allowed_it():
    """Plausible input is what the model represents; what an explicit scheme cannot
    resolve is the run's limit, listed in an allowed explicit run's summary only."""
    from tethersim.analysis.summary import implausible_summary

    sat = _kevlar()
    assert sat.implausible == ()
    allowed = sat.replace(allow_implausible=True)
    assert implausible_summary(allowed, "implicit") == {}
    line = implausible_summary(allowed, "adaptive")["implausible inputs (allowed)"]
    assert "tether 1 would oscillate" in line
