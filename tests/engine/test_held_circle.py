"""A circular-orbit run integrates only its model's states; its COM orbit is the closed
form r0 (cos ωt, sin ωt) (issue 22), checked against an integration of Eq 3.9."""
from __future__ import annotations

import inspect
import re

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import tethersim as ts
from tethersim.engine.dynamics import held_circle
from tethersim.model.constants import R_EARTH
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import KERNELS, MODELS

SAT = ts.load_preset("satI")
CIRCULAR = [m for m in MODELS if m.orbit == "circular"]


@pytest.fixture(scope="module")
def run():
    return ts.simulate(SAT, periods=1.5, samples=60, check=False, progress=False)


@pytest.mark.parametrize("method", ["rk4", "adaptive"])
def test_a_circular_run_integrates_only_the_model_states(method):
    kw = dict(steps=90) if method == "rk4" else {}
    res = ts.simulate(SAT, periods=0.3, method=method, check=False, progress=False, **kw)
    assert held_circle(res.layout.index)
    assert res.states.shape == (res.t.size, res.layout.n_state)
    assert res.model_states is res.states


def test_the_held_circle_is_the_two_body_orbit_from_table_4_3(run):
    """Eq 3.9 integrated tightly from Table 4.3's start (r0, 0) moving +Y at r0 ω, with the
    run's own μ: the closed form matches it to 1e-9 of r0 and of r0 ω."""
    m = run.layout
    p = run.parameters
    mu, r0, omega = (p[m.parameters.index(n)] for n in ("mu", "r0", "omega"))
    assert (r0, omega) == (SAT.r0, SAT.omega)

    def two_body(t, s):
        k = -mu / np.hypot(s[0], s[1]) ** 3
        return [s[2], s[3], k * s[0], k * s[1]]

    sol = solve_ivp(two_body, (0.0, run.t[-1]), [r0, 0.0, 0.0, r0 * omega], method="DOP853",
                    rtol=1e-13, atol=1e-9, t_eval=run.t)
    truth = sol.y.T
    assert np.max(np.abs(run.orbit[:, :2] - truth[:, :2])) < 1e-9 * r0
    assert np.max(np.abs(run.orbit[:, 2:] - truth[:, 2:])) < 1e-9 * r0 * omega
    assert np.all(run.altitude == r0 - R_EARTH)


def test_the_bodies_map_puts_the_com_on_the_same_circle(run):
    """tethersim.bodies (engine/bodies.py) and SimResult.orbit: one circle, to 1 mm."""
    b = run.bodies()
    assert np.max(np.abs(b.com_position[:, :2] - run.orbit[:, :2])) < 1e-3
    assert np.max(np.abs(b.com_velocity[:, :2] - run.orbit[:, 2:])) < 1e-6
    assert np.all(b.com_position[:, 2] == 0.0)


@pytest.mark.parametrize("model", [m.name for m in CIRCULAR])
def test_no_circular_rhs_reads_past_the_model_state(model):
    """Every state index the generated code reads is < n_state (its source, each model)."""
    m = next(x for x in CIRCULAR if x.name == model)
    k = KERNELS[m.index]
    for fn in (k.rhs, k.tether_margins, k.body_radii):
        src = inspect.getsource(fn.py_func if hasattr(fn, "py_func") else fn)
        read = {int(i) for i in re.findall(r"\by\[(\d+)\]", src)}
        assert read and max(read) < m.n_state, fn
        assert not re.search(r"\by\[[^0-9]", src), fn  # no computed index, no slice


def test_the_derived_rhs_ignores_anything_after_the_model_state():
    """Run, not read: NaN after the 6 states changes neither dydt nor anything after it."""
    p = parameter_vector(SAT, MODELS[0].name)
    y = np.array([29.0, 0.5, 0.3, 0.01, -0.02, 1e-3])
    plain = np.empty(6)
    KERNELS[0].rhs(0.0, y, p, plain)
    padded = np.concatenate([y, np.full(4, np.nan)])
    out = np.full(10, 7.0)
    KERNELS[0].rhs(0.0, padded, p, out)
    assert np.array_equal(out[:6], plain) and np.all(out[6:] == 7.0)
