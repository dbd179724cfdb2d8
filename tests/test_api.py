"""Public API contract: accelerations, generalized_forces, parameters, simulate, SimResult.

Equation numbers: the thesis as printed (Maramba 2005, chapter III).
"""
from __future__ import annotations

import importlib
import math
import warnings

import numpy as np
import pytest

import tethersim
from tethersim import RK4StepWarning, SimResult, accelerations, generalized_forces
from tethersim.generated.layout import FAMILIES, STATE
from tethersim.model.constants import MU_EARTH, OMEGA_EARTH, R_EARTH
from tethersim.model.registry import THESIS_VARIANTS

SAT = tethersim.load_preset("satI")
# (δx, δy, θ, δẋ, δẏ, θ̇): balloon in the wake with both tethers taut and every term
# of Eqs 3.28-3.30 non-zero
TAUT = np.array([29.0, 0.5, 0.3, 0.01, -0.02, 1e-3])
STATES = [
    TAUT,
    np.array([25.0, -3.0, -0.4, -0.05, 0.03, -2e-3]),
    np.array([31.0, 2.0, 1.0, 0.0, 0.0, 0.0]),
    np.array(SAT.initial),
]
# Models whose left-hand sides are Eqs 3.28-3.30 (exact-gravity keeps 1/|r| unexpanded)
LHS_MODELS = ("derived", "printed", "objective-damper")


def _total(forces):
    return np.sum([forces[f] for f in FAMILIES], axis=0)


# --- shapes and keys ---------------------------------------------------------------

@pytest.mark.parametrize("model", THESIS_VARIANTS)
def test_accelerations_and_forces_shapes_and_family_keys(model):
    acc = accelerations(SAT, TAUT, model)
    assert isinstance(acc, np.ndarray) and acc.shape == (3,) and acc.dtype == np.float64
    assert np.all(np.isfinite(acc))
    forces = generalized_forces(SAT, TAUT, model)
    assert tuple(forces) == FAMILIES  # keys, in layout order
    for f in FAMILIES:
        assert forces[f].shape == (3,), f
        assert np.all(np.isfinite(forces[f])), f


def test_models_are_the_four_variants():
    assert THESIS_VARIANTS == ("derived", "printed", "exact-gravity", "objective-damper")
    assert set(THESIS_VARIANTS) < set(tethersim.MODELS)
    assert tethersim.STATE == STATE == ("delta_x", "delta_y", "theta", "delta_x_dot",
                                        "delta_y_dot", "theta_dot")


def test_returned_arrays_are_copies():
    acc = accelerations(SAT, TAUT)
    acc[:] = 0.0
    assert np.any(accelerations(SAT, TAUT) != 0.0)
    forces = generalized_forces(SAT, TAUT)
    forces["drag3"][:] = 0.0
    assert np.any(generalized_forces(SAT, TAUT)["drag3"] != 0.0)


def test_accelerations_accept_list_and_tuple_states():
    np.testing.assert_array_equal(accelerations(SAT, list(TAUT)), accelerations(SAT, tuple(TAUT)))


# --- Lagrange equations (Eqs 3.28-3.30) with the families' forces ---------------------

