"""The convergence check compares every generalized coordinate of the model (issue 19).

The 3-D layout leads with δx, δy, δz: a check of the first three states never
saw roll φ, pitch θ or yaw ψ.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import tethersim as ts
from tethersim.engine.result import CONVERGED_POSITION, CONVERGED_THETA, SimResult
from tethersim.engine.simulate import _with_error
from tethersim.model.registry import get_model


@pytest.fixture(scope="module")
def sat():
    return ts.load_preset("satI")


def _pair(sat, model: str, name: str, error: float):
    """A finished run and a 'finer rerun' whose final state differs only in ``name``."""
    lay = get_model(model)
    states = np.zeros((3, lay.n_state))
    run = SimResult(sat, model, "adaptive", np.array([0.0, 1.0, 2.0]), states,
                    rtol=1e-10, atol=1e-12, periods=1.0)
    fine_states = states.copy()
    fine_states[-1, lay.state.index(name)] += error
    return run, replace(run, states=fine_states)


@pytest.mark.parametrize("name", ["phi", "psi", "theta"])
def test_an_attitude_error_in_a_3d_run_is_seen(sat, name):
    run, fine = _pair(sat, "3d", name, 5 * CONVERGED_THETA)
    # the old check's coordinates (the first three states: δx, δy, δz) agree exactly
    assert np.array_equal(run.states[-1, :3], fine.states[-1, :3])
    checked = _with_error(run, fine)
    assert checked.converged is False
    assert checked.errors[name] == pytest.approx(5 * CONVERGED_THETA)
    assert "NOT converged" in checked.label
    assert f"largest in {name}: " in checked.label and "rad" in checked.label


def test_the_estimate_names_every_coordinate_in_layout_order(sat):
    for model in ("derived", "3d", "free", "3d-free"):
        lay = get_model(model)
        run, fine = _pair(sat, model, lay.state[0], 0.0)
        errors = _with_error(run, fine).errors
        assert tuple(errors) == lay.state[:lay.n_coordinates]
        assert run.units == dict(zip(lay.state[:lay.n_coordinates],
                                     lay.state_units[:lay.n_coordinates]))


def test_the_bound_follows_the_unit_of_the_coordinate(sat):
    # an error between the two bounds passes in a length, fails in an angle
    between = (CONVERGED_THETA + CONVERGED_POSITION) / 2
    assert CONVERGED_THETA < between < CONVERGED_POSITION
    length, _ = _pair(sat, "3d", "delta_z", between)
    angle, _ = _pair(sat, "3d", "phi", between)
    assert _with_error(length, _pair(sat, "3d", "delta_z", between)[1]).converged is True
    assert _with_error(angle, _pair(sat, "3d", "phi", between)[1]).converged is False


def test_the_dominant_coordinate_is_the_largest_against_its_bound(sat):
    lay = get_model("3d")
    run, _ = _pair(sat, "3d", "phi", 0.0)
    fine_states = run.states.copy()
    fine_states[-1, lay.state.index("delta_x")] += 0.5 * CONVERGED_POSITION  # 5e-3 m: half
    fine_states[-1, lay.state.index("psi")] += 0.9 * CONVERGED_THETA  # 9e-4 rad: 90 %
    checked = _with_error(run, replace(run, states=fine_states))
    assert checked.converged is True
    assert "largest in psi: 0.0009 rad" in checked.label


def test_a_planar_estimate_is_the_difference_to_an_independent_finer_rerun(sat):
    """Planar θ unchanged: (δx, δy, θ), each |final − final of a run at rtol/100|."""
    res = ts.simulate(sat, periods=0.5, progress=False, check=True)
    finer = ts.simulate(sat, periods=0.5, progress=False, rtol=res.rtol / 100,
                        atol=res.atol / 100)
    expected = np.abs(res.states[-1, :3] - finer.states[-1, :3])
    assert np.array_equal(np.array(res.error_estimate), expected)
    ex, ey, eth = res.error_estimate
    assert res.converged is bool(eth <= CONVERGED_THETA and max(ex, ey) <= CONVERGED_POSITION)
    row = ts.outcome(res, forces=False).row()
    assert row["error_theta"] == eth
    assert row["error_position"] == max(ex, ey)
    assert row["error_angle"] == eth


def test_a_planar_rk4_estimate_is_the_difference_to_the_run_at_half_the_step(sat):
    res = ts.simulate(sat, periods=0.5, method="rk4", steps=150, progress=False, check=True)
    half = ts.simulate(sat, periods=0.5, method="rk4", steps=300, progress=False)
    assert np.array_equal(np.array(res.error_estimate),
                          np.abs(res.states[-1, :3] - half.states[-1, :3]))


@pytest.mark.slow  # compiles the 3-D loop
def test_a_coarse_3d_rk4_run_is_judged_on_roll_and_yaw_too(sat):
    tilted = sat.replace(initial_3d={"phi": 0.1, "psi": 0.1})
    res = ts.simulate(tilted, periods=1, model="3d", method="rk4", steps=300, progress=False,
                      check=True)
    half = ts.simulate(tilted, periods=1, model="3d", method="rk4", steps=600, progress=False)
    lay = res.layout
    for k, name in enumerate(lay.state[:lay.n_coordinates]):
        assert res.errors[name] == abs(res.states[-1, k] - half.states[-1, k]), name
    assert res.errors["phi"] > 0 and res.errors["psi"] > 0
    assert all(math.isfinite(e) for e in res.error_estimate)


@pytest.mark.slow  # compiles the 3-D loop; 400 orbits of RK4 at the thesis's step (~2 s)
def test_a_long_3d_rk4_run_is_not_converged_in_yaw_where_the_old_check_saw_nothing(sat):
    """SatI with 0.5 rad of roll and yaw, 400 orbits at the thesis's 26.55 s step: the yaw
    error grows orbit after orbit (undamped) while δx, δy, δz agree to far below their
    bounds, so a check of the first three states (δx, δy, δz) called it converged."""
    tilted = sat.replace(initial_3d={"phi": 0.5, "psi": 0.5})
    steps = 200 * 400
    res = ts.simulate(tilted, periods=400, model="3d", method="rk4", steps=steps,
                      progress=False, check=True, step_warning=False)
    half = ts.simulate(tilted, periods=400, model="3d", method="rk4", steps=2 * steps,
                       progress=False, step_warning=False)
    lay = res.layout
    diff = {k: abs(res.states[-1, i] - half.states[-1, i])
            for i, k in enumerate(lay.state[:lay.n_coordinates])}
    # the old check: δx, δy within 1 cm and the third state (δz here) within 1e-3
    assert diff["delta_x"] <= CONVERGED_POSITION and diff["delta_y"] <= CONVERGED_POSITION
    assert diff["delta_z"] <= CONVERGED_THETA
    # the yaw is not within its bound, and the check now says so and names it
    assert diff["psi"] > CONVERGED_THETA
    assert res.converged is False
    assert "NOT converged" in res.label and "largest in psi" in res.label
