"""Equilibria: zero residual, which tethers are taut, and eigenvalues that predict the runs."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.analysis.equilibrium import find_equilibrium, format_equilibrium
from tethersim.engine.simulate import simulate
from tethersim.model.registry import THESIS_VARIANTS


@pytest.mark.parametrize("model", THESIS_VARIANTS)
@pytest.mark.parametrize("preset", ["satI", "satII", "dumbsat"])
def test_equilibrium_residual_is_below_1e_10(preset, model):
    eq = find_equilibrium(ts.load_preset(preset), model=model)
    assert eq.residual < 1e-10
    assert eq.taut == (True, True)
    assert eq.stable


def test_dumbsat_symmetry_puts_pitch_near_zero():
    # equal masses, arms, areas and tethers (thesis p. 4-2): only the small damper
    # bias of Eqs 3.43-3.44 (rigid rotation of the formation) tilts it.
    eq = find_equilibrium(ts.load_preset("dumbsat"))
    assert abs(eq.theta) < 0.01


def test_simulated_run_settles_at_the_equilibrium():
    sat = ts.load_preset("satII")
    eq = find_equilibrium(sat)
    r = simulate(sat, periods=30, samples=3000, check=False)
    assert abs(r.x[-1] - eq.delta_x) < 1e-3
    assert abs(ts.outcome(r).metrics.steady_state_pitch - eq.theta) < 5e-3


@pytest.mark.slow
def test_slowest_eigenvalue_predicts_the_simulated_settling_time():
    sat = ts.load_preset("satI")
    eq = find_equilibrium(sat)
    r = simulate(sat, periods=50, check=False)
    predicted = eq.predicted_settling_time(sat.initial[2] - eq.theta)
    # the linear prediction ignores the first, nonlinear swings: allow 10 %
    assert abs(ts.outcome(r).metrics.settling_time / predicted - 1) < 0.1


def test_report_names_tethers_and_modes():
    text = format_equilibrium(find_equilibrium(ts.load_preset("satI")))
    assert "tether 1 taut" in text and "damping ratio" in text and "RK4 step" in text