@pytest.mark.parametrize("model", LHS_MODELS)
@pytest.mark.parametrize("state", STATES, ids=["taut", "other", "pitched", "initial"])
def test_accelerations_solve_eqs_3_28_to_3_30_with_summed_family_forces(model, state):
    p = tethersim.parameters(SAT)
    m1, m2, m3, a, b = p["m1"], p["m2"], p["m3"], p["a"], p["b"]
    w, r0 = p["omega"], p["r0"]
    dx, dy, th, dxd, dyd, _ = state
    xdd, ydd, thdd = accelerations(SAT, state, model)
    Qx, Qy, Qth = _total(generalized_forces(SAT, state, model))
    # Eq 3.28: m3 δẍ − 2 m3 ω δẏ − 3 m3 ω² δy δx / r0 = Q_δx
    lhs_x = m3 * xdd - 2 * m3 * w * dyd - 3 * m3 * w**2 * dy * dx / r0
    # Eq 3.29: m3 δÿ + 2 m3 ω δẋ − 3 m3 ω² δy − 9 m3 ω² δy²/(2 r0) − 3 m3 ω² δx²/(2 r0) = Q_δy
    lhs_y = (m3 * ydd + 2 * m3 * w * dxd - 3 * m3 * w**2 * dy
             - 9 * m3 * w**2 * dy**2 / (2 * r0) - 3 * m3 * w**2 * dx**2 / (2 * r0))
    # Eq 3.30: m1 (b² θ̈ + 3ω² b² cosθ sinθ + 3ω² b³ sinθ/(2 r0))
    #        + m2 (a² θ̈ + 3ω² a² cosθ sinθ − 3ω² a³ sinθ/(2 r0)) = Q_θ
    s, c = math.sin(th), math.cos(th)
    lhs_th = (m1 * (b**2 * thdd + 3 * w**2 * b**2 * c * s + 3 * w**2 * b**3 * s / (2 * r0))
              + m2 * (a**2 * thdd + 3 * w**2 * a**2 * c * s - 3 * w**2 * a**3 * s / (2 * r0)))
    # tolerance: rounding relative to the largest term of each equation
    scale_x = max(abs(m3 * xdd), abs(Qx), abs(2 * m3 * w * dyd))
    scale_y = max(abs(m3 * ydd), abs(Qy), abs(3 * m3 * w**2 * dy), abs(2 * m3 * w * dxd))
    scale_th = max(abs(SAT.pitch_inertia * thdd), abs(Qth), abs(3 * w**2 * SAT.pitch_inertia * s))
    assert lhs_x == pytest.approx(Qx, abs=1e-12 * scale_x)
    assert lhs_y == pytest.approx(Qy, abs=1e-12 * scale_y)
    assert lhs_th == pytest.approx(Qth, abs=1e-12 * scale_th)


def test_mass_matrix_is_diag_m3_m3_pitch_inertia():
    # Eqs 3.28-3.30: M = diag(m3, m3, m1 b² + m2 a²).  At δx = δy = θ = 0 with zero rates
    # every other left-hand-side term vanishes, so q̈ = Q / diag(M)
    state = np.zeros(6)  # satI: tether 1 (10.5 m > 6 m) taut, drag on all three bodies
    acc = accelerations(SAT, state)
    Q = _total(generalized_forces(SAT, state))
    assert acc[0] == pytest.approx(Q[0] / SAT.m3, rel=1e-12)
    assert acc[1] == pytest.approx(Q[1] / SAT.m3, rel=1e-12)
    assert acc[2] == pytest.approx(Q[2] / SAT.pitch_inertia, rel=1e-12)
    assert SAT.pitch_inertia == SAT.m1 * SAT.b**2 + SAT.m2 * SAT.a**2


# --- forces switch with the tethers (Eqs 3.35-3.36, 3.43-3.44) ------------------------

def test_slack_tethers_give_zero_spring_and_damper_forces():
    # DumbSat (a = b = 5 m, l10 = l20 = 6 m): balloon at the COM is 5 m from each end,
    # so both tethers are slack (γ < 1) and only drag acts
    dumb = tethersim.load_preset("dumbsat")
    forces = generalized_forces(dumb, [0.0, 0.0, 0.3, 0.01, 0.01, 1e-3])
    for f in ("spring1", "spring2", "damper1", "damper2"):
        np.testing.assert_array_equal(forces[f], 0.0)
    assert forces["drag3"][0] > 0  # the wake is +x (docs/conventions.md)


def test_end_body_drag_acts_only_on_pitch_and_balloon_drag_only_on_offsets():
    # Q_θ collects drag on m1, m2; Q_δx, Q_δy the drag on m3 (Eqs 3.45-3.47)
    forces = generalized_forces(SAT, TAUT)
    np.testing.assert_array_equal(forces["drag1"][:2], 0.0)
    np.testing.assert_array_equal(forces["drag2"][:2], 0.0)
    assert forces["drag3"][2] == 0.0


def test_taut_spring_pulls_balloon_towards_its_end_body():
    # Eq 3.35: F_spring1 = τ1 E1 (γ1 − 1), τ1 the unit vector from balloon to tip-mass
    dx, dy, th = TAUT[:3]
    to_tip = np.array([SAT.b * math.sin(th) - dx, SAT.b * math.cos(th) - dy])
    lam1 = np.hypot(*to_tip)
    expected = to_tip / lam1 * SAT.E1 * (lam1 / SAT.l10 - 1)
    np.testing.assert_allclose(generalized_forces(SAT, TAUT)["spring1"][:2], expected, rtol=1e-12)


