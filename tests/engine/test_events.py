"""The stopping limits are events located inside the compiled loops (engine/events.py).

Independent truths for the located time: for RK4, plain bisection on τ of the
event function at the engine's own RK4 step from the last row before the event
(the step replayed through rk4_run with every stopping event off); for the
adaptive method, scipy's solve_ivp (Radau-free DOP853 at rtol 1e-13, its own event
location on its dense output) started from the last sample before the event.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import tethersim as ts
from tethersim.engine.domain import MAX_STRETCH, ROLL_LIMIT, reach, state_violation
from tethersim.engine.dynamics import derivative
from tethersim.engine.evaluate import tether_margin_series
from tethersim.engine.events import EVENTS, N_EVENTS, SLOT, event_parameters, events_at
from tethersim.engine.integrators.rk4 import STATUS_OK, rk4_run
from tethersim.engine.integrators.select import specialised
from tethersim.engine.integrators.switching import RTOL_TAU
from tethersim.engine.simulate import _run_adaptive
from tethersim.model.inputs import air_vector

LOCATED = 1e-6  # s: issue 20's bound on a located event time


@pytest.fixture(scope="module")
def sat():
    return ts.load_preset("satI")


@pytest.fixture(scope="module")
def blown(sat):
    """115 km (allowed knowingly): the air pulls the balloon past its tethers' limit in ~2 s."""
    return sat.replace(altitude=115e3, allow_implausible=True)


def _g(res, slot, y, stops=None):
    ev = event_parameters(res.satellite, res.model, *(() if stops is None else (stops,)))
    return events_at(res.layout.index, y, res.parameters, ev)[slot]


def _rk4_step(res, y, tau):
    """The engine's own RK4 step of size tau from y (rk4_run, every stopping event off)."""
    m = res.layout.index
    air = air_vector(res.satellite, res.t[-1])
    y = np.array(y, dtype=float)
    p = res.parameters
    out_t, out_y = np.empty(2), np.empty((2, y.size))
    args = (air, 0, y, tau, 1, 1, p, p.copy(), event_parameters(res.satellite, res.model, ()),
            False, out_t, out_y, 0)
    rows, _, st, _, _ = specialised(rk4_run, m, args)(m, *args)
    assert st == STATUS_OK and rows == 1
    return y


def _rk4_root(res, slot):
    """Bisection (to 1e-10 s) on τ of g(step(y_k, τ)) from the last row before the event."""
    y0, t0, h = res.states[-2], res.t[-2], res.step
    # the replayed step is the engine's: the step before reproduces the row before, bit for bit
    if res.t.size >= 3:
        assert np.array_equal(_rk4_step(res, res.states[-3], h), y0)
    lo, hi = 0.0, h
    assert _g(res, slot, y0) > 0 >= _g(res, slot, _rk4_step(res, y0, h))
    while hi - lo > 1e-10:
        mid = 0.5 * (lo + hi)
        if _g(res, slot, _rk4_step(res, y0, mid)) > 0:
            lo = mid
        else:
            hi = mid
    return t0 + 0.5 * (lo + hi)


def _ivp_root(res, slot, stops=None, rtol=1e-13):
    """solve_ivp's event time from the last sample before the event, on the same rhs."""
    m = res.layout.index
    air = air_vector(res.satellite, res.t[-1])
    p = res.parameters
    pw, dydt = p.copy(), np.empty(res.states.shape[1])
    f = specialised(derivative, m, (air, 0.0, res.states[-2].copy(), p, pw, dydt), loud=False)

    def rhs(t, y):
        f(m, air, t, np.ascontiguousarray(y), p, pw, dydt)
        return dydt.copy()

    def event(t, y):
        return _g(res, slot, y, stops)
    event.terminal = True
    span = res.t[-1] - res.t[-2]
    sol = solve_ivp(rhs, (res.t[-2], res.t[-1] + span), res.states[-2], method="DOP853",
                    rtol=rtol, atol=1e-12 * np.maximum(np.abs(res.states[-2]), 1.0),
                    events=event)
    assert sol.t_events[0].size == 1
    return float(sol.t_events[0][0])


