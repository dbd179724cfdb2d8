"""Roll and yaw of the 3-D models against closed forms and symmetry (docs/roll.md).

Truths used: the classical roll–yaw quartic of a rigid body in a circular orbit,
the end-body drag damping D/(2 I_roll), the thesis damper's roll damping
(c1 b² + c2 a²)/(2 I_roll), the z → −z symmetry of a planar equilibrium, and
conservation of the spin about a symmetric boom's axis (no torque about it).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.roll import (
    boom_inertias,
    case_satellite,
    roll_case,
    roll_drag_rate,
    roll_response,
    roll_yaw_quartic,
)

# compiles and runs the 3-D / free-orbit kernels: the slow tier (make test-slow, CI)
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def sat():
    return tethersim.load_preset("satI")


def test_3d_equilibrium_is_the_planar_one_with_zero_out_of_plane_coordinates(sat):
    eq2 = find_equilibrium(sat, "exact-gravity")
    eq3 = find_equilibrium(sat, "3d-exact-gravity")
    c = eq3.coordinates
    assert c["delta_z"] == 0.0 and c["phi"] == 0.0 and c["psi"] == 0.0
    assert eq3.residual < 1e-15
    # the 3-D boom carries the boxes' pitch inertia too, which the planar model has not;
    # with point masses only (boxes off) the two equilibria agree
    pts = find_equilibrium(_points(sat), "3d-exact-gravity")
    assert abs(pts.theta - eq2.theta) < 1e-12 and abs(pts.delta_x - eq2.delta_x) < 1e-9
    assert eq3.taut == (True, True) and eq3.stable and eq3.neutral == 2


def _points(sat):
    """The satellite with its boxes off (point masses)."""
    return sat.replace(inertia="points")


def test_planar_equilibrium_decouples_in_plane_and_out_of_plane_blocks(sat):
    for model in ("3d", "3d-exact-gravity", "3d-objective-damper"):
        assert roll_case(sat, "balloon", model).coupling == 0.0


def test_boom_alone_rolls_at_the_root_of_the_roll_yaw_quartic(sat):
    n = sat.omega
    s2 = roll_yaw_quartic(sat)
    i = boom_inertias(sat)
    k1 = (i["pitch"] - i["yaw"]) / i["roll"]
    assert s2 == (-(1 + 3 * k1), 0.0)  # k3 = 0: symmetric boom, neutral yaw
    for model, rtol in (("3d", 1e-6), ("3d-exact-gravity", 1e-5)):
        # exact gravity differs from the quadrupole closed form at O((a + b)/r0) ~ 2e-6
        c = roll_case(sat, "boom alone", model)
        assert c.mode("roll").frequency / n == pytest.approx(math.sqrt(-s2[0]), rel=rtol)
        assert c.mode("yaw").neutral
        # pitch of the same rigid body: ω² = 3 n² (I_roll − I_yaw) / I_pitch
        w_pitch = n * math.sqrt(3 * (i["roll"] - i["yaw"]) / i["pitch"])
        assert c.pitch.frequency == pytest.approx(w_pitch, rel=rtol)


def test_end_body_drag_damps_roll_at_the_closed_form_rate(sat):
    for case in ("boom alone", "drag area split"):
        s = case_satellite(sat, case)
        c = roll_case(sat, case, "3d")
        rate = roll_drag_rate(sat, (s.A1, s.A2))
        assert -c.mode("roll").eigenvalue.real == pytest.approx(rate, rel=1e-5)


def test_thesis_damper_damps_roll_at_c_b_squared_over_twice_the_inertia(sat):
    for factor in (1.0, 3.0):
        s = sat.replace(c1=sat.c1 * factor, c2=sat.c2 * factor)
        rate = ((s.c1 * s.b**2 + s.c2 * s.a**2) / (2 * boom_inertias(s)["roll"])
                + roll_drag_rate(s))
        c = roll_case(s, "balloon", "3d")
        assert -c.mode("roll").eigenvalue.real == pytest.approx(rate, rel=2e-3)


def test_objective_damper_balloon_adds_no_roll_stiffness_or_damping(sat):
    boom = roll_case(sat, "boom alone", "3d-objective-damper").mode("roll").eigenvalue
    bal = roll_case(sat, "balloon", "3d-objective-damper").mode("roll").eigenvalue
    assert bal.imag == pytest.approx(boom.imag, rel=1e-6)
    assert bal.real == pytest.approx(boom.real, rel=1e-4)


def test_tether_springs_alone_add_no_roll_stiffness(sat):
    # thesis model with its dampers off: the springs and the balloon's drag remain
    boom = roll_case(sat, "boom alone", "3d").mode("roll").eigenvalue
    springs = roll_case(sat.replace(c1=0.0, c2=0.0), "balloon", "3d").mode("roll").eigenvalue
    assert springs.imag == pytest.approx(boom.imag, rel=1e-6)


def test_simulated_roll_decay_matches_the_linear_mode(sat):
    r = roll_response(sat, "3d", periods=20)
    linear = -roll_case(sat, "balloon", "3d").mode("roll").eigenvalue.real
    assert r.result.status == "ok"
    assert r.roll_decay_rate == pytest.approx(linear, rel=0.03)
    assert r.orbit_peaks["phi"][0] == pytest.approx(math.radians(5.0))


def test_spin_about_a_symmetric_boom_is_conserved(sat):
    # no force acts about the boom axis and I_roll = I_pitch: ω·boom axis is constant
    s = sat.replace(initial_3d={"phi": math.radians(5), "psi": math.radians(5),
                                "delta_z": 1.0, "psi_dot": 1e-4})
    res = tethersim.simulate(s, periods=3, model="3d-exact-gravity", progress=False)
    b = res.bodies()
    spin = np.einsum("ni,ni->n", b.angular_velocity, b.attitude[:, :, 1])
    assert np.max(np.abs(spin - spin[0])) < 1e-9 * np.max(np.abs(b.angular_velocity))
