"""tethersim compare: experiments/compare.py, plot_compare.py (the command: tests/cli).

tests/derive/test_generated.py already checks the model variants against each other
at single states (right-hand sides and force families).  Here the truths are
checked on whole trajectories, through compare(): what the comparison adds.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

import tethersim as ts
from tests.tiers import VARIANT_LOOP
from tethersim.analysis.classify import CLASSES, classify
from tethersim.analysis.metrics import pitch_metrics
from tethersim.engine.result import SimResult
from tethersim.experiments.compare import (
    COLUMNS,
    compare,
    comparison_table,
    outcome_differences,
    parse_models,
)
from tethersim.model.registry import THESIS_VARIANTS as MODEL_NAMES

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def satI():
    return ts.load_preset("satI")


def _max_diff(results, a, b):
    """max |q_a − q_b| over the run for q = δx [m], δy [m], θ [rad]."""
    r = dict(results)
    assert np.array_equal(r[a].t, r[b].t)  # same settings, same output grid
    return np.max(np.abs(r[a].states[:, :3] - r[b].states[:, :3]), axis=0)


# ------------------------------------------------------------- trajectories

@VARIANT_LOOP
def test_printed_equals_derived_without_tether2_damping(satI):
    """Erratum E1 (docs/errata.md) is the only difference and it is ∝ c2: with
    c2 = 0 (drag, springs and the tether-1 damper all on) the two trajectories
    agree to integration tolerance; with SatI's c2 they do not."""
    res = compare(satI.replace(c2=0.0), ["derived", "printed"], periods=1, progress=False)
    d = _max_diff(res, "derived", "printed")
    assert np.all(d <= np.array([1e-8, 1e-8, 1e-10])), d
    res = compare(satI, ["derived", "printed"], periods=1, progress=False)
    d = _max_diff(res, "derived", "printed")
    assert d[2] > 1e-3, d  # 8e-3 rad after one orbit


@VARIANT_LOOP
def test_printed_minus_derived_pitch_grows_as_double_integral_of_erratum_torque(satI):
    """Drag (CD = 0), springs (E = 0) and damper 1 off, c2 > 0, tether 2 taut
    (the balloon starts 29 m out, l20 = 6 m): θ̈_printed − θ̈_derived =
    k (θ̇ − ω), k = c2 a (a+b) / (m1 b² + m2 a²) (E1).  Over t ≪ the libration
    period the feedback of Δθ is O((ω t)²), so Δθ(t) ≈ k ∫0^t ∫0^s (θ̇ − ω) du ds
    along the derived run, to well under 1 %."""
    bare = satI.replace(CD=0.0, E1=0.0, E2=0.0, c1=0.0, c2=0.01)
    res = dict(compare(bare, ["derived", "printed"], periods=0.02, samples=200, progress=False))
    d, p = res["derived"], res["printed"]
    lam2 = np.hypot(-bare.a * np.sin(d.theta) - d.x, -bare.a * np.cos(d.theta) - d.y)
    assert np.all(lam2 > bare.l20)  # the damper acts throughout
    k = bare.c2 * bare.a * (bare.a + bare.b) / bare.pitch_inertia
    inner = cumulative_trapezoid(d.thetadot - bare.omega, d.t, initial=0.0)
    predicted = k * cumulative_trapezoid(inner, d.t, initial=0.0)
    dth = p.theta - d.theta
    assert abs(dth[-1]) > 1e-4  # far above the integration error
    assert dth[-1] == pytest.approx(predicted[-1], rel=0.01)
    assert np.sign(dth[-1]) == np.sign(-bare.omega)  # spurious torque −c2 a (a+b) ω at rest


@VARIANT_LOOP
def test_objective_damper_equals_derived_without_damping(satI):
    """c1 = c2 = 0: both damper laws vanish, the runs agree to integration
    tolerance (drag and springs on); with SatI's dampers they differ."""
    res = compare(satI.replace(c1=0.0, c2=0.0), ["derived", "objective-damper"], periods=1,
                  progress=False)
    d = _max_diff(res, "derived", "objective-damper")
    assert np.all(d <= np.array([1e-8, 1e-8, 1e-10])), d
    res = compare(satI, ["derived", "objective-damper"], periods=1, progress=False)
    assert _max_diff(res, "derived", "objective-damper")[2] > 1e-3