def _check_landing(res, slot, stops=None):
    """The run ends just past the crossing: the last sample at the event time, the event
    function there ≤ 0 and within the bracket (RTOL_TAU of a step) times its rate."""
    assert res.event == EVENTS[slot].name and res.status == EVENTS[slot].status
    assert res.t[-1] == res.event_time and np.all(np.diff(res.t) > 0)
    g = np.array([_g(res, slot, y, stops) for y in res.states])
    assert np.all(g[:-1] > 0) and g[-1] <= 0
    rate = (g[-2] - g[-1]) / (res.t[-1] - res.t[-2])  # |ġ| over the last interval
    step = res.step if res.step is not None else res.t[-1] - res.t[-2]
    assert abs(g[-1]) <= 10 * RTOL_TAU * step * rate


def test_the_event_table_is_the_vector_the_loops_evaluate(sat):
    """Slots: the two tether margins, then the stopping limits; a slot a model lacks is
    +1 (a circular planar model has no re-entry, no roll)."""
    assert N_EVENTS == len(EVENTS) and [e.terminal for e in EVENTS[:2]] == [False, False]
    assert all(e.terminal for e in EVENTS[2:])
    res = ts.simulate(sat, periods=0.05, progress=False)
    y = res.states[-1]
    g = events_at(0, y, res.parameters, event_parameters(sat, "derived"))
    margins = tether_margin_series(0, res.states[-1:], res.parameters)[0]
    assert g[0] == margins[0] and g[1] == margins[1]
    assert g[SLOT["re-entry"]] == 1.0 and g[SLOT["roll"]] == 1.0
    assert g[SLOT["balloon reach"]] == pytest.approx(reach(sat) ** 2 - y[0] ** 2 - y[1] ** 2)
    for j, l0 in ((0, sat.l10), (1, sat.l20)):
        assert g[SLOT[f"tether {j + 1} stretch"]] == pytest.approx(MAX_STRETCH * l0
                                                                   - (margins[j] + l0))


@pytest.mark.parametrize("seed", range(3))
def test_the_stretch_slots_skip_the_tether_lengths_only_where_no_stretch_is_possible(sat, seed):
    """Without switch location the loops skip the two hypot where the balloon is too close
    to any stretch limit (|λ_j| <= |δ| + end_j); the stretch slots' signs are those of the
    full evaluation everywhere, their values wherever the lengths were evaluated."""
    ev = event_parameters(sat, "derived")
    p = ts.simulate(sat, periods=0.01, progress=False).parameters
    rng = np.random.default_rng(seed)
    for radius in np.linspace(1.0, 1.2 * MAX_STRETCH * 6.0, 400) * rng.uniform(0.9, 1.0, 400):
        ang = rng.uniform(-np.pi, np.pi)
        y = np.zeros(10)
        y[0], y[1], y[2] = radius * math.cos(ang), radius * math.sin(ang), rng.uniform(-1, 1)
        full, fast = events_at(0, y, p, ev, True), events_at(0, y, p, ev, False)
        for s in (5, 6):
            assert (full[s] > 0) == (fast[s] > 0)
            assert fast[s] == 1.0 or fast[s] == full[s]


def test_an_absent_line_has_no_stretch_limit_and_a_present_one_keeps_it(sat):
    """One line flown alone (the other's E = c = 0, no mass): the absent line's length can
    be anything, so its stretch slot never fires; the line that holds keeps its limit."""
    alone = sat.replace(E2=0.0, c2=0.0)
    p = ts.simulate(sat, periods=0.01, progress=False).parameters
    y = np.zeros(10)
    y[0] = 1.5 * MAX_STRETCH * sat.l20  # past both lines' limits
    for who, ev in (("both", event_parameters(sat, "derived")),
                    ("alone", event_parameters(alone, "derived"))):
        g = events_at(0, y, p, ev, True)
        assert g[SLOT["tether 1 stretch"]] < 0
        assert (g[SLOT["tether 2 stretch"]] < 0) == (who == "both"), who