# --- model variants differ only where they should -------------------------------------

@pytest.mark.parametrize("state", STATES[:3], ids=["taut", "other", "pitched"])
def test_printed_differs_from_derived_only_in_damper2_pitch_torque(state):
    # docs/errata.md row E1: Eq 3.50 as printed uses tether 1's brackets for c2
    d = generalized_forces(SAT, state, "derived")
    p = generalized_forces(SAT, state, "printed")
    for f in FAMILIES:
        n = 2 if f == "damper2" else 3
        np.testing.assert_allclose(p[f][:n], d[f][:n], rtol=1e-12, atol=1e-18, err_msg=f)
    assert p["damper2"][2] != pytest.approx(d["damper2"][2], rel=1e-6)
    undamped = SAT.replace(c1=0.0, c2=0.0)
    np.testing.assert_allclose(accelerations(undamped, state, "printed"),
                               accelerations(undamped, state, "derived"), rtol=1e-12, atol=0)


@pytest.mark.parametrize("state", STATES[:3], ids=["taut", "other", "pitched"])
def test_objective_damper_differs_from_derived_only_through_dampers(state):
    d = generalized_forces(SAT, state, "derived")
    o = generalized_forces(SAT, state, "objective-damper")
    for f in ("drag1", "drag2", "drag3", "spring1", "spring2"):
        np.testing.assert_allclose(o[f], d[f], rtol=1e-12, atol=1e-18, err_msg=f)
    assert not np.allclose(o["damper1"], d["damper1"], rtol=1e-6, atol=0)
    undamped = SAT.replace(c1=0.0, c2=0.0)
    np.testing.assert_allclose(accelerations(undamped, state, "objective-damper"),
                               accelerations(undamped, state, "derived"), rtol=1e-12, atol=0)


@pytest.mark.parametrize("state", STATES, ids=["taut", "other", "pitched", "initial"])
def test_exact_gravity_agrees_with_derived_to_offset_over_r0(state):
    # Eqs 3.18-3.25: the binomial expansion of 1/|r| drops terms a factor ~ L/r0 below the
    # kept ones, L ~ 30 m the largest offset: 30 / 6.58e6 ≈ 5e-6
    d = accelerations(SAT, state, "derived")
    e = accelerations(SAT, state, "exact-gravity")
    np.testing.assert_allclose(e, d, rtol=1e-5, atol=0)
    np.testing.assert_array_equal(
        _total(generalized_forces(SAT, state, "exact-gravity")),
        _total(generalized_forces(SAT, state, "derived")))


def test_per_body_density_changes_only_drag():
    per_body = SAT.replace(density_mode="per-body")
    u = generalized_forces(SAT, TAUT)
    p = generalized_forces(per_body, TAUT)
    for f in ("spring1", "spring2", "damper1", "damper2"):
        np.testing.assert_array_equal(p[f], u[f])
    # bodies lie within ~30 m of 200 km; scale height there 37.105 km (Vallado Table 8-4)
    for f in ("drag1", "drag2", "drag3"):
        np.testing.assert_allclose(p[f], u[f], rtol=30 / 37.105e3 * 1.1, atol=0)
    assert not np.array_equal(p["drag3"], u["drag3"])


@pytest.mark.parametrize("altitude", [1000e3, 999.99e3, 0.0])
def test_per_body_satellite_at_the_range_ends_is_rejected_or_finite(altitude):
    try:
        sat = SAT.replace(altitude=altitude, density_mode="per-body")
    except tethersim.SatelliteError:
        return  # rejected at creation: acceptable
    state = [29.0, 0.0, 0.0, 0.0, 0.0, 0.0]  # tip-mass 10.5 m above, bus 1 m below the COM
    try:
        acc = accelerations(sat, state)
    except ValueError:
        return  # a clear error: acceptable
    assert np.all(np.isfinite(acc))


# --- parameters --------------------------------------------------------------------

