"""The 3-D model on a free orbit through the engine: ``orbit = "free"`` with ``model="3d"``."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.model.constants import J2_EARTH, MU_EARTH, R_EARTH
from tethersim.model.inputs import initial_model_state, parameter_vector

# compiles the 16-state kernels into the engine's loops: the slow tier
pytestmark = pytest.mark.slow

SAT = ts.load_preset("satI")


def test_3d_on_a_free_orbit_runs_end_to_end_and_a_planar_start_stays_planar():
    res = ts.simulate(SAT.replace(orbit="free"), model="3d", periods=0.2, progress=False)
    assert res.model == "3d-free" and res.status == "ok"
    for name in ("delta_z", "phi", "psi"):
        assert np.all(res.series(name) == 0.0)
    # the orbit is free: r moves, the altitude is the reference point's
    assert np.ptp(res.series("r")) > 0.0
    np.testing.assert_allclose(res.altitude, res.series("r") - R_EARTH, rtol=0, atol=1e-6)


def test_initial_state_and_parameters_are_filled_by_name():
    sat = SAT.replace(orbit="free", j2=True, eccentricity=0.001, initial_3d={"phi": 0.05})
    y = dict(zip(ts.model.registry.get_model("3d-free").state, initial_model_state(sat, "3d-free")))
    planar = dict(zip(ts.model.registry.get_model("free").state, initial_model_state(sat, "free")))
    assert all(y[n] == v for n, v in planar.items())
    assert y["phi"] == 0.05 and y["delta_z"] == 0.0
    assert y["r"] == sat.r0 and math.isclose(y["nu_dot"] ** 2 * sat.r0**3 / MU_EARTH,
                                             1.001 * (1 + 1.5 * J2_EARTH * (R_EARTH / sat.r0) ** 2),
                                             rel_tol=1e-12)
    p = dict(zip(ts.model.registry.get_model("3d-free").parameters, parameter_vector(sat, "3d-free")))
    assert p["J2"] > 0 and p["I2_pitch"] == pytest.approx(SAT.m2 * 2 * SAT.A2 / 12)


def test_an_out_of_plane_start_librates_in_roll_and_loses_energy_to_drag():
    sat = SAT.replace(orbit="free", initial_3d={"phi": 0.05, "delta_z": 2.0})
    res = ts.simulate(sat, model="3d", periods=0.5, progress=False)
    assert res.status == "ok"
    phi = res.series("phi")
    assert phi.min() < -0.01 and phi.max() > 0.01  # the roll libration crosses zero
    assert res.series("r")[-1] < res.series("r")[0]  # drag lowers the orbit
