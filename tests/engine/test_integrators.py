"""Integrators: tableau identities, convergence order, switch location, agreement."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.validation import libration_case
from tethersim.engine.integrators import dop853_tableau as tab
from tethersim.engine.linearise import rk4_amplification, rk4_max_step
from tethersim.engine.simulate import RK4StepWarning, simulate


@pytest.fixture(scope="module")
def sat():
    return ts.load_preset("satI")


def test_dop853_tableau_row_sums_equal_nodes():
    # Runge-Kutta consistency: Σ_j A[i, j] = C[i] for every stage, extended ones included.
    assert np.allclose(tab.A.sum(axis=1), tab.C, rtol=0, atol=1e-14)


def test_dop853_weights_sum_to_one_and_error_weights_to_zero():
    assert math.isclose(tab.B.sum(), 1.0, abs_tol=1e-14)
    assert abs(tab.E5.sum()) < 1e-14 and abs(tab.E3.sum()) < 1e-14


def _slope(hs, errs):
    return float(np.polyfit(np.log(hs), np.log(errs), 1)[0])


def test_rk4_converges_at_fourth_order_on_smooth_libration(sat):
    """No drag, no tethers: smooth right-hand side, so the fitted order is 4 (Eqs 4.1-4.5)."""
    s = libration_case(sat)
    ref = simulate(s, periods=0.5, method="adaptive", rtol=1e-13, atol=1e-15, samples=4, check=False)
    hs, errs = [], []
    for n in (25, 50, 100, 200):
        r = simulate(s, periods=0.5, steps=n, method="rk4", check=False)
        hs.append(r.step)
        errs.append(abs(r.theta[-1] - ref.theta[-1]))
    assert 3.8 < _slope(hs, errs) < 4.2


def _switching_case(sat):
    # Balloon released 4 m behind the COM: tether 2 (rest 6 m) starts slack and
    # goes taut as drag pushes the balloon back; dampers make the force jump there.
    return sat.replace(initial=(4.0, 0.0, 0.3, 0.0, 0.0, 0.0), c1=0.01, c2=0.01)


@pytest.mark.slow
def test_rk4_order_drops_at_switches_and_is_restored_by_locating_them(sat):
    s = _switching_case(sat)
    per = 600.0 / s.period
    ref = simulate(s, periods=per, method="adaptive", rtol=1e-13, atol=1e-14, samples=4, check=False)
    assert ref.n_switches >= 1
    slopes = {}
    for locate in (False, True):
        hs, errs = [], []
        for n in (200, 400, 800, 1600, 3200):
            r = simulate(s, periods=per, steps=n, method="rk4", locate_switches=locate, check=False)
            hs.append(r.step)
            errs.append(np.abs(r.states[-1, :6] - ref.states[-1, :6]).max())
        slopes[locate] = _slope(hs, errs)
    assert slopes[False] < 2.5, slopes
    assert 3.5 < slopes[True] < 4.5, slopes


def test_adaptive_error_shrinks_with_tolerance(sat):
    s = _switching_case(sat)
    per = 600.0 / s.period
    ref = simulate(s, periods=per, method="adaptive", rtol=1e-13, atol=1e-15, samples=4, check=False)
    errs = [np.abs(simulate(s, periods=per, method="adaptive", rtol=rt, atol=rt * 1e-2, samples=4,
                            check=False).states[-1, :6] - ref.states[-1, :6]).max()
            for rt in (1e-6, 1e-8, 1e-10)]
    assert errs[0] > errs[1] > errs[2]
    assert errs[2] < 1e-6


@pytest.mark.slow
@pytest.mark.parametrize("preset", ["satI", "satII", "dumbsat"])
def test_adaptive_and_rk4_agree_on_nominal_runs(preset):
    s = ts.load_preset(preset)
    a = simulate(s, periods=5, method="adaptive", samples=100, check=False)
    r = simulate(s, periods=5, steps=1500 * 8, method="rk4", locate_switches=True, check=False)
    assert np.allclose(a.states[-1, :3], r.states[-1, :3], rtol=0, atol=1e-5)
    assert np.allclose(a.theta, r.theta[::120], rtol=0, atol=1e-5)


def test_orbit_stays_circular_two_body(sat):
    """Eq 3.9 from Table 4.3's circular state: |R| = r0 (the closed form since issue 22;
    tests/engine/test_held_circle.py checks it against an integration of Eq 3.9)."""
    r = simulate(sat, periods=2, method="adaptive", samples=50, check=False)
    radius = np.hypot(r.orbit[:, 0], r.orbit[:, 1])
    assert np.max(np.abs(radius / sat.r0 - 1)) < 1e-9
    # after two periods the COM is back at (r0, 0)
    assert abs(r.orbit[-1, 1]) / sat.r0 < 1e-8


def test_convergence_check_flags_a_step_that_is_too_long(sat):
    s = _switching_case(sat)
    # 20 s steps: inside RK4's stability limit (~30 s) but far from accurate
    coarse = simulate(s, periods=0.5, steps=133, method="rk4", check=True)
    fine = simulate(s, periods=0.5, method="adaptive").estimate_error()
    assert fine.converged is True
    assert coarse.converged is False
    assert "NOT converged" in coarse.label


def test_slack_at_start_still_warns_for_a_step_the_taut_tethers_cannot_take(sat):
    s = _switching_case(sat)  # tether 2 slack at t = 0
    with pytest.warns(RK4StepWarning):
        r = simulate(s, periods=0.5, steps=60, method="rk4")  # 44 s steps
    # the balloon is flung off: the run stops where the first limit is passed, before the
    # state can turn non-finite
    assert r.status == "left-domain" and r.event in ("balloon reach", "tether 1 stretch",
                                                    "tether 2 stretch")
    assert np.all(np.isfinite(r.states))


def test_rk4_warning_only_when_step_exceeds_linear_stability(sat):
    h_max = rk4_max_step(sat)
    # tether modes near 0.09 rad/s: RK4's imaginary-axis limit h w = 2.83 gives ~30 s
    assert 20 < h_max < 40
    assert rk4_amplification(sat, 0.9 * h_max) <= 1 < rk4_amplification(sat, 1.1 * h_max)
    per = 3 * 1.1 * h_max / sat.period
    with pytest.warns(RK4StepWarning, match="step"):
        simulate(sat, periods=per, steps=3, method="rk4", check=False)


def test_interrupted_run_keeps_every_finished_step(sat, monkeypatch):
    """Ctrl-C between chunks: the rows already computed are returned unchanged."""
    import tethersim.engine.simulate as sim

    full = simulate(sat, periods=1, steps=300, method="rk4", check=False)
    calls = {"n": 0}
    real = sim.rk4_run

    def flaky(*args):
        calls["n"] += 1
        if calls["n"] == 40:
            raise KeyboardInterrupt
        return real(*args)

    monkeypatch.setattr(sim, "rk4_run", flaky)
    monkeypatch.setattr(sim, "RK4_PAUSE_STEPS", 3)  # a pause every 3 steps, as a long run's
    part = simulate(sat, periods=1, steps=300, method="rk4", check=False, progress=False)
    assert part.status == "interrupted"
    n = part.t.size
    assert 1 < n < full.t.size
    assert np.array_equal(part.states, full.states[:n])


def test_nonfinite_start_returns_at_once_instead_of_hanging(sat):
    """A NaN derivative at t = 0 must end the run with a status, not loop forever."""
    from tethersim.engine.events import event_parameters
    from tethersim.engine.integrators.dop853 import STATUS_NONFINITE, dop853_run
    from tethersim.model.air.vector import uniform_air
    from tethersim.model.inputs import parameter_vector

    p = parameter_vector(sat, "derived")
    p[5] = np.nan  # A3: the Satellite record refuses this, the kernel must still stop
    y = np.array(sat.initial, dtype=float)
    out_t = np.array([100.0])
    out_y = np.empty((1, y.size))
    ev = event_parameters(sat, "derived")
    t, h, i_out, status, _ = dop853_run(0, uniform_air(), 0.0, 100.0, y, 0.0, p, p.copy(), ev,
                                        1e-10, 1e-12, True, out_t, out_y, 0, 1000,
                                        np.zeros(5, np.int64), math.inf)
    assert status == STATUS_NONFINITE and t == 0.0


def test_progress_pauses_do_not_change_the_adaptive_steps():
    """One compiled call (progress=False) and 100 paused calls take the same steps."""
    from tethersim import load_preset, simulate
    sat = load_preset("satI")
    one = simulate(sat, 3.0, check=False, progress=False)
    paused = simulate(sat, 3.0, check=False, progress=True)
    np.testing.assert_array_equal(one.states, paused.states)
    assert one.n_accepted == paused.n_accepted and one.n_rejected == paused.n_rejected