@VARIANT_LOOP
def test_exact_gravity_differs_from_derived_by_order_length_over_r0(satI):
    """Note N2: the binomial expansion misses terms ~ offset/r0 of the Hill
    terms.  Over one orbit the pitch difference, relative to the libration
    amplitude, is of the order of the longest offset over r0 (b = 10.5 m, the
    29 m trail: 1.6e-6 to 4.4e-6), far above the estimated integration error."""
    res = compare(satI, ["derived", "exact-gravity"], periods=1, check=True, progress=False)
    r = dict(res)
    d = _max_diff(res, "derived", "exact-gravity")
    rel_theta = d[2] / np.max(np.abs(r["derived"].theta))
    scale = max(satI.b, abs(satI.initial[0])) / satI.r0
    assert 0.1 * scale < rel_theta < 100 * scale, (rel_theta, scale)
    err = max(r["derived"].error_estimate[2], r["exact-gravity"].error_estimate[2])
    assert d[2] > 1e3 * err
    rows = comparison_table(res)
    assert rows[1]["max_dtheta"] == pytest.approx(d[2])
    assert rows[1]["class"] == rows[0]["class"]  # a 1e-5 effect changes no outcome


@VARIANT_LOOP
def test_compare_runs_models_in_the_order_given_with_shared_settings(satI):
    # printed before derived: not the registry's order, and a fixed-step loop the CLI's
    # faithful tests compile anyway (each further model's loop is ~13 s of cold compile)
    res = compare(satI, ["printed", "derived"], periods=0.05, method="rk4", steps=20,
                  check=False, progress=False)
    assert [m for m, _ in res] == ["printed", "derived"]
    assert [r.model for _, r in res] == ["printed", "derived"]
    assert all(r.method == "rk4" and r.t.size == 21 for _, r in res)
    rows = comparison_table(res)
    assert rows[0]["max_dtheta"] == 0.0
    assert rows[0]["converged"] is None  # not checked
    assert math.isnan(rows[0]["error_theta"])


# ------------------------------------------------------------ table and classes

def _synthetic(sat, model, t, theta, x):
    states = np.zeros((t.size, 10))
    states[:, 0], states[:, 2] = x, theta
    return SimResult(sat, model, "adaptive", t, states, rtol=1e-10)


def test_comparison_table_metrics_from_known_histories(satI):
    """θ = 0.3 rad until t = 2 h then 0: settles at the first sample after 2 h;
    θ = 0.3 until 4 h then π − 0.1 (over the top): upside down.  δx = 100 m
    except over the last fifth, where it is 5 m: trail δx_ss = 5 m."""
    t = np.linspace(0.0, 10 * 3600.0, 1001)  # 36 s samples
    x = np.where(t >= 8 * 3600.0, 5.0, 100.0)
    stable = _synthetic(satI, "derived", t, np.where(t < 2 * 3600.0, 0.3, 0.0), x)
    flipped = _synthetic(satI, "printed", t, np.where(t < 4 * 3600.0, 0.3, math.pi - 0.1), x)
    rows = comparison_table([("derived", stable), ("printed", flipped)])
    assert [r["model"] for r in rows] == ["derived", "printed"]
    assert rows[0]["settling_time_h"] == pytest.approx(2.0)
    assert rows[0]["class"] == "stable"
    assert rows[0]["trail_delta_x"] == pytest.approx(5.0)
    assert rows[1]["upside_down"] is True and rows[1]["tumbled"] is False
    assert rows[1]["steady_state_pitch"] == pytest.approx(math.pi - 0.1)
    assert rows[1]["class"] == "upside_down"
    assert rows[1]["class"] == CLASSES[classify(pitch_metrics(t, flipped.theta))]
    assert rows[1]["max_dtheta"] == pytest.approx(math.pi - 0.1)
    assert set(rows[0]) == {k for k, _ in COLUMNS}
    notes = outcome_differences(rows)
    assert notes and "derived" in notes[0] and "printed" in notes[0]
    assert "stable" in notes[0] and "upside_down" in notes[0]
    assert outcome_differences(rows[:1] + rows[:1]) == []


def test_failed_run_is_classed_failed(satI):
    t = np.linspace(0.0, 3600.0, 11)
    ok = _synthetic(satI, "derived", t, np.zeros_like(t), np.zeros_like(t))
    bad = SimResult(satI, "printed", "adaptive", t[:5], ok.states[:5], status="failed",
                    message="too many steps at t = 1440 s")
    rows = comparison_table([("derived", ok), ("printed", bad)])
    assert rows[1]["class"] == "failed" and rows[1]["status"] == "failed"
    assert rows[1]["max_dtheta"] == 0.0  # compared over the part both runs cover
    assert any("failed" in n for n in outcome_differences(rows))


@pytest.mark.parametrize("models, words", [
    ("derived,nosuch", ["nosuch", *MODEL_NAMES]),
    ("", ["none given"]),
    ("derived,derived", ["derived", "more than once"]),
])
def test_parse_models_errors_name_the_allowed_values(models, words):
    with pytest.raises(ValueError) as exc:
        parse_models(models)
    for w in words:
        assert w in str(exc.value)


def test_parse_models_keeps_order_and_strips_spaces():
    assert parse_models(" printed , derived ") == ("printed", "derived")