THESIS_SYMBOLS = ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b", "l10", "l20", "E1", "E2",
                  "c1", "c2", "CD", "r0", "mu", "omega", "omega_earth", "rho")


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_parameters_has_every_thesis_symbol_as_si_float(name):
    sat = tethersim.load_preset(name)
    p = tethersim.parameters(sat)
    for k in THESIS_SYMBOLS:
        assert k in p, k
        assert type(p[k]) is float, k
        assert math.isfinite(p[k]), k
    # Eq 3.14
    assert p["omega"] == pytest.approx(math.sqrt(p["mu"] / p["r0"] ** 3), rel=1e-15)
    assert p["r0"] == R_EARTH + 200e3 == 6578137.0  # WGS-84 R_E + 200 km (facts.md)
    assert p["mu"] == MU_EARTH
    assert p["omega_earth"] == OMEGA_EARTH
    assert p["rho"] == pytest.approx(2.789e-10, rel=1e-12)  # Vallado Table 8-4 at 200 km
    assert p["CD"] == 2.0  # thesis p. 3-9
    for k in ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b", "l10", "l20", "E1", "E2", "c1", "c2"):
        assert p[k] == getattr(sat, k), k


def test_parameters_moduli_in_newtons():
    # E in N/mm² × 1 mm² = N (thesis p. 3-1): satI.toml E1_N_per_mm2 = 0.004
    assert tethersim.parameters(SAT)["E1"] == pytest.approx(0.004, rel=1e-15)


# --- argument validation -------------------------------------------------------------

@pytest.mark.parametrize("state", [
    [0.0] * 5, [0.0] * 7, [0.0] * 10, [[0.0] * 6], [0.0, 0.0, math.nan, 0.0, 0.0, 0.0],
    [0.0, math.inf, 0.0, 0.0, 0.0, 0.0],
], ids=["len5", "len7", "len10", "2d", "nan", "inf"])
@pytest.mark.parametrize("func", [accelerations, generalized_forces])
def test_bad_state_raises_value_error_naming_state(func, state):
    with pytest.raises(ValueError, match=r"state = .*6 finite numbers"):
        func(SAT, state)


@pytest.mark.parametrize("func", [accelerations, generalized_forces])
def test_bad_model_raises_value_error_listing_models(func):
    with pytest.raises(ValueError, match=r"model = 'thesis'.*derived.*printed"):
        func(SAT, TAUT, "thesis")


def test_non_satellite_raises_type_error():
    with pytest.raises(TypeError, match="Satellite"):
        accelerations({"m1": 1.0}, TAUT)
    with pytest.raises(TypeError, match="Satellite"):
        tethersim.simulate("satI", periods=0.1)


@pytest.mark.parametrize("method", ["adaptive", "rk4"])
@pytest.mark.parametrize("periods", [0, -1, math.nan, math.inf, "x", None])
def test_bad_periods_raise_value_error_naming_periods(periods, method):
    with pytest.raises(ValueError, match="periods"):
        tethersim.simulate(SAT, periods=periods, method=method)


@pytest.mark.parametrize("steps", [0, -3, 1.5, "10", True])
def test_bad_rk4_steps_raise_value_error_naming_steps(steps):
    with pytest.raises(ValueError, match=r"steps = .*integer >= 1"):
        tethersim.simulate(SAT, periods=0.1, steps=steps, method="rk4")


@pytest.mark.parametrize("steps", [0, 1.5])
def test_bad_adaptive_steps_raise_value_error_naming_steps(steps):
    with pytest.raises(ValueError, match=r"steps = "):
        tethersim.simulate(SAT, periods=0.1, steps=steps)


@pytest.mark.parametrize("method", ["euler", "RK4", "", None])
def test_bad_method_raises_value_error_listing_methods(method):
    with pytest.raises(ValueError, match=r"method = .*adaptive, rk4"):
        tethersim.simulate(SAT, periods=0.1, method=method)


def test_bad_model_in_simulate_raises_value_error():
    with pytest.raises(ValueError, match=r"model = 'nope'"):
        tethersim.simulate(SAT, periods=0.1, model="nope")


@pytest.mark.parametrize("rtol", [0, -1e-8, math.nan, 1e-16])
def test_bad_rtol_raises_value_error_naming_rtol(rtol):
    with pytest.raises(ValueError, match="rtol"):
        tethersim.simulate(SAT, periods=0.1, rtol=rtol)


# --- simulate and SimResult ------------------------------------------------------------

@pytest.fixture(scope="module")
def short_run():
    return tethersim.simulate(SAT, periods=0.2, check=True, progress=False)