@pytest.mark.parametrize("method", ["rk4", "adaptive"])
def test_a_tether_stretch_is_located_to_a_microsecond(blown, method):
    if method == "rk4":
        res = ts.simulate(blown, periods=0.05, steps=400, method="rk4", progress=False)
    else:
        res = ts.simulate(blown, periods=0.05, rtol=1e-13, atol=1e-14, progress=False)
    slot = SLOT[res.event]
    assert res.event in ("tether 1 stretch", "tether 2 stretch")
    _check_landing(res, slot)
    truth = _rk4_root(res, slot) if method == "rk4" else _ivp_root(res, slot)
    assert abs(res.event_time - truth) <= LOCATED


def test_the_balloon_reach_is_located_to_a_microsecond(blown):
    """With the stretch limits off, the balloon passes its reach (10 x the tether path)."""
    stops = ("balloon reach",)
    res = _run_adaptive(blown, 0.05, 20, "derived", 1e-13, 1e-14, True, False, stops=stops)
    assert res.event == "balloon reach" and res.status == "left-domain"
    slot = SLOT["balloon reach"]
    _check_landing(res, slot, stops)
    assert abs(res.event_time - _ivp_root(res, slot, stops)) <= LOCATED
    assert math.hypot(res.x[-1], res.y[-1]) == pytest.approx(reach(blown), rel=1e-9)


@pytest.mark.parametrize("locate", [True, False])
def test_evaluating_the_events_changes_no_step_of_a_run_that_meets_none(sat, locate):
    """A run with every stopping limit watched, and the same run with none: the same steps
    and samples to the last bit (a located switch included, locate=True)."""
    ok = ts.simulate(sat, periods=1, locate_switches=locate, progress=False)
    bare = _run_adaptive(sat, 1, 200, "derived", 1e-10, 1e-12, locate, False, stops=())
    assert ok.status == bare.status == "ok" and ok.event is None
    np.testing.assert_array_equal(ok.states, bare.states)
    assert (ok.nfev, ok.n_switches) == (bare.nfev, bare.n_switches)


def test_state_violation_words_the_same_limits(sat, blown):
    res = ts.simulate(blown, periods=0.05, progress=False)
    assert "stretched to" in state_violation(blown, "derived", res.states[-1][:6])
    assert state_violation(sat, "derived", res.states[0][:6]) == ""


@pytest.mark.slow  # compiles the free-orbit loop
@pytest.mark.parametrize("method", ["rk4", "adaptive"])
def test_a_re_entry_is_located_to_a_microsecond(sat, method):
    """A free orbit from 200 km with the re-entry altitude set 1 km below the start: the
    orbit's radial oscillation and the decay take it there within an orbit."""
    free = sat.replace(orbit="free", reentry_altitude=199e3)
    if method == "rk4":
        res = ts.simulate(free, periods=1, steps=200, method="rk4", progress=False)
    else:
        res = ts.simulate(free, periods=1, rtol=1e-13, atol=1e-14, progress=False)
    assert res.status == "re-entered" and res.reentry_time == res.event_time
    slot = SLOT["re-entry"]
    _check_landing(res, slot)
    assert res.altitude[-1] <= 199e3 < res.altitude[-2]
    truth = _rk4_root(res, slot) if method == "rk4" else _ivp_root(res, slot)
    assert abs(res.event_time - truth) <= LOCATED


@pytest.mark.slow  # compiles the 3-D loop
@pytest.mark.parametrize("method", ["rk4", "adaptive"])
def test_a_roll_past_the_limit_is_located_to_a_microsecond(sat, method):
    tumbling = sat.replace(initial_3d={"phi_dot": 10 * sat.omega})
    if method == "rk4":
        res = ts.simulate(tumbling, periods=0.5, steps=100, method="rk4", model="3d",
                          progress=False)
    else:
        res = ts.simulate(tumbling, periods=0.5, rtol=1e-13, atol=1e-14, model="3d",
                          progress=False)
    slot = SLOT["roll"]
    _check_landing(res, slot)
    assert abs(res.series("phi")[-1]) == pytest.approx(ROLL_LIMIT, abs=1e-9)
    truth = _rk4_root(res, slot) if method == "rk4" else _ivp_root(res, slot)
    assert abs(res.event_time - truth) <= LOCATED
