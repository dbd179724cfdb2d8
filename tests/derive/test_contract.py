"""One contract for every registered model (``tethersim.MODELS``): energy rate and Jacobian.

For each model, at a SatI state off equilibrium (balloon displaced and moving,
boom pitched, rolled and turning, both tethers taut; on a free orbit for the
free models, climbing):

* dh/dt = ∇h · ẏ, with ∇h by central differences of the generated ``jacobi``
  and ẏ the generated ``rhs``, equals the power of the dissipative families,
  Σ_{drag, damper} Q_f · q̇ (the generated ``family_forces``): the Jacobi
  integral (total energy for a free orbit) plus the spring energy changes only
  by the work of drag and dampers;
* with C_D = 0 and c1 = c2 = 0 that power is 0 and h is stationary;
* the model's Jacobian (tethersim.engine.jacobian: generated for the planar
  models, central differences for the others) equals differences of its rhs.

An instantaneous form of the budget the run tests check along trajectories
(tests/engine/test_energy.py, tests/derive/test_3d_jacobi.py,
tests/derive/test_orbit_physics.py), the same for every geometry and orbit, so a
model that `make derive` adds is checked with no edit here.
"""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tethersim.engine.jacobian import STEP, jacobian
from tethersim.model.inputs import initial_model_state, parameter_vector
from tethersim.model.registry import BY_NAME, KERNELS

MOTION = dict(delta_x_dot=0.3, delta_y_dot=-0.2, theta=0.1, theta_dot=1e-3, delta_z=2.0,
              delta_z_dot=0.1, phi=0.05, phi_dot=-2e-4, psi=0.1, psi_dot=3e-4, r_dot=3.0)
GRADIENT_STEP = 1e-4  # relative: the free models' h is ~3.5e9 J, rounding ε|h|/step


def _case(name, **changes):
    model = BY_NAME[name]
    sat = ts.load_preset("satI").replace(**changes)
    if model.orbit == "free":
        sat = sat.replace(orbit="free")
    y = initial_model_state(sat, name).copy()
    for k, v in MOTION.items():
        if k in model.state:
            y[model.state.index(k)] += v
    return model, y, parameter_vector(sat, name)


def _rate_and_power(name, **changes):
    """(∇h · ẏ, dissipated power, Σ |∂h/∂y_i ẏ_i|) [W] at the state of :func:`_case`."""
    model, y, p = _case(name, **changes)
    mod = KERNELS[model.index]
    ydot = np.empty_like(y)
    mod.rhs(0.0, y, p, ydot)
    g = np.empty(len(y))
    for c in range(len(y)):
        h = GRADIENT_STEP * max(abs(y[c]), 1.0)
        hi, lo = y.copy(), y.copy()
        hi[c] += h
        lo[c] -= h
        g[c] = (mod.jacobi(hi, p) - mod.jacobi(lo, p)) / (hi[c] - lo[c])
    margins = np.empty(2)
    mod.tether_margins(y, p, margins)
    assert np.all(margins > 1.0)  # both taut, far from the switch: h is smooth here
    n = model.n_coordinates
    out = np.zeros((len(model.families), n))
    mod.family_forces(y, p, out)
    dissipative = [i for i, f in enumerate(model.families) if f.startswith(("drag", "damper"))]
    power = float(np.sum(out[dissipative] @ y[n:]))
    terms = g * ydot
    return float(np.sum(terms)), power, float(np.sum(np.abs(terms)))


def _params():
    # the 3-D and free models compile for tens of seconds cold: the slow tier
    return [name if (BY_NAME[name].geometry, BY_NAME[name].orbit) == ("planar", "circular")
            else pytest.param(name, marks=pytest.mark.slow) for name in ts.MODELS]


@pytest.mark.parametrize("name", _params())
def test_jacobi_integral_changes_by_the_power_of_drag_and_dampers(name):
    rate, power, scale = _rate_and_power(name)
    assert power != 0.0  # (in the rotating frame the steady drag "wind" may also feed h)
    assert abs(rate - power) <= 1e-6 * scale, (rate, power, scale)


@pytest.mark.parametrize("name", _params())
def test_jacobi_integral_is_stationary_without_drag_and_dampers(name):
    rate, power, scale = _rate_and_power(name, CD=0.0, c1=0.0, c2=0.0)
    assert power == 0.0
    assert abs(rate) <= 1e-6 * scale, (rate, scale)


@pytest.mark.parametrize("name", _params())
def test_jacobian_equals_central_differences_of_rhs(name):
    """tethersim.engine.jacobian (generated, or its own differences) against differences of
    the generated rhs at a 16 times larger step, per row to 1e-6 of the row's largest entry."""
    model, y, p = _case(name)
    n = len(y)
    J = np.empty((n, n))
    jacobian(model.index, 0.0, y, p, J)
    fd = np.empty((n, n))
    dp, dm = np.empty(n), np.empty(n)
    for c in range(n):
        h = 16 * STEP * max(abs(y[c]), 1.0)
        hi, lo = y.copy(), y.copy()
        hi[c] += h
        lo[c] -= h
        KERNELS[model.index].rhs(0.0, hi, p, dp)
        KERNELS[model.index].rhs(0.0, lo, p, dm)
        fd[:, c] = (dp - dm) / (hi[c] - lo[c])
    scale = np.max(np.abs(fd), axis=1, keepdims=True)
    assert np.all(np.abs(J - fd) <= 1e-6 * scale), np.max(np.abs(J - fd) / scale)
