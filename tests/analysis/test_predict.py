"""Predicted classes, the torque balance E2/E1 ≈ b/a, and the free balloon's Hill modes.

Derivation of the torque balance and the accuracy claims tested here:
docs/torque-balance.md.  Prediction rules: tethersim/analysis/predict.py.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.classify import (
    FAILED,
    OFFSET,
    STABLE,
    TUMBLING,
    UNSETTLED,
    flag_attrs,
)
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.predict import predicted_class, predicted_map
from tethersim.analysis.torque_balance import (
    balanced_E2,
    balloon_trail_at_zero_pitch,
    torque_balance_ratio,
    torque_balance_terms,
)
from tethersim.engine.linearise import attitude_jacobian
from tethersim.model import params
from tethersim.model.registry import THESIS_VARIANTS

PRESETS = ["satI", "satII", "dumbsat"]


# --- torque balance -------------------------------------------------------------
@pytest.mark.parametrize("model", THESIS_VARIANTS)
@pytest.mark.parametrize("preset", PRESETS)
def test_balanced_E2_puts_the_equilibrium_at_zero_pitch(preset, model):
    sat = ts.load_preset(preset)
    E2 = balanced_E2(sat, model=model)
    eq = find_equilibrium(sat.replace(E2=E2), model=model)
    assert abs(eq.theta) < 1e-10
    assert eq.residual < 1e-10 and eq.taut == (True, True)


@pytest.mark.parametrize("model", THESIS_VARIANTS)
@pytest.mark.parametrize("preset", PRESETS)
def test_formula_TB4_is_exact_at_the_balanced_trail(preset, model):
    # TB4 is the θ = 0 pitch equation solved for E2: exact up to rounding (claim 1)
    sat = ts.load_preset(preset)
    E2 = balanced_E2(sat, model=model)
    trail = balloon_trail_at_zero_pitch(sat.replace(E2=E2), model)
    ratio = torque_balance_ratio(sat, model=model, trail=trail)
    assert ratio == pytest.approx(E2 / sat.E1, rel=1e-12)


@pytest.mark.parametrize("preset", PRESETS)
def test_formula_TB4_at_the_satellites_own_trail_errs_first_order_in_the_E2_mismatch(preset):
    # claim 2: with the trail of the unbalanced satellite, |error| <= 0.05 |E2/E2_bal - 1|
    sat = ts.load_preset(preset)
    exact = balanced_E2(sat) / sat.E1
    for f in (0.9, 0.99, 1.01, 1.1):
        s = sat.replace(E2=f * exact * sat.E1)
        assert abs(torque_balance_ratio(s) / exact - 1) <= 0.05 * abs(f - 1)
    # the presets' own E2 is within 0.1 % of balance: the formula within 1e-4
    assert torque_balance_ratio(sat) == pytest.approx(exact, rel=1e-4)


@pytest.mark.parametrize("preset, second_order_tol, leading_tol",
                         [("satI", 2e-3, 0.02), ("satII", 2e-4, 0.007), ("dumbsat", 3e-4, 3e-4)])
def test_leading_b_over_a_and_second_order_approximations(preset, second_order_tol, leading_tol):
    # claims 3 and 4 (docs/torque-balance.md, table): TB6 within 2e-3 of exact for the
    # presets, b/a within 2 % (SatI), 0.7 % (SatII), 3e-4 (DumbSat, the damper bias)
    sat = ts.load_preset(preset)
    exact = balanced_E2(sat) / sat.E1
    terms = torque_balance_terms(sat, *balloon_trail_at_zero_pitch(sat))
    assert terms["leading"] == sat.b / sat.a == terms["b_over_a"]  # l10 = l20
    assert abs(terms["second_order"] / exact - 1) <= second_order_tol
    assert abs(terms["leading"] / exact - 1) <= leading_tol
    # the trail corrections push the ratio above b/a (the tip tether is the longer)
    if sat.b > sat.a:
        assert exact > sat.b / sat.a and terms["second_order"] > sat.b / sat.a


def test_dumbsat_ratio_is_one_by_symmetry():
    sat = ts.load_preset("dumbsat")
    assert (sat.a, sat.m1, sat.A1, sat.l10, sat.E1, sat.c1) == (sat.b, sat.m2, sat.A2, sat.l20,
                                                              sat.E2, sat.c2)
    # the formula: exactly 1 at δy = 0 (λ1 = λ2), and its leading term is exactly 1
    terms = torque_balance_terms(sat, 28.0, 0.0)
    assert terms["b_over_a"] == 1.0 and terms["leading"] == 1.0 and terms["geometric"] == 1.0
    # the model without the thesis damper's rigid-rotation torque: 1 up to the O(offset/r0)
    # asymmetries (air speed ∝ r0 + y, the balloon drag's y-component ∝ δx/r0), ~5e-7
    no_damper = sat.replace(c1=0.0, c2=0.0)
    assert balanced_E2(no_damper) / sat.E1 == pytest.approx(1.0, abs=2e-6)
    assert balanced_E2(sat, model="objective-damper") / sat.E1 == pytest.approx(1.0, abs=2e-6)
    # the thesis damper resists the formation's rotation ω: a torque ω c (a² + b²) that
    # tilts DumbSat (θ_eq > 0) and needs E2 a little larger than E1
    with_damper = balanced_E2(sat) / sat.E1 - 1
    assert 1e-4 < with_damper < 5e-4


# --- predicted classes ------------------------------------------------------------
def test_satI_nominal_is_predicted_stable_and_E1_times_1_5_is_not():
    sat = ts.load_preset("satI")
    code, info = predicted_class(sat)
    assert code == STABLE, info["reason"]
    assert abs(info["theta_eq"]) < 0.05 and info["max_real_eigenvalue"] < 0
    assert info["predicted_settling_time"] < info["settling_limit"]
    assert info["taut"] == (True, True)
    code, info = predicted_class(sat.replace(E1=1.5 * sat.E1))
    assert code != STABLE
    # the tip-mass tether wins and the boom trails the wake (thesis Fig 5.5: offset ≈ π/2)
    assert code == OFFSET and info["theta_eq"] == pytest.approx(math.pi / 2, abs=0.05)


def test_branch_follows_theta_zero_continuously_in_E1():
    # θ_eq grows monotonically with E1 through 0 towards π/2 (no jump to another root)
    sat = ts.load_preset("satI")
    thetas = [predicted_class(sat.replace(E1=f * sat.E1))[1]["theta_eq"]
              for f in (0.98, 0.995, 1.0, 1.005, 1.02, 1.1, 1.2, 1.3)]
    assert np.all(np.diff(thetas) > 0)
    assert -math.pi / 2 - 0.05 < thetas[0] and thetas[-1] < math.pi / 2 + 0.05


def test_a_first_swing_over_the_top_is_predicted_tumbling():
    # E1 x 0.9: the branch equilibrium is at -1.51 rad; swinging there from θ0 = +π/6 the
    # boom passes -π (a 50-orbit DOP853 run: tumbled, class tumbling, θ_ss = -1.52)
    sat = ts.load_preset("satI").replace(E1=0.9 * 0.004)
    code, info = predicted_class(sat)
    assert code == TUMBLING and info["theta_turn"] == -math.pi
    assert info["theta_eq"] == pytest.approx(-1.513, abs=1e-3)
    assert predicted_class(sat, swing=False)[0] == OFFSET
    # E1 x 1.5: the swing towards +π/2 turns back near π - θ0 (no tumbling; simulated: offset)
    code, info = predicted_class(ts.load_preset("satI").replace(E1=1.5 * 0.004))
    assert code == OFFSET and 2.0 < info["theta_turn"] < 3.0
    # nominal, no dampers: the quasi-static swing turns where the simulated one does
    # (-0.612 against -0.618 rad: the balloon's own motion; not the harmonic -0.537)
    sat = ts.load_preset("satI").replace(c1=0.0, c2=0.0)
    _, info = predicted_class(sat)
    run = ts.simulate(sat, periods=0.3, check=False, progress=False)
    assert info["theta_turn"] == pytest.approx(run.theta.min(), abs=0.01)


def test_settling_limit_is_the_run_window_or_three_days():
    sat = ts.load_preset("satI")
    _, info = predicted_class(sat)  # settles in ~47 h
    assert info["settling_limit"] == pytest.approx(0.8 * 50 * sat.period)
    # a 30-orbit run keeps only 24 orbits (35 h) to settle before its steady window
    assert predicted_class(sat, periods=30)[0] == UNSETTLED
    # a third of the damping triples the slowest decay time
    assert predicted_class(sat.replace(c1=1e-4, c2=1e-4))[0] == UNSETTLED
    assert predicted_class(sat, periods=200)[1]["settling_limit"] == 3 * 86400.0


def test_no_tethers_is_a_graceful_failure():
    sat = ts.load_preset("satI").replace(E1=0.0, E2=0.0)
    code, info = predicted_class(sat)
    assert code == FAILED and math.isnan(info["theta_eq"]) and "balloon" in info["reason"]


def test_predicted_map_labels_and_matches_predicted_class():
    sat = ts.load_preset("satI")
    e1 = np.array([0.0, 0.004, 0.006])  # N/mm^2
    e2 = np.array([0.0, 0.0427])
    ds = predicted_map(sat, "E1", e1, "E2", e2, progress=False)
    assert ds.predicted_class.dims == ("E2", "E1") and ds.predicted_class.dtype == np.int8
    assert ds.E1.attrs["units"] == "N/mm^2" and ds.theta_eq.attrs["units"] == "rad"
    assert ds.max_real_eigenvalue.attrs["units"] == "1/s"
    assert ds.predicted_settling_time.attrs["units"] == "s" and ds.theta_turn.attrs["units"] == "rad"
    assert ds.predicted_class.attrs["flag_meanings"] == flag_attrs()["flag_meanings"]
    for i, y in enumerate(e2):
        for j, x in enumerate(e1):
            code, info = predicted_class(params.with_values(sat, {"E1": x, "E2": y}))
            assert ds.predicted_class.values[i, j] == code
            np.testing.assert_allclose(ds.theta_eq.values[i, j], info["theta_eq"], atol=1e-9)
    assert ds.predicted_class.values[0, 0] == FAILED
    assert ds.predicted_class.values[1, 1] == STABLE
    with pytest.raises(ts.SatelliteError, match="grid point"):
        predicted_map(sat, "m1", [10.0, 11.0], "E1", [0.004], progress=False)


# --- eigenvalues with no tethers and no drag (issue 5) --------------------------------
@pytest.mark.parametrize("model", THESIS_VARIANTS)
def test_free_balloon_has_the_hill_clohessy_wiltshire_modes(model):
    """No tethers, dampers or drag: the balloon's in-plane block is Hill's / CW's.

    In L (ω ẑ, y up): δẍ = 2ω δẏ, δÿ = −2ω δẋ + 3ω² δy, so the characteristic
    polynomial is λ²(λ² + ω²): eigenvalues 0, 0 (along-track drift) and ±iω
    (the epicycle).  The pitch (√3 ω, tests/derive/test_jacobian.py) is decoupled.
    """
    sat = ts.load_preset("satI").replace(CD=0.0, E1=0.0, E2=0.0, c1=0.0, c2=0.0)
    w = sat.omega
    balloon = [0, 1, 3, 4]
    # at the COM the truncated terms (offset²/r0², docs/errata.md N1-N2) vanish: exact CW
    J = attitude_jacobian(sat, [0.0, 0.0, 0.3, 0.0, 0.0, 0.0], model)
    B = J[np.ix_(balloon, balloon)]
    np.testing.assert_allclose(B[2:, :], [[0, 0, 0, 2 * w], [0, 3 * w**2, -2 * w, 0]],
                               rtol=1e-12, atol=1e-15 * w**2)
    coeffs = np.poly(B) / w ** np.arange(5)
    np.testing.assert_allclose(coeffs, [1, 0, 1, 0, 0], atol=1e-12)
    ev = np.sort_complex(np.linalg.eigvals(B)) / w
    np.testing.assert_allclose(ev, [-1j, 1j, 0, 0], atol=1e-9)  # sorted by real, then imag
    assert not J[np.ix_([2, 5], balloon)].any() and not J[np.ix_([3, 4], [2, 5])].any()
    # 29 m in the wake: the same modes up to (offset/r0)² ~ 2e-11 (frequency) and its
    # square root in the split of the double zero
    J = attitude_jacobian(sat, [29.0, 0.0, 0.0, 0.0, 0.0, 0.0], model)
    ev = np.linalg.eigvals(J[np.ix_(balloon, balloon)]) / w
    osc = ev[np.abs(ev.imag) > 0.5]
    np.testing.assert_allclose(np.sort(osc.imag), [-1, 1], rtol=1e-9)
    assert np.all(np.abs(ev[np.abs(ev.imag) <= 0.5]) < 1e-4)
