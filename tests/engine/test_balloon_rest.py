"""engine/balloon_rest.py: the balloon's rest at a held pitch, against scipy's root finder."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import root

from tethersim.engine.balloon_rest import balloon_rest
from tethersim.engine.integrators.select import call
from tethersim.model.inputs import parameter_vector
from tethersim.model.presets import load_preset
from tethersim.model.registry import KERNELS, get_model

TOL = (50, 1e-11, 1e-10)  # iterations, step [m], residual [m/s^2]: PitchTorque's


def _solve(sat, theta, trail):
    m = get_model("derived").index
    p = parameter_vector(sat, "derived")
    trail = np.array(trail, float)
    y, d, J = np.zeros(6), np.empty(6), np.empty((6, 6))
    ok = call(balloon_rest, m, float(theta), trail, y, p, d, J, *TOL)
    return ok, trail, d, p


@pytest.mark.parametrize("theta", [0.0, 0.3, -1.2])
def test_balloon_rest_is_the_root_scipy_finds_of_the_balloon_accelerations(theta):
    sat = load_preset("satI")
    ok, trail, d, p = _solve(sat, theta, sat.initial[:2])
    assert ok
    f = np.empty(6)

    def acc(xy):
        KERNELS[get_model("derived").index].rhs(0.0, np.array([*xy, theta, 0, 0, 0]), p, f)
        return f[3:5].copy()
    ref = root(acc, np.array(sat.initial[:2], float), method="hybr", options={"xtol": 1e-14})
    assert np.max(np.abs(acc(ref.x))) <= TOL[2]  # hybr's own converged root
    assert np.allclose(trail, ref.x, rtol=0, atol=1e-9)
    assert np.max(np.abs(d[3:5])) <= TOL[2]
    # d is the rhs at the answer: d[5] the pitch acceleration there (PitchTorque's g)
    acc(trail)
    assert d[5] == f[5]


def test_balloon_rest_without_tethers_fails_and_leaves_the_start():
    sat = load_preset("satI").replace(E1=0.0, E2=0.0, c1=0.0, c2=0.0)
    start = np.array(sat.initial[:2], float)
    ok, trail, _, _ = _solve(sat, 0.0, start)
    assert not ok
    assert np.array_equal(trail, start)
