"""The settling band tol must be a finite number of radians in (0, π) (issue 19): NaN made
every run "stable", a negative or huge band was accepted silently."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tethersim.analysis.metrics import check_tol, pitch_metrics
from tethersim.experiments.sweep import SweepSpec

SAT = ts.load_preset("satI")
BAD = [math.nan, math.inf, -1.0, 0.0, math.pi, 10.0, True, "0.05"]


@pytest.fixture(scope="module")
def res():
    return ts.simulate(SAT, periods=0.05, progress=False)


@pytest.mark.parametrize("tol", BAD)
def test_outcome_refuses_a_band_outside_zero_to_pi(res, tol):
    with pytest.raises(ValueError, match=r"^tol = .*\(0, pi\)") as e:
        ts.outcome(res, tol=tol)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("tol", BAD)
def test_pitch_metrics_and_sweep_specs_refuse_it_too(tol):
    with pytest.raises(ValueError, match="tol"):
        pitch_metrics([0.0, 1.0], [0.1, 0.2], tol=tol)
    with pytest.raises(ValueError, match="tol"):
        SweepSpec(SAT, (("E2", [0.0427]),), periods=1, tol=tol)


def test_a_band_inside_the_range_is_taken_as_given(res):
    assert check_tol(0.05) == 0.05 and check_tol(3.0) == 3.0
    assert ts.outcome(res, tol=0.2, forces=False).counts
