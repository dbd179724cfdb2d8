"""tethersim.bodies / body_accelerations against an independent Newton–Euler computation.

The forces are written here from their physical laws in the inertial frame
(exact point-mass gravity plus each box's quadrupole force and torque, drag in
co-rotating air, tension-only tether springs and the thesis dampers), with no
generated code: the balloon's inertial acceleration must be the sum of the
forces on it over m3, and the boom's angular acceleration must satisfy Euler's
equations about its COM, I α + ω × I ω = Σ torques.
"""
from __future__ import annotations

import numpy as np
import pytest

import tethersim
from tethersim.model.constants import MU_EARTH, OMEGA_EARTH
from tethersim.model.inputs import box_inertias

# compiles and runs the 3-D / free-orbit kernels: the slow tier (make test-slow, CI)
pytestmark = pytest.mark.slow

RTOL = 1e-9
EZ = np.array([0.0, 0.0, 1.0])


def _gravity(m, G, rho, I=None):
    """Force and torque (about the body's centre) of exact gravity on a body at G + rho.

    |G + rho| from |G|² + 2 G·rho + |rho|², so that nothing is lost to the
    rounding of a 6.6e6 m position.
    """
    r = G + rho
    d = np.sqrt(G @ G + 2 * G @ rho + rho @ rho)
    F = -MU_EARTH * m * r / d**3
    tau = np.zeros(3)
    if I is not None:
        rIr = r @ I @ r
        F = F + MU_EARTH / 2 * (-3 * np.trace(I) * r / d**5 - 6 * I @ r / d**5
                                + 15 * rIr * r / d**7)
        tau = 3 * MU_EARTH / d**5 * np.cross(r, I @ r)
    return F, tau


def _drag(sat, A, r, v):
    vrel = v - np.cross(OMEGA_EARTH * EZ, r)
    return -0.5 * sat.CD * A * sat.rho * np.linalg.norm(vrel) * vrel


def _tether(E, l0, c, r3, v3, r_end, v_end):
    """Force of one tether on the balloon (its reaction acts on the end body).

    r3, r_end: positions relative to the boom COM.
    """
    d = r_end - r3
    lam = np.linalg.norm(d)
    if lam <= l0:
        return np.zeros(3)
    return E * (lam / l0 - 1) * d / lam - c * (v3 - v_end)


def newton_euler(sat, b, inertia_body):
    """(balloon acceleration, boom COM torque, forces) from the inertial kinematics ``b``."""
    R = b.attitude
    boxes = [R @ np.diag(i) @ R.T for i in inertia_body]
    G = b.com_position
    (r1, r2, r3), (v1, v2, v3) = b.position, b.velocity
    (o1, o2, o3) = b.offset
    F3 = _gravity(sat.m3, G, o3)[0] + _drag(sat, sat.A3, r3, v3)
    T1 = _tether(sat.E1, sat.l10, sat.c1, o3, v3, o1, v1)
    T2 = _tether(sat.E2, sat.l20, sat.c2, o3, v3, o2, v2)
    F3 = F3 + T1 + T2
    torque = np.zeros(3)
    for m, A, o, r, v, T, Ib in ((sat.m1, sat.A1, o1, r1, v1, T1, boxes[0]),
                                 (sat.m2, sat.A2, o2, r2, v2, T2, boxes[1])):
        Fg, tg = _gravity(m, G, o, Ib)
        F = Fg + _drag(sat, A, r, v) - T
        torque += np.cross(o, F) + tg
    return F3 / sat.m3, torque


def _boom_inertia(sat, inertia_body, R):
    """The boom's inertia about its COM in N: end masses on the boom axis plus boxes."""
    pts = sat.m1 * sat.b**2 + sat.m2 * sat.a**2
    body = np.diag([pts, 0.0, pts]) + np.diag(inertia_body[0]) + np.diag(inertia_body[1])
    return R @ body @ R.T


def _body_inertias(sat):
    i = box_inertias(sat)
    # body axes in the attitude matrix's column order: roll, boom (yaw), pitch
    return [np.array([i[f"I{k}_roll"], i[f"I{k}_yaw"], i[f"I{k}_pitch"]]) for k in (1, 2)]


def _random_states(n, seed=13):
    rng = np.random.default_rng(seed)
    w = 1.2e-3
    for _ in range(n):
        yield np.concatenate([
            [29 + rng.normal(0, 3), rng.normal(0, 3), rng.normal(0, 3)],
            rng.uniform(-0.6, 0.6, 3),
            rng.normal(0, 0.05, 3),
            rng.normal(0, 3 * w, 3)])


@pytest.fixture(scope="module")
def sat():
    # damping raised so the dampers matter as much as the springs at these rates
    return tethersim.load_preset("satI").replace(c1=0.02, c2=0.03)


