"""The implicit Radau IIA loop (engine/integrators/radau.py) against independent truths:
numpy's LU solve, the generated analytic Jacobian, a tight DOP853 reference run, and
itself run in one call versus resumed in many."""
from __future__ import annotations

import math

import numpy as np
import pytest
from numba import literally, njit

import tethersim as ts
from tethersim.engine.dynamics import derivative
from tethersim.engine.events import SLOT, event_parameters
from tethersim.engine.integrators.linalg import fd_jacobian, lu_factor, lu_solve
from tethersim.engine.integrators.radau import N_COUNTERS, carry_size, radau_run
from tethersim.engine.integrators.select import call, specialised
from tethersim.model.inputs import air_vector, initial_model_state, parameter_vector
from tethersim.model.registry import KERNELS, model_index

SAT = ts.load_preset("satI")
# a real fibre line (EA = 9e4 N, issue 21) cut to the thesis's stretched geometry: an
# axial mode near 56 rad/s, slack/taut switches every second or so
STIFF = SAT.replace(E1=9e4, E2=9e4, l10=30.83, l20=28.92, allow_implausible=True)


def _radau(sat, periods, rtol, pauses=(), model="derived", atol=1e-12, locate=True):
    """(final state, counters, output) of radau_run over ``periods`` orbits; the run
    returns at each pause time and is resumed, as simulate's progress bar does."""
    t_end = periods * sat.period
    m, air = model_index(model), air_vector(sat, t_end)
    p = parameter_vector(sat, model)
    pw = p.copy()
    y = initial_model_state(sat, model)
    out_t = np.linspace(0.0, t_end, 21)
    out_y = np.full((out_t.size, y.size), np.nan)
    out_y[0] = y
    counters = np.zeros(N_COUNTERS, dtype=np.int64)
    carry = np.zeros(carry_size(y.size))
    ev = event_parameters(sat, model)
    t, h, i_out = 0.0, 0.0, 1
    for t_pause in (*pauses, math.inf):
        args = (air, t, t_end, y, h, p, pw, ev, rtol, atol, locate, out_t, out_y, i_out, 10**8,
                counters, carry, t_pause)
        t, h, i_out, status, _ = specialised(radau_run, m, args)(m, *args)
        assert status == 0
    assert t == t_end and i_out == out_t.size
    return y, counters, out_y


@pytest.mark.parametrize("dtype", [float, complex])
def test_lu_solve_matches_numpy_solve_with_pivoting(dtype):
    """Real (Radau's real system) and complex (its complex pair, radau_step._factor)."""
    rng = np.random.default_rng(3)
    for n in (1, 2, 5, 10, 20):
        A = rng.normal(size=(n, n)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1))
        b = rng.normal(size=n).astype(dtype)
        if dtype is complex:
            A = A + 1j * rng.normal(size=(n, n)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1))
            b += 1j * rng.normal(size=n)
        if n > 1:
            A[0, 0] = 0.0  # the first pivot must be a swap
        LU, piv, x = A.copy(), np.empty(n, dtype=np.int64), b.copy()
        lu_factor(LU, piv, n)
        lu_solve(LU, piv, x, n)
        assert np.allclose(x, np.linalg.solve(A, b), rtol=1e-10, atol=0)


def test_finite_difference_jacobian_matches_the_generated_one():
    m = model_index("derived")
    p = parameter_vector(SAT, "derived")
    y = initial_model_state(SAT, "derived")
    n = y.size  # the generated model's own states, all that is integrated
    J_ref = np.zeros((n, n))
    KERNELS[m].jacobian(0.0, y.copy(), p, J_ref)
    air = air_vector(SAT, SAT.period)
    f = np.empty(y.size)
    call(_derivative_of, m, air, y, p, f)
    J = np.empty((y.size, y.size))
    call(_fd, m, air, y, f, p, J)
    scale = np.abs(J_ref).max(axis=0) + 1e-300
    assert np.all(np.abs(J[:n, :n] - J_ref) <= 1e-6 * scale)


@njit
def _derivative_of(model, air, y, p, f):
    literally(model)
    derivative(model, air, 0.0, y, p, p.copy(), f)


@njit
def _fd(model, air, y, f, p, J):
    literally(model)
    fd_jacobian(model, air, 0.0, y, f, p, p.copy(), J, np.empty(y.size), np.empty(y.size))


def test_a_run_resumed_in_calls_takes_the_steps_of_one_call():
    one, c1, out1 = _radau(SAT, 0.5, 1e-8)
    many, c2, out2 = _radau(SAT, 0.5, 1e-8, pauses=(1.0, 300.0, 301.0, 1200.0))
    assert one.tobytes() == many.tobytes() and out1.tobytes() == out2.tobytes()
    assert c1[1] == c2[1] and c1[2] == c2[2]  # accepted, rejected steps


def test_error_against_a_tight_reference_falls_with_the_tolerance():
    ref = ts.simulate(SAT, 1, rtol=1e-13, atol=1e-14, progress=False).states[-1, :6]
    scale = np.maximum(np.abs(ref), 1.0)
    errors = []
    for rtol in (1e-6, 1e-8, 1e-10):
        y, _, _ = _radau(SAT, 1, rtol)
        errors.append(float(np.max(np.abs(y[:6] - ref) / scale)))
        assert errors[-1] <= 100 * rtol
    assert errors[0] > errors[1] > errors[2]


