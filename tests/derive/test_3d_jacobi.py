"""Jacobi integral of the 3-D kernels along integrated runs (check (e)).

Runs are integrated here with scipy's DOP853 on the generated rhs (no runtime
engine involved).  Without drag and dampers, h = Σ q̇ ∂L/∂q̇ − L plus the
taut-tether spring energy is a first integral of the rotating-frame system
(the potential is autonomous in L); with them, dh/dt is the power of drag and
dampers, Σ_f Q_f·q̇, so h(t) − h(0) equals their work.  The runs start out of
the plane (roll, yaw, δz) and cross taut/slack switches.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import tethersim.generated as generated
from derive.three_d.symbols3d import eq44_box_inertia
from tethersim.generated import three_d as layout3d  # every 3-D model has this layout

R0 = 6.578e6
MU = 3.986004418e14
N = math.sqrt(MU / R0**3)
PERIOD = 2 * math.pi / N
I_DRAG_DAMP = [layout3d.FAMILIES.index(n) for n in ("drag1", "drag2", "drag3", "damper1", "damper2")]

CIRCULAR_3D = [n for n, m in generated.MODELS.items()
               if m.GEOMETRY == "3d" and m.ORBIT == "circular"]


def sat_params(boxes=True, drag=True, dampers=True):
    """SatI-like values (tethersim/model/presets/satI.toml) with Eq 4.4 boxes or point masses."""
    v = dict(m1=10.0, m2=105.0, m3=1.0, A1=0.1, A2=1.05, A3=12.0, a=1.0, b=10.5, l10=6.0,
             l20=6.0, E1=0.004, E2=0.0427, c1=3e-4 if dampers else 0.0,
             c2=3e-4 if dampers else 0.0, CD=2.0 if drag else 0.0, r0=R0, mu=MU, omega=N,
             omega_earth=7.292115e-5, rho1=2.8e-10, rho2=2.8e-10, rho3=2.8e-10)
    for body, (m, area) in ((1, (v["m1"], v["A1"])), (2, (v["m2"], v["A2"]))):
        box = eq44_box_inertia(m, area) if boxes else (0.0, 0.0, 0.0)
        v.update({f"I{body}_{ax}": x for ax, x in zip(("roll", "pitch", "yaw"), box)})
    return np.array([v[n] for n in layout3d.PARAMETERS])


# balloon released 8 m behind and 3 m out of plane; boom rolled, pitched, yawed
Y0 = np.array([8.0, 1.0, 3.0, 0.15, 0.4, 0.3, 0.0, 0.0, 0.0, 2e-4, 0.0, 5e-4])


def lengths(y, p):
    dx, dy, dz, phi, th = y[:5]
    e = np.array([math.cos(phi) * math.sin(th), math.cos(phi) * math.cos(th), math.sin(phi)])
    d = np.array([dx, dy, dz])
    i = layout3d.PARAMETERS.index
    return np.linalg.norm(p[i("b")] * e - d), np.linalg.norm(-p[i("a")] * e - d)


def run(module, p, periods, with_work=False):
    """Dense samples of y (and of the drag + damper work W) from DOP853."""
    out = np.zeros((7, 6))

    def f(t, z):
        d = np.empty(12)
        module.rhs(t, z[:12], p, d)
        if not with_work:
            return d
        module.family_forces(z[:12], p, out)
        power = float(np.sum(out[I_DRAG_DAMP] @ z[6:12]))
        return np.append(d, power)

    def gate(j):
        rest = p[layout3d.PARAMETERS.index(("l10", "l20")[j])]
        event = lambda t, z: lengths(z[:12], p)[j] - rest  # noqa: E731
        event.terminal = True
        return event

    def solve(t0, t1, z, events=None, last=False):
        """Samples in [t0, t1) (and t1 itself if ``last``), and the solution object."""
        keep = t_out[(t_out >= t0) & ((t_out <= t1) if last else (t_out < t1))]
        sol = solve_ivp(f, (t0, t1), z, method="DOP853", rtol=1e-13, atol=1e-14,
                        t_eval=keep if last or events else np.append(keep, t1), events=events)
        assert sol.status >= 0
        return sol

    # A taut/slack switch (λ_j = l_j0) is a kink in the tension: no step may cross
    # it.  Locate it (events), redo the segment so that it ends exactly there, and
    # leave it by a 0.1 s run without events (a tether period is ~70 s).
    t_out = np.linspace(0.0, periods * PERIOD, 801)
    t0, z, samples = 0.0, (np.append(Y0, 0.0) if with_work else Y0), []
    while True:
        sol = solve(t0, t_out[-1], z, events=[gate(0), gate(1)], last=True)
        if sol.status == 0:
            samples.append(np.asarray(sol.y).T)
            return np.vstack(samples)
        t_switch = min(e[0] for e in sol.t_events if e.size)
        for t1 in (t_switch, t_switch + 0.1):
            sol = solve(t0, t1, z)
            samples.append(np.asarray(sol.y)[:, :-1].T)
            t0, z = t1, sol.y[:, -1]


def spring_energy(module, y, p):
    """Tether energy along a run: h with springs minus h with E1 = E2 = 0."""
    q = p.copy()
    q[[layout3d.PARAMETERS.index("E1"), layout3d.PARAMETERS.index("E2")]] = 0.0
    return np.array([module.jacobi(s, p) - module.jacobi(s, q) for s in y])


@pytest.mark.slow
@pytest.mark.parametrize("name", CIRCULAR_3D)
@pytest.mark.parametrize("boxes", [True, False], ids=["eq44-boxes", "point-masses"])
def test_jacobi_integral_is_conserved_without_drag_and_dampers(name, boxes):
    module, p = generated.MODELS[name], sat_params(boxes, drag=False, dampers=False)
    y = run(module, p, periods=0.5)
    h = np.array([module.jacobi(s, p) for s in y])
    taut = np.array([lengths(s, p)[1] > p[layout3d.PARAMETERS.index("l20")] for s in y])
    assert taut.any() and not taut.all()  # the run crosses slack/taut switches
    assert np.ptp(y[:, 3]) > 0.05 and np.ptp(y[:, 2]) > 1.0  # really out of plane
    scale = np.ptp(spring_energy(module, y, p))  # energy swapped into the tethers
    assert scale > 0
    assert np.max(np.abs(h - h[0])) <= 1e-9 * scale, np.max(np.abs(h - h[0])) / scale


@pytest.mark.slow
@pytest.mark.parametrize("name", CIRCULAR_3D)
def test_jacobi_change_equals_work_of_drag_and_dampers(name):
    module, p = generated.MODELS[name], sat_params()
    z = run(module, p, periods=0.2, with_work=True)
    h = np.array([module.jacobi(s[:12], p) for s in z])
    work = z[:, 12]
    # In L, drag is mostly a steady wind along +x: released 8 m behind, the
    # balloon is blown downstream and the work is positive; it is not small.
    assert abs(work[-1]) > 1e-3 * np.ptp(spring_energy(module, z[:, :12], p))
    assert np.max(np.abs((h - h[0]) - work)) <= 1e-8 * abs(work[-1])