@pytest.mark.parametrize("k, y", list(enumerate(_random_states(6))))
def test_balloon_acceleration_equals_sum_of_forces_over_mass(sat, k, y):
    t = 517.0 * k
    b = tethersim.bodies(sat, y, t, model="3d-exact-gravity")
    acc = tethersim.body_accelerations(sat, y, t, model="3d-exact-gravity")
    truth, _ = newton_euler(sat, b, _body_inertias(sat))
    a3 = acc.acceleration[2]
    assert np.linalg.norm(a3 - truth) <= RTOL * np.linalg.norm(truth)
    # the part that is not the COM's own Keplerian acceleration (drag, tethers, tides)
    # agrees as well: a stronger statement, since it is ~1e-4 of the total
    g0 = -MU_EARTH * b.com_position / np.linalg.norm(b.com_position) ** 3
    np.testing.assert_allclose(np.linalg.norm(a3 - truth),
                               0.0, atol=RTOL * np.linalg.norm(truth - g0))


@pytest.mark.parametrize("k, y", list(enumerate(_random_states(6, seed=7))))
def test_boom_angular_acceleration_satisfies_euler_equations(sat, k, y):
    t = 311.0 * k
    b = tethersim.bodies(sat, y, t, model="3d-exact-gravity")
    acc = tethersim.body_accelerations(sat, y, t, model="3d-exact-gravity")
    inert = _body_inertias(sat)
    _, torque = newton_euler(sat, b, inert)
    I = _boom_inertia(sat, inert, b.attitude)
    w, alpha = b.angular_velocity, acc.angular_acceleration
    lhs = I @ alpha + np.cross(w, I @ w)
    scale = max(np.linalg.norm(torque), np.linalg.norm(I @ alpha))
    assert np.linalg.norm(lhs - torque) <= RTOL * scale


def test_tethers_taut_and_drag_on_in_the_random_states(sat):
    # the checks above exercise every force: both tethers taut, drag non-zero
    for y in _random_states(6):
        b = tethersim.bodies(sat, y, model="3d-exact-gravity")
        (r1, r2, r3) = b.offset
        assert np.linalg.norm(r1 - r3) > sat.l10 and np.linalg.norm(r2 - r3) > sat.l20


def test_end_bodies_are_rigidly_carried_by_the_boom(sat):
    y = next(_random_states(1))
    b = tethersim.bodies(sat, y, 100.0, model="3d")
    axis = b.attitude[:, 1]
    np.testing.assert_allclose(b.position[0] - b.com_position, sat.b * axis, rtol=0, atol=1e-8)
    np.testing.assert_allclose(b.offset[0], sat.b * axis, rtol=1e-15)
    np.testing.assert_allclose(b.velocity[1] - b.com_velocity,
                               np.cross(b.angular_velocity, -sat.a * axis), rtol=0,
                               atol=1e-11)
    np.testing.assert_allclose(b.attitude.T @ b.attitude, np.eye(3), atol=1e-15)


def test_velocities_are_time_derivatives_of_positions(sat):
    # central differences of bodies() along the exact trajectory y(t) ≈ y + ẏ dt
    y = next(_random_states(1, seed=3))
    n = 6
    dy = np.concatenate([y[n:], tethersim.accelerations(sat, y, model="3d-exact-gravity")])
    h = 1e-2
    bp = tethersim.bodies(sat, y + h * dy, h, model="3d-exact-gravity")
    bm = tethersim.bodies(sat, y - h * dy, -h, model="3d-exact-gravity")
    b = tethersim.bodies(sat, y, 0.0, model="3d-exact-gravity")
    fd = (bp.position - bm.position) / (2 * h)
    np.testing.assert_allclose(fd, b.velocity, rtol=0, atol=1e-5)


def test_planar_model_is_the_3d_model_in_the_orbit_plane(sat):
    y2 = np.array([28.0, 1.5, 0.3, 1e-3, -2e-3, 4e-4])
    y3 = np.array([28.0, 1.5, 0.0, 0.0, 0.3, 0.0, 1e-3, -2e-3, 0.0, 0.0, 4e-4, 0.0])
    b2 = tethersim.bodies(sat, y2, 50.0, model="exact-gravity")
    b3 = tethersim.bodies(sat, y3, 50.0, model="3d-exact-gravity")
    np.testing.assert_allclose(b2.position, b3.position, rtol=1e-15, atol=0)
    np.testing.assert_allclose(b2.velocity, b3.velocity, rtol=1e-13, atol=1e-12)
    assert np.all(b2.position[:, 2] == 0.0)


