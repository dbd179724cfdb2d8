"""Generated 3-D free-orbit kernels (generated/three_d_free*.py): planar runs, energy, decay.

* (b) From a state with zero out-of-plane offsets, angles and rates, and point
  masses, a fixed-step RK4 run of ``3d-free`` equals the planar ``free`` run of
  the same variant (tethers switching, J2 and drag on) and stays exactly planar.
* (c) E = T + V + taut-spring energy (the generated ``jacobi``) is conserved
  without drag and dampers along an out-of-plane run with J2 on, and loses
  exactly the drag and damper work otherwise (tests/derive/test_orbit_physics.py's
  checks of the planar free models, on 16 states); the orbit decays at the
  closed-form rate of tests/derive/test_orbit_physics.py (Vallado ch. 8).
* The engine's Jacobian (central differences of ``rhs`` at its own steps,
  tethersim/engine/jacobian.py) equals central differences at hand-picked steps,
  and has a zero ψ̈ row for point masses.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from tests.derive.test_3d_planar import rk4  # the fixed-step RK4 of the 3-D planar check
from tethersim.engine.jacobian import jacobian
from tethersim.generated import (
    free,
    free_objective_damper,
    three_d_free,
    three_d_free_objective_damper,
)
from tethersim.model.constants import J2_EARTH, MU_EARTH
from tethersim.model.registry import BY_NAME as REGISTRY
from tools.docnumbers.figures_orbit import R200 as R0
from tools.docnumbers.figures_orbit import decay
from tools.docnumbers.free_orbit import integrate, params, state, work

pytestmark = pytest.mark.slow  # compiles the 16-state kernels (about a minute each)

PAIRS = ((free, three_d_free), (free_objective_damper, three_d_free_objective_damper))
N3 = 16


@pytest.mark.parametrize("planar, three_d", PAIRS, ids=lambda m: m.MODEL)
def test_planar_start_runs_as_the_planar_free_model_and_stays_planar(planar, three_d):
    """SatI values, J2 and air on, balloon released 3 m behind (tether 2 switches),
    θ0 = 0.4, a slightly eccentric start: 0.1 orbit of RK4 at 0.5 s per model."""
    rho = dict(rho1=2.8e-10, rho2=2.8e-10, rho3=2.8e-10, J2=J2_EARTH)
    points = {f"I{b}_{ax}": 0.0 for b in (1, 2) for ax in ("roll", "pitch", "yaw")}
    nu_dot = 1.001 * math.sqrt(MU_EARTH / R0**3)
    start = dict(delta_x=3.0, delta_y=1.0, theta=0.4, r=R0, nu=-math.pi / 2, nu_dot=nu_dot)
    p2, p3 = params(planar, **rho), params(three_d, **rho, **points)
    steps = int(0.1 * 2 * math.pi / nu_dot / 0.5)
    r2 = rk4(planar, state(planar, **start), p2, 0.5, steps)
    r3 = rk4(three_d, state(three_d, **start), p3, 0.5, steps)
    g = np.zeros(2)
    lam2 = []
    for s in r2:
        planar.tether_margins(s, p2, g)
        lam2.append(g[1])
    assert min(lam2) < 0 < max(lam2)  # tether 2 switches
    in_plane = [three_d.STATE.index(n) for n in planar.STATE]
    out_of_plane = [i for i in range(N3) if i not in in_plane]
    assert np.all(r3[:, out_of_plane] == 0.0)
    scale = np.max(np.abs(r2), axis=0)
    assert np.max(np.abs(r3[:, in_plane] - r2) / scale) <= 1e-9


def out_of_plane_start(module, r_dot=0.0, nu_factor=1.0):
    """Balloon 25 m behind, 3 m up, 4 m out of plane; roll 0.1, yaw 0.2, moving."""
    return state(module, delta_x=25.0, delta_y=3.0, delta_z=4.0, phi=0.1, theta=math.pi / 6,
                 psi=0.2, r=R0, nu=-math.pi / 2, delta_x_dot=2.0, delta_y_dot=-1.0,
                 delta_z_dot=0.5, phi_dot=2e-3, psi_dot=-1e-3, r_dot=r_dot,
                 nu_dot=nu_factor * math.sqrt(MU_EARTH / R0**3))


@pytest.mark.parametrize("module", (three_d_free, three_d_free_objective_damper), ids=lambda m: m.MODEL)
def test_energy_is_conserved_out_of_the_plane_without_drag_and_dampers(module):
    """Springs, boxes and J2 (with each body's latitude) on: E drifts < 1e-3 J of 3.5e9 J."""
    p = params(module, c1=0.0, c2=0.0, J2=J2_EARTH)
    y0 = out_of_plane_start(module, r_dot=5.0, nu_factor=1.01)
    sol = integrate(module, p, y0, 2000.0, t_eval=np.linspace(0.0, 2000.0, 5))
    energy = np.array([module.jacobi(sol.y[:, i].copy(), p) for i in range(sol.y.shape[1])])
    assert abs(np.ptp(sol.y[module.STATE.index("delta_z")])) > 1.0  # it does leave the plane
    assert np.max(np.abs(energy - energy[0])) < 1e-3


@pytest.mark.parametrize("module", (three_d_free, three_d_free_objective_damper), ids=lambda m: m.MODEL)
def test_energy_lost_equals_drag_and_damper_work_out_of_the_plane(module):
    """dE/dt = Σ (Q_drag + Q_damper)·q̇ over all eight coordinates (L has no explicit t)."""
    rho = 2.8e-10
    p = params(module, rho1=rho, rho2=1.1 * rho, rho3=0.9 * rho, c1=0.3, c2=0.3, J2=J2_EARTH)
    t_eval = np.linspace(0.0, 2000.0, 5)
    sol = integrate(module, p, out_of_plane_start(module), 2000.0, extra=work(module, p),
                    t_eval=t_eval)
    energy = np.array([module.jacobi(sol.y[:N3, i].copy(), p) for i in range(len(t_eval))])
    w_drag, w_damp = sol.y[N3], sol.y[N3 + 1]
    assert np.all(w_drag[1:] < 0) and np.all(w_damp[1:] < 0) and abs(w_damp[-1]) > 1.0
    assert np.allclose(energy - energy[0], w_drag + w_damp, rtol=0, atol=1e-3)


def test_circular_orbit_decays_at_the_drag_rate_with_co_rotating_air():
    """da/dt = −ρ (Σ C_D A_i/m) √(μ a) (1 − ω_E/n)², 3000 s at 200 km, ρ = 2.8e-10 (≤ 1 %),
    with the balloon 2 m out of the plane; a of the COM by vis-viva from the inertial
    bodies (figures_orbit.decay, the planar check's run on 16 states)."""
    d = decay(three_d_free, delta_z=2.0)
    assert abs(d.run / d.law - 1) < 0.01, (d.run, d.law)


@pytest.mark.parametrize("axial", (True, False), ids=("boxes", "points"))
def test_jacobian_equals_central_differences_of_rhs(axial):
    """The engine's Jacobian (steps ε^(1/3) max(|y_c|, 1)) against hand-picked steps, rtol 1e-5;
    the floor 1e-11 covers the ψ column, pure rounding noise for the isotropic Eq 4.4 boxes:
    ~ε |f| / h, and the engine's ψ step (6e-6 rad) is 16 times smaller than the 1e-4 here."""
    module = three_d_free
    changes = {} if axial else {f"I{b}_{ax}": 0.0 for b in (1, 2) for ax in ("roll", "pitch", "yaw")}
    p = params(module, rho1=2.8e-10, rho2=2.8e-10, rho3=2.8e-10, c1=0.3, c2=0.3, J2=J2_EARTH,
               **changes)
    y = out_of_plane_start(module)
    J = np.zeros((N3, N3))
    jacobian(REGISTRY[module.MODEL].index, 0.0, y, p, J)
    if not axial:
        assert np.all(J[module.STATE.index("psi_dot")] == 0.0)  # ψ̈ = 0: no ψ degree of freedom
    steps = np.array([1e-3] * 3 + [1e-4] * 3 + [10.0, 1e-3] + [1e-4] * 3 + [1e-6] * 3 + [1e-2, 1e-8])
    for c in range(N3):
        hi, lo, dp, dm = y.copy(), y.copy(), np.zeros(N3), np.zeros(N3)
        hi[c] += steps[c]
        lo[c] -= steps[c]
        module.rhs(0.0, hi, p, dp)
        module.rhs(0.0, lo, p, dm)
        fd = (dp - dm) / (2 * steps[c])
        assert np.allclose(J[:, c], fd, rtol=1e-5, atol=1e-10 * np.abs(fd).max() + 1e-11), c
