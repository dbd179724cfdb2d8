"""The public API refuses a wrong argument with a one-line TypeError/ValueError naming the
argument and what is allowed, never an AttributeError, LinAlgError or KeyError from inside."""
from __future__ import annotations

import math

import pytest

import tethersim as ts
from tethersim.experiments.sweep import SweepSpec
from tethersim.experiments.sweep.plan import MAX_SAMPLES, MAX_STEPS

SAT = ts.load_preset("satI")
RES = ts.simulate(SAT, periods=0.05, progress=False)
AXIS = (("E1", (0.001, 0.004)),)

CASES = {
    "guess nan": (lambda: ts.find_equilibrium(SAT, guess=[math.nan, 0, 0]), ValueError, "guess"),
    "guess text": (lambda: ts.find_equilibrium(SAT, guess="abc"), ValueError, "guess"),
    "guess short": (lambda: ts.find_equilibrium(SAT, guess=[1, 2]), ValueError, "guess"),
    "guess nested": (lambda: ts.find_equilibrium(SAT, guess=[[29, 0, 0]]), ValueError, "guess"),
    "equilibrium of a name": (lambda: ts.find_equilibrium("satI"), TypeError, "sat"),
    "preset None": (lambda: ts.load_preset(None), TypeError, "name"),
    "outcome None": (lambda: ts.outcome(None), TypeError, "res"),
    "axes dict": (lambda: SweepSpec(SAT, {"E1": [0.001, 0.004]}), TypeError, "axes"),
    "axis text": (lambda: SweepSpec(SAT, (("E1", "abc"),)), ValueError, "axis E1"),
    "axis repeats": (lambda: SweepSpec(SAT, (("E1", (0.001, 0.001)),)), ValueError, "axis E1"),
    "samples": (lambda: SweepSpec(SAT, AXIS, samples_per_period=MAX_SAMPLES + 1), ValueError,
                "samples_per_period"),
    "steps": (lambda: SweepSpec(SAT, AXIS, steps_per_period=MAX_STEPS + 1), ValueError,
              "steps_per_period"),
    "sweep rtol": (lambda: SweepSpec(SAT, AXIS, rtol=5), ValueError, "rtol"),
    "netcdf attr None": (lambda: ts.write_netcdf(RES, "/nonexistent/x.nc", attrs={"x": None}),
                         TypeError, "attrs['x']"),
}


@pytest.mark.parametrize("call, exc, name", CASES.values(), ids=CASES.keys())
def test_bad_argument_is_one_line_naming_it(call, exc, name):
    with pytest.raises(exc) as err:
        call()
    assert type(err.value) is exc or issubclass(type(err.value), exc)
    line = str(err.value)
    assert "\n" not in line and line.startswith(name), line


def test_a_good_guess_of_either_size_still_finds_the_equilibrium():
    eq = ts.find_equilibrium(SAT)
    assert ts.find_equilibrium(SAT, guess=(eq.delta_x, eq.delta_y, eq.theta)).delta_x == \
        pytest.approx(eq.delta_x, rel=1e-9)