def test_planar_pitch_satisfies_euler_about_the_orbit_normal():
    # planar exact-gravity model: point masses, Euler's z component with I = m1 b² + m2 a²
    sat = tethersim.load_preset("satI").replace(c1=0.02, c2=0.03)
    y = np.array([27.0, -2.0, 0.4, 1e-2, -3e-2, 2e-3])
    b = tethersim.bodies(sat, y, 40.0, model="exact-gravity")
    acc = tethersim.body_accelerations(sat, y, 40.0, model="exact-gravity")
    zeros = [np.zeros(3), np.zeros(3)]
    a3, torque = newton_euler(sat, b, zeros)
    assert np.linalg.norm(acc.acceleration[2] - a3) <= RTOL * np.linalg.norm(a3)
    Iz = sat.pitch_inertia
    assert abs(Iz * acc.angular_acceleration[2] - torque[2]) <= RTOL * abs(torque[2])


def test_circular_orbit_com_phase_matches_the_runtime_orbit(sat):
    t = 1234.5
    b = tethersim.bodies(sat, np.zeros(6), t)
    w = sat.omega
    np.testing.assert_allclose(b.com_position, sat.r0 * np.array([np.cos(w * t),
                                                                  np.sin(w * t), 0.0]),
                               rtol=1e-15, atol=1e-8)


def test_result_bodies_along_a_run_match_pointwise_bodies(sat):
    res = tethersim.simulate(sat, periods=0.02, model="3d")
    along = res.bodies()
    k = len(res.t) // 2
    one = tethersim.bodies(sat, res.model_states[k], res.t[k], model="3d")
    np.testing.assert_allclose(along.position[k], one.position, rtol=1e-15)
    np.testing.assert_allclose(along.angular_velocity[k], one.angular_velocity, rtol=1e-14)


def test_free_orbit_model_obeys_newton_euler_for_all_three_motions(sat):
    # the free-orbit model has no prescribed path: the boom COM too must obey Σ F = m a
    m = tethersim.model.registry.get_model("free-exact-gravity")
    q = dict(delta_x=27.0, delta_y=-2.0, theta=0.4, r=sat.r0 + 300.0, nu=0.3,
             delta_x_dot=1e-2, delta_y_dot=-3e-2, theta_dot=2e-3, r_dot=2.0,
             nu_dot=sat.omega * 1.001)
    y = np.array([q[k] for k in m.state])
    b = tethersim.bodies(sat, y, 0.0, model="free-exact-gravity")
    acc = tethersim.body_accelerations(sat, y, 0.0, model="free-exact-gravity")
    a3, torque = newton_euler(sat, b, [np.zeros(3), np.zeros(3)])
    assert np.linalg.norm(acc.acceleration[2] - a3) <= RTOL * np.linalg.norm(a3)
    assert abs(sat.pitch_inertia * acc.angular_acceleration[2] - torque[2]) <= RTOL * abs(
        torque[2])
    G, (o1, o2, o3), (v1, v2, v3) = b.com_position, b.offset, b.velocity
    r1, r2 = b.position[0], b.position[1]
    T1 = _tether(sat.E1, sat.l10, sat.c1, o3, v3, o1, v1)
    T2 = _tether(sat.E2, sat.l20, sat.c2, o3, v3, o2, v2)
    F = (_gravity(sat.m1, G, o1)[0] + _gravity(sat.m2, G, o2)[0] + _drag(sat, sat.A1, r1, v1)
         + _drag(sat, sat.A2, r2, v2) - T1 - T2)
    a_com = F / (sat.m1 + sat.m2)
    kepler = -MU_EARTH * G / np.linalg.norm(G) ** 3
    # to 1e-9 of the non-Keplerian part (drag, tethers, the boom's own tide)
    assert np.linalg.norm(acc.com_acceleration - a_com) <= RTOL * np.linalg.norm(a_com - kepler)


@pytest.mark.parametrize("k, y", list(enumerate(_random_states(4, seed=5))))
def test_thesis_truncated_gravity_is_newton_euler_to_order_boom_over_radius(sat, k, y):
    # model "3d" truncates gravity at the thesis's order (Eqs 3.28-3.30): the exact
    # Newton-Euler forces hold to O((a + b)/r0) of the torques and tidal forces
    order = (sat.a + sat.b) / sat.r0
    b = tethersim.bodies(sat, y, 100.0 * k, model="3d")
    acc = tethersim.body_accelerations(sat, y, 100.0 * k, model="3d")
    inert = _body_inertias(sat)
    a3, torque = newton_euler(sat, b, inert)
    kepler = -MU_EARTH * b.com_position / np.linalg.norm(b.com_position) ** 3
    assert np.linalg.norm(acc.acceleration[2] - a3) <= order * np.linalg.norm(a3 - kepler)
    I = _boom_inertia(sat, inert, b.attitude)
    w = b.angular_velocity
    lhs = I @ acc.angular_acceleration + np.cross(w, I @ w)
    assert np.linalg.norm(lhs - torque) <= order * np.linalg.norm(torque)
