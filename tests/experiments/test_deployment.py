"""tethersim/experiments/deployment.py: the two ends of a deployment on real lines, checked
against closed forms and a Newton-Euler balance of the boom."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tests.tiers import VARIANT_LOOP
from tethersim.experiments.deployment import (
    MAX_SPEED,
    arrival,
    catch_closed_form,
    deploy,
    line_lengths,
    pull_along_trim,
    released,
    settle,
)
from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
from tethersim.model.presets import load_preset

CATCH = 0.01  # orbits (53 s): the first catch of a release from 3 m comes at ~17 s
FINE = 2e-4  # s: 280 samples across a 56 ms catch


@pytest.fixture(scope="module")
def bridle():
    """SatI on the stretched bridle of 1 mm Dyneema, dampers off (the closed forms'
    lines are springs)."""
    return real_lines(load_preset("satI"), STRETCHED_LENGTHS).replace(c1=0.0, c2=0.0)


def test_the_lines_turn_the_boom_only_by_the_balloons_height_times_their_pull(bridle):
    # Varignon: both lines meet at the balloon, so their torque on the boom about the COM
    # is the balloon's position crossed with their pull, whatever their lengths: the
    # generated families (springs and Kelvin-Voigt dampers) give Q_θ = δx Q_δy − δy Q_δx.
    # Hence the pay-out rule of docs/real-tethers.md: a balloon level with the COM pulls
    # the boom without a torque.
    from tethersim.generated import objective_damper
    from tethersim.generated.layout import FAMILIES
    from tethersim.model.inputs import parameter_vector
    lines = [FAMILIES.index(f) for f in ("spring1", "spring2", "damper1", "damper2")]
    p = parameter_vector(bridle, "objective-damper")
    rng = np.random.default_rng(7)
    for _ in range(20):
        y = np.array([30.0, 0.0, 0.0, 0.0, 0.0, 0.0]) + rng.normal(size=6) * (
            3.0, 3.0, 0.5, 1.0, 1.0, 0.01)
        out = np.zeros((len(FAMILIES), 3))
        objective_damper.family_forces.py_func(y, p.copy(), out)
        qx, qy, qt = out[lines].sum(axis=0)
        assert qt == pytest.approx(y[0] * qy - y[1] * qx, rel=1e-12, abs=1e-9)


def test_with_one_line_the_closed_form_is_the_energy_balance(bridle):
    # one taut line, one mode: the pull along u peaks at D_u + v (e·u)² √(k μ)
    sat = bridle.replace(E2=0.0, c2=0.0, Fb2=0.0)
    x, y, v = 29.0, 2.0, 0.7
    lam = math.hypot(x, y - sat.b)
    start = sat.replace(initial=(x, y, 0.0, v * x / math.hypot(x, y), v * y / math.hypot(x, y),
                                 0.0), l10=lam - 1e-4)
    e_u = (x * x + (y - sat.b) * y) / (lam * math.hypot(x, y))
    k = start.E1 / start.l10
    mu = sat.m3 * (sat.m1 + sat.m2) / (sat.m1 + sat.m2 + sat.m3)
    energy = k * 1e-4 * e_u + v * e_u ** 2 * math.sqrt(k * mu)
    assert catch_closed_form(start) == pytest.approx(energy, rel=1e-7)


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
@pytest.mark.parametrize("speed", [0.01, 0.1, 1.0])
def test_an_arrivals_first_catch_is_the_bridles_modal_closed_form_to_5e_5(bridle, speed):
    # a satellite 100x heavier: the boom's turn and recoil, which the closed form leaves
    # out, shrink 100-fold; what is left is the gravity gradient and Coriolis over ~20 ms
    start = arrival(bridle.replace(m1=1e3, m2=1.05e4), speed)
    dep = deploy(start, periods=1e-4, sample=FINE)
    pull = pull_along_trim(dep.result, start)
    first = pull[:int(np.argmax(dep.result.tether_tensions().max(1) <= 0)) or None].max()
    assert first == pytest.approx(catch_closed_form(start), rel=5e-5)


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_on_satI_the_boom_turn_softens_the_catch_by_under_half_a_percent(bridle):
    start = arrival(bridle, 1.0)
    dep = deploy(start, periods=1e-4, sample=FINE)
    ratio = pull_along_trim(dep.result, start).max() / catch_closed_form(start)
    assert 0.995 < ratio < 1.0, ratio


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_an_arrival_at_rest_is_the_equilibrium_and_nothing_moves(bridle):
    dep = deploy(arrival(bridle, 0.0), periods=0.01)
    y = dep.result.model_states
    assert dep.catches == 0 and dep.result.n_switches == 0 and dep.first_catch == 0.0
    assert np.ptp(y[:, 2]) < 1e-9 and np.abs(y[:, 3:]).max() < 1e-9


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_an_arrival_at_rest_settles_at_once_at_its_own_trim(bridle):
    start = arrival(bridle, 0.0)
    settled = settle(start, periods=5.0)
    assert settled["settled_class"] == "stable" and settled["settling_h"] == 0.0
    assert settled["theta_ss"] == pytest.approx(start.initial[2], abs=1e-9)


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_a_release_flies_slack_until_the_drag_carries_it_to_its_lines(bridle):
    start = released(bridle, 3.0)
    dep = deploy(start, periods=CATCH, sample=FINE)
    res = dep.result
    y = res.model_states
    k = int(np.searchsorted(res.t, dep.first_catch))
    # slack until the catch: each line shorter than its rest length before it
    lam = np.array([line_lengths(start, *row[:3]) for row in y[:k:50]])
    assert (lam < (start.l10, start.l20)).all()
    # free flight under the balloon's drag against the satellite's: t = sqrt(2 s / a), with
    # a the relative deceleration the run itself shows in its first second (Coriolis bends
    # the path by ~0.4 m over 28 m and the lines' directions turn: 1.6e-4 measured)
    travel = math.hypot(y[k, 0] - y[0, 0], y[k, 1] - y[0, 1])
    second = int(np.searchsorted(res.t, 1.0))
    accel = 2 * math.hypot(y[second, 0] - y[0, 0], y[second, 1] - y[0, 1]) / res.t[second] ** 2
    assert dep.first_catch == pytest.approx(math.sqrt(2 * travel / accel), rel=1e-3)


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_the_first_catch_spins_the_boom_by_the_lines_angular_impulse(bridle):
    # Newton-Euler for the boom about its COM: I dθ/dt changes by minus the lines'
    # torque (θ turns the tip-mass towards +δx, clockwise) integrated over the catch
    start = released(bridle, 3.0)
    dep = deploy(start, periods=CATCH, sample=FINE)
    res = dep.result
    y, t = res.model_states, res.t
    tension = res.tether_tensions()
    taut = tension.max(1) > 0
    a = int(np.argmax(taut))
    b = a + int(np.argmin(taut[a:]))
    window = slice(a - 1, b + 1)
    s, c = np.sin(y[window, 2]), np.cos(y[window, 2])
    torque = np.zeros(b - a + 2)
    for j, (rx, ry) in enumerate(((start.b * s, start.b * c), (-start.a * s, -start.a * c))):
        dx, dy = y[window, 0] - rx, y[window, 1] - ry
        lam = np.hypot(dx, dy)
        torque += rx * tension[window, j] * dy / lam - ry * tension[window, j] * dx / lam
    impulse = float(((torque[1:] + torque[:-1]) / 2 * np.diff(t[window])).sum())
    spin = start.pitch_inertia * (y[b, 5] - y[a - 1, 5])
    # the trapezoid rule on 280 samples of a half sine: ~1e-5 (8e-8 measured)
    assert spin == pytest.approx(-impulse, rel=1e-4)
    # the record reads the same catch: its end, its duration, the spin it leaves
    assert dep.spin == abs(y[b, 5]) and dep.catch_duration == t[b] - t[a]
    # some 36 times the orbit rate, where the gravity gradient holds at most √3 times it
    assert dep.spin > 20 * start.omega


@VARIANT_LOOP  # deploy runs objective-damper's Radau loop (~35 s cold)
def test_a_line_too_thin_for_the_catch_breaks_at_its_breaking_load():
    # 0.05 mm Dyneema breaks at 5.9 N; a free release from 3 m snaps it within the catch
    thin = real_lines(load_preset("satI"), STRETCHED_LENGTHS, diameter=5e-5)
    dep = deploy(released(thin, 3.0), periods=CATCH, sample=FINE)
    res = dep.result
    assert dep.status == "tether-broke" and res.event in ("tether 1 break", "tether 2 break")
    quarter = math.pi / 2 * math.sqrt(thin.m3 * thin.l10 / thin.E1)  # to the catch's peak
    assert dep.first_catch < res.event_time < dep.first_catch + quarter
    assert res.t[-1] == res.event_time  # the run ends at the located break
    assert dep.first_peak == pytest.approx(thin.Fb1, rel=1e-6)
    assert dep.safety_factor == pytest.approx(1.0, rel=1e-6)


def test_a_catch_needs_a_grid_finer_than_it_and_a_planar_model(bridle):
    # 2 ms is the default; a catch on both 1 mm Dyneema lines of ~30 m lasts 40 ms
    with pytest.raises(ValueError, match=r"sample = 0.5 s: a catch on these lines lasts "
                                         r"0.0404 s .* 0 < sample <= 0.00404 s"):
        deploy(arrival(bridle, 0.1), sample=0.5)
    with pytest.raises(ValueError, match=r"model = 'free', orbit = 'circular': a deployment "
                                         r"runs the planar circular-orbit models \(derived, "):
        arrival(bridle, 0.1, model="free")
    with pytest.raises(ValueError, match="turns the boom over at its equilibrium"):
        # the lines' loss as the thesis's damper (on the whole relative velocity)
        arrival(real_lines(load_preset("satI"), STRETCHED_LENGTHS), 0.1, model="derived")
    with pytest.raises(ValueError, match="no line is taut"):
        catch_closed_form(released(bridle, 3.0))


@pytest.mark.parametrize("call, match", [
    (lambda s: released(s, 40.0), r"release distance = 40 m: .* 1.95 < distance < 28.9 m"),
    (lambda s: released(s, 1.0), r"release distance = 1 m: .* balloon \(radius 1.95 m\) clear "
                                 r"of the boom"),
    (lambda s: released(s, -1.0), r"release distance = -1 m"),
    # the thesis's 6 m lines cannot reach past the balloon's radius beside the boom
    (lambda s: released(s.replace(l10=6.0, l20=6.0), 3.0),
     r"release distance = 3 m: .* no distance gives both at offset 0 m \(lines 6 and 6 m\)"),
    (lambda s: arrival(s, -0.5), rf"arrival speed = -0.5 m/s: allowed 0 to {MAX_SPEED:g}"),
    (lambda s: arrival(s, math.nan), r"arrival speed = nan m/s"),
])
def test_a_start_outside_the_deployment_is_refused_in_one_line(bridle, call, match):
    with pytest.raises(ValueError, match=match) as err:
        call(bridle)
    assert "\n" not in str(err.value)