def test_simulate_returns_simresult_with_equal_length_si_arrays(short_run):
    res = short_run
    assert isinstance(res, SimResult)
    assert res.status == "ok"
    n = res.t.size
    assert n == round(200 * 0.2) + 1  # adaptive output: 200 samples per orbit + t = 0
    for name in ("t", "x", "y", "theta", "xdot", "ydot", "thetadot"):
        arr = getattr(res, name)
        assert isinstance(arr, np.ndarray) and arr.shape == (n,), name
        assert np.all(np.isfinite(arr)), name
    assert res.orbit.shape == (n, 4)
    assert np.all(np.diff(res.t) > 0)
    # SI: seconds, metres, radians (satI.toml: delta_x = 29 m, theta0_deg = 30)
    assert res.t[0] == 0.0
    assert res.t[-1] == pytest.approx(0.2 * SAT.period, rel=1e-12)
    assert res.t[-1] == pytest.approx(0.2 * 5309.64, rel=1e-5)  # period ≈ 5310 s (facts.md)
    np.testing.assert_array_equal(
        [res.x[0], res.y[0], res.theta[0], res.xdot[0], res.ydot[0], res.thetadot[0]],
        SAT.initial)
    assert res.theta[0] == pytest.approx(math.pi / 6)
    # COM on the circular orbit of radius r0 (Table 4.3), speed sqrt(μ/r0)
    r = np.hypot(res.orbit[:, 0], res.orbit[:, 1])
    np.testing.assert_allclose(r, SAT.r0, rtol=1e-9)
    assert res.orbit[0, 3] == pytest.approx(math.sqrt(MU_EARTH / SAT.r0), rel=1e-12)


def test_simulate_run_is_checked_and_converged(short_run):
    assert short_run.error_estimate is not None
    assert short_run.converged is True
    assert short_run.method == "adaptive"
    assert "converged" in short_run.label


def test_timeseries_csv_round_trips_exactly(short_run, tmp_path):
    path = tethersim.write_timeseries(short_run, tmp_path / "run.csv")
    header = path.read_text().splitlines()[0]
    assert header.startswith("t [s],delta_x [m],delta_y [m],theta [rad]")
    assert header.endswith("tension_1 [N],tension_2 [N]")
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    np.testing.assert_array_equal(data, np.column_stack([short_run.t, short_run.states,
                                                         short_run.tether_tensions()]))


def test_rk4_run_step_and_sample_count():
    res = tethersim.simulate(SAT, periods=0.5, steps=150, method="rk4", check=False,
                             progress=False)
    assert res.status == "ok"
    assert res.t.size == 151
    assert res.step == pytest.approx(0.5 * SAT.period / 150, rel=1e-14)
    assert f"{res.step:.2f}" == "17.70"  # facts.md: 17.7 s/step (thesis p. 5-2)
    assert res.faithful
    np.testing.assert_allclose(np.diff(res.t), res.step, rtol=1e-9)


def _simulation_module():
    # tethersim.simulate is the function; the module behind it
    return importlib.import_module(tethersim.simulate.__module__)


def test_unstable_rk4_step_warns_before_the_run(monkeypatch):
    # 5 periods in 50 steps: 531 s per step, while the taut-tether bounce of satI has a
    # period of tens of seconds (RK4 is stable only for h·w <= 2.83)
    mod = _simulation_module()
    calls = []
    original = mod.rk4_run

    def spy(*args):
        calls.append(1)
        return original(*args)

    monkeypatch.setattr(mod, "rk4_run", spy)
    with pytest.warns(RK4StepWarning, match="unstable") as record:
        res = tethersim.simulate(SAT, periods=5, steps=50, method="rk4", check=False,
                                 progress=False)
    assert res.status in ("diverged", "left-domain")  # flung off before it turns non-finite
    assert record[0].filename == __file__  # attributed to the caller of simulate()
    # escalated to an error, the warning stops simulate before any step is taken
    calls.clear()
    with warnings.catch_warnings():
        warnings.simplefilter("error", RK4StepWarning)
        with pytest.raises(RK4StepWarning):
            tethersim.simulate(SAT, periods=5, steps=50, method="rk4", check=False,
                               progress=False)
    assert calls == []


def test_stable_rk4_step_does_not_warn():
    # the thesis's 5 periods in 1500 steps (17.7 s per step, p. 5-2)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RK4StepWarning)
        res = tethersim.simulate(SAT, periods=5, steps=1500, method="rk4", check=False,
                                 progress=False)
    assert res.status == "ok"
    assert not tethersim.outcome(res).metrics.tumbled
