"""pitch_metrics and wrap on synthetic signals whose answers are known in closed form.

Definitions: tethersim/analysis/metrics.py (settling tolerance ±0.05 rad, thesis p. 5-18;
steady state = mean over the last fifth of the run).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.analysis.metrics import SETTLING_TOL, PitchMetrics, pitch_metrics, wrap


def test_default_tolerance_is_the_thesis_criterion():
    # facts.md: stability region = mean pitch within ±0.05 rad (5-18)
    assert SETTLING_TOL == 0.05


@pytest.mark.parametrize("A, tau, period, theta_ss, tol", [
    (0.5, 1000.0, 200.0, 0.1, 0.05),
    (math.pi / 6, 3000.0, 500.0, -0.2, 0.05),  # θ0 = π/6 as in Table 4.2
    (1.0, 500.0, 60.0, 0.0, 0.01),
])
def test_decaying_sinusoid_settles_at_tau_ln_A_over_tol(A, tau, period, theta_ss, tol):
    # θ = A e^{-t/τ} cos(wt) + θ_ss: the envelope reaches tol at τ ln(A/tol); the
    # last excursion beyond tol is a peak of cos within one period before that.
    t_end = 20 * tau
    t = np.linspace(0.0, t_end, 200_001)
    w = 2 * math.pi / period
    theta = A * np.exp(-t / tau) * np.cos(w * t) + theta_ss
    m = pitch_metrics(t, theta, tol=tol)
    expected = tau * math.log(A / tol)
    dt = t[1] - t[0]
    assert expected - period <= m.settling_time <= expected + dt
    assert m.steady_state_pitch == pytest.approx(theta_ss, abs=1e-6)
    # mean over the run: θ_ss plus ∫A e^{-t/τ} cos(wt) dt / t_end = A τ/(1 + w²τ²) / t_end,
    # up to the sample mean's end-point weight, about A / (number of samples)
    assert m.mean_pitch == pytest.approx(theta_ss + A * tau / (1 + (w * tau) ** 2) / t_end,
                                         abs=2 * A / t.size)
    assert not m.tumbled
    assert not m.upside_down


def test_decaying_sinusoid_on_nonuniform_samples():
    rng = np.random.default_rng(1)
    t = np.sort(np.concatenate([[0.0, 20000.0], rng.uniform(0, 20000.0, 100_000)]))
    theta = 0.5 * np.exp(-t / 1000.0) * np.cos(2 * math.pi * t / 200.0)
    m = pitch_metrics(t, theta)
    expected = 1000.0 * math.log(0.5 / 0.05)
    assert expected - 200.0 <= m.settling_time <= expected + np.max(np.diff(t))


def test_constant_signal_settles_at_first_sample():
    t = np.linspace(100.0, 1000.0, 91)
    m = pitch_metrics(t, np.full_like(t, 0.3))
    assert m.settling_time == 100.0
    assert m.steady_state_pitch == pytest.approx(0.3)
    assert m.mean_pitch == pytest.approx(0.3)
    assert not m.tumbled and not m.upside_down


@pytest.mark.parametrize("signal", [
    # sustained oscillation, amplitude 0.5 > tol, run ends on a peak
    lambda t: 0.5 * np.cos(2 * math.pi * t / 100.0),
    # growing oscillation
    lambda t: 0.01 * np.exp(t / 300.0) * np.cos(2 * math.pi * t / 100.0),
    # drift: pitch ramps 0 -> 1 rad
    lambda t: t / 1000.0,
], ids=["sustained", "growing", "ramp"])
def test_signal_that_never_settles_gives_nan(signal):
    t = np.linspace(0.0, 1000.0, 10_001)
    m = pitch_metrics(t, signal(t))
    assert math.isnan(m.settling_time)


def test_sustained_oscillation_ending_near_its_mean_never_settles():
    # docs/metrics.md: NaN unless the whole steady-state window is within tol; the last
    # samples of this undamped ±0.5 rad libration lie within tol of the mean
    t = np.linspace(0.0, 1025.0, 10_251)  # 10.25 periods: ends at a zero crossing of cos
    theta = 0.5 * np.cos(2 * math.pi * t / 100.0)
    assert abs(theta[-1]) < SETTLING_TOL
    assert math.isnan(pitch_metrics(t, theta).settling_time)


def test_settling_inside_the_steady_state_window_is_not_settled():
    # envelope reaches tol at τ ln(A/tol) = 0.9 t_end: inside the last fifth of the run
    t_end = 10_000.0
    tau = 0.9 * t_end / math.log(0.5 / 0.05)
    t = np.linspace(0.0, t_end, 100_001)
    theta = 0.5 * np.exp(-t / tau) * np.cos(2 * math.pi * t / 100.0)
    assert math.isnan(pitch_metrics(t, theta).settling_time)


def test_tumbling_through_pi_is_flagged():
    # end over end: θ runs from 0 through π and 2π, then librates about 2π (upright again)
    t = np.linspace(0.0, 1000.0, 10_001)
    theta = np.where(t < 500.0, 2 * math.pi * t / 500.0, 2 * math.pi + 0.01 * np.sin(t))
    m = pitch_metrics(t, theta)
    assert m.tumbled
    assert not m.upside_down  # wrapped steady state ≈ 0
    assert m.steady_state_pitch == pytest.approx(0.0, abs=0.02)


def test_tumbling_backwards_through_minus_pi_is_flagged():
    t = np.linspace(0.0, 1000.0, 1001)
    assert pitch_metrics(t, -4 * math.pi * t / 1000.0).tumbled


def test_libration_below_pi_is_not_tumbling():
    t = np.linspace(0.0, 1000.0, 1001)
    theta = (math.pi - 1e-3) * np.sin(2 * math.pi * t / 100.0)
    assert not pitch_metrics(t, theta).tumbled


@pytest.mark.parametrize("theta_ss", [math.pi - 0.02, -math.pi + 0.02, 3.18])
def test_upside_down_steady_state_near_pi_is_flagged(theta_ss):
    # facts.md: damping x 10 gives a steady pitch of 3.18 rad, "upside down" (5-13)
    t = np.linspace(0.0, 1000.0, 1001)
    theta = theta_ss * (1 - np.exp(-t / 50.0))
    m = pitch_metrics(t, theta)
    assert m.upside_down
    assert abs(m.steady_state_pitch) == pytest.approx(math.pi, abs=0.05)
    assert -math.pi < m.steady_state_pitch <= math.pi
    assert m.tumbled == (abs(theta_ss) >= math.pi)


@pytest.mark.parametrize("theta_ss, flagged", [
    (0.76 * math.pi, True), (0.74 * math.pi, False), (-0.76 * math.pi, True),
    (0.0, False), (3 * math.pi, True),
])
def test_upside_down_means_within_quarter_turn_of_pi(theta_ss, flagged):
    t = np.linspace(0.0, 10.0, 11)
    assert pitch_metrics(t, np.full_like(t, theta_ss)).upside_down is flagged


def test_metrics_record_types_and_dict():
    t = np.linspace(0.0, 10.0, 11)
    m = pitch_metrics(t, np.zeros_like(t))
    assert isinstance(m, PitchMetrics)
    d = m.to_dict()
    assert set(d) == {"mean_pitch", "steady_state_pitch", "settling_time", "tumbled",
                      "upside_down"}
    assert isinstance(d["tumbled"], bool) and isinstance(d["upside_down"], bool)
    assert all(isinstance(d[k], float) for k in ("mean_pitch", "steady_state_pitch",
                                                 "settling_time"))


def test_pitch_metrics_rejects_bad_input():
    with pytest.raises(ValueError, match="two samples"):
        pitch_metrics([0.0], [0.0])
    for bad in (0.0, -0.1, 1.5):
        with pytest.raises(ValueError, match="ss_fraction"):
            pitch_metrics([0.0, 1.0], [0.0, 0.0], ss_fraction=bad)


# --- wrap ------------------------------------------------------------------------

@pytest.mark.parametrize("angle, expected", [
    (0.0, 0.0), (math.pi, math.pi), (-math.pi, math.pi), (3 * math.pi, math.pi),
    (-3 * math.pi, math.pi), (2 * math.pi, 0.0), (-2 * math.pi, 0.0),
    (math.pi / 2, math.pi / 2), (-math.pi / 2, -math.pi / 2),
    (3 * math.pi / 2, -math.pi / 2), (7.0, 7.0 - 2 * math.pi), (-7.0, -7.0 + 2 * math.pi),
])
def test_wrap_known_values(angle, expected):
    assert wrap(angle) == pytest.approx(expected, abs=1e-12)


def test_wrap_maps_into_half_open_interval_and_keeps_angle_mod_2pi():
    rng = np.random.default_rng(0)
    a = np.concatenate([rng.uniform(-100.0, 100.0, 100_000),
                        np.arange(-20, 21) * math.pi])  # odd multiples of π: the boundary
    w = wrap(a)
    assert w.shape == a.shape
    assert np.all(w > -math.pi) and np.all(w <= math.pi)
    turns = (a - w) / (2 * math.pi)
    assert np.allclose(turns, np.round(turns), atol=1e-12)


def test_wrap_one_ulp_above_pi_stays_inside_interval():
    # rounding in the remainder must not land on −π, which the interval excludes
    for angle in (np.nextafter(math.pi, 4.0), np.nextafter(3 * math.pi, 10.0),
                  np.nextafter(-math.pi, 0.0)):
        w = float(wrap(angle))
        assert -math.pi < w <= math.pi
        assert abs(abs(w) - math.pi) < 4e-15  # a few ulp of 3π