@pytest.mark.slow
def test_stiff_tethers_with_switches_agree_with_dop853():
    """EA = 9e4 N lines (axial mode ~56 rad/s) bouncing slack/taut: Radau with its
    switches located on the dense output agrees with a tight DOP853 run."""
    periods = 0.01
    # from the preset's deployment (a real line would otherwise start at rest at its
    # equilibrium, engine/start.py, and never bounce), as _radau starts
    ref = ts.simulate(STIFF, periods, rtol=1e-12, atol=1e-13, progress=False, start="given")
    assert ref.status == "ok" and ref.n_switches > 0
    y, c, _ = _radau(STIFF, periods, 1e-9)
    assert c[3] > 0  # switches located
    assert np.allclose(y[:6], ref.states[-1, :6], rtol=1e-5, atol=1e-6)


@pytest.mark.slow  # the free-orbit model's Radau and DOP853 loops (~40 s cold), a 5 s reference
def test_newton_does_not_stall_on_the_rounding_of_a_nearly_unloaded_real_line():
    """SatI's stretched Dyneema bridle on a free orbit at 400 km: the lines carry 0.2 mN, so
    their force is mostly rounding (EA/l0 ulp(λ) ~ 1e-11 N).  Radau's Newton stops at
    NEWTON_TOL of the error scale and steps over the 77 rad/s axial mode: under 10,000
    steps for 2 h at rtol 1e-8, a rejection for every three or more accepted (with scipy's
    tolerance: 26,885 steps and more rejected than accepted), and the final state
    agrees with a tight DOP853 run to ten times rtol of the balloon's 29 m distance (θ: of
    1 rad).  Not closer: with lines this unloaded the last digits are the arithmetic's.
    Measured (AMD EPYC Zen 4): perturbing m3 by 1e-13 of itself, a change with no
    physical meaning, moves Radau's δy error between 2.5e-9 and 4.1e-8 m, DOP853's at the
    same rtol between 2e-9 and 5.5e-8 m; the Kelvin-Voigt clamp's regenerated code (the
    same forces, other roundings) between 4.6e-8 and 2.9e-7 m, and DOP853's between 5e-10
    and 9.7e-8 m; without dampers, Radau's reached 1.7e-7 m on the old code too."""
    from tethersim.experiments.feasibility import FeasibilitySpec
    from tethersim.experiments.real_tethers import REAL_MODEL, STRETCHED_LENGTHS, real_lines
    spec = FeasibilitySpec(real_lines(SAT, STRETCHED_LENGTHS), (400.0,), model=REAL_MODEL,
                           method="implicit")
    sat = spec.free(400.0, SAT.A3)
    kw = dict(periods=2 * 3600 / sat.period, model=REAL_MODEL, progress=False)
    rtol = 1e-8
    ref = ts.simulate(sat, method="adaptive", rtol=1e-11, atol=1e-13, **kw)
    res = ts.simulate(sat, method="implicit", rtol=rtol, atol=rtol * 1e-2, **kw)
    assert ref.status == res.status == "ok"
    assert res.n_accepted < 10_000 and 3 * res.n_rejected < res.n_accepted
    err = np.abs(res.states[-1] - ref.states[-1])
    distance = math.hypot(*ref.states[-1, :2])
    assert np.all(err[:3] <= 10 * rtol * np.array([distance, distance, 1.0]))  # δx, δy, θ
    assert err[3] <= 1e-12 * ref.states[-1, 3]  # r


def test_simulate_implicit_agrees_with_dop853_and_says_which_scheme():
    ref = ts.simulate(SAT, 1, rtol=1e-13, atol=1e-14, progress=False)
    res = ts.simulate(SAT, 1, method="implicit", rtol=1e-9, progress=False)
    assert res.method == "implicit" and res.status == "ok" and res.t.size == ref.t.size
    assert "Radau IIA implicit, rtol 1e-09" in res.label
    scale = np.maximum(np.abs(ref.states[:, :6]).max(axis=0), 1.0)
    assert np.all(np.abs(res.states[:, :6] - ref.states[:, :6]) <= 1e-6 * scale)
    # its error estimate reruns the same scheme, tighter
    assert res.estimate_error().converged


def test_a_tether_stretch_is_located_by_the_implicit_scheme_to_a_microsecond():
    """The blown-out balloon of tests/engine/test_events.py (115 km): Radau locates the stretch
    limit on its dense output and lands a converged step there; the time agrees with
    scipy's DOP853 event location from the last sample before it."""
    from tests.engine.test_events import LOCATED, _ivp_root
    blown = SAT.replace(altitude=115e3, allow_implausible=True)
    res = ts.simulate(blown, periods=0.05, method="implicit", rtol=1e-12, atol=1e-14,
                      progress=False)
    assert res.event in ("tether 1 stretch", "tether 2 stretch")
    assert res.status == "left-domain" and res.t[-1] == res.event_time
    assert abs(res.event_time - _ivp_root(res, SLOT[res.event])) <= LOCATED
