"""3-D models reduce to the planar models at zero out-of-plane state (check (a)).

With δz = φ = ψ = 0 and their rates zero, and the box inertias off (the planar
model has point masses only: I1 = I2 = 0), the in-plane components of the 3-D
rhs, family forces and Jacobian equal the planar ones of the same variant, and
every out-of-plane acceleration and its dependence on the in-plane state vanish
(so a planar state stays planar).  Symbolically, M and f reduce to the planar
Lagrange terms.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import tethersim.generated as generated
from derive.reference import derived as derived_3d
from derive.three_d import symbols3d as s3
from tethersim.engine.jacobian import jacobian
from tethersim.generated import layout
from tethersim.generated import three_d as layout3d  # every 3-D model has this layout
from tethersim.model.registry import BY_NAME

PAIRS = (("derived", "3d"), ("exact-gravity", "3d-exact-gravity"),
         ("objective-damper", "3d-objective-damper"))
SEED = 20051313
N_POINTS = 24
R0 = 6.578e6
MU = 3.986004418e14
IN_PLANE = tuple(layout3d.STATE.index(n) for n in layout.STATE)  # δx, δy, θ and rates
OUT_OF_PLANE = tuple(i for i in range(12) if i not in IN_PLANE)
Q_IN = (0, 1, 4)  # q index of δx, δy, θ in the 3-D coordinates
REL_TOL = 1e-12  # relative, per component (two cse trees of the same expressions)
FLOOR = 1e-15


def _lengths(y, p):
    v = dict(zip(layout.PARAMETERS, p))
    dx, dy, th = y[:3]
    return (math.hypot(v["b"] * math.sin(th) - dx, v["b"] * math.cos(th) - dy),
            math.hypot(-v["a"] * math.sin(th) - dx, -v["a"] * math.cos(th) - dy))


def _draw(rng, taut):
    """Random planar (y, p) as tests/derive/test_generated.py, tether j taut or slack by ≥ 5 %."""
    u = rng.uniform
    par = dict(m1=u(5, 20), m2=u(50, 200), m3=u(0.5, 2), A1=u(0.1, 1), A2=u(0.1, 1),
               A3=u(5, 20), a=u(0.5, 2), b=u(5, 20), l10=0.0, l20=0.0, E1=u(1e-3, 0.1),
               E2=u(1e-3, 0.1), c1=u(1e-3, 0.1), c2=u(1e-3, 0.1), CD=2.0, r0=R0, mu=MU,
               omega=math.sqrt(MU / R0**3), omega_earth=7.292115e-5,
               rho1=u(2.5e-10, 3.1e-10), rho2=u(2.5e-10, 3.1e-10), rho3=u(2.5e-10, 3.1e-10))
    y = np.array([u(-40, 40), u(-10, 10), u(-np.pi, np.pi), u(-0.5, 0.5), u(-0.5, 0.5),
                  u(-0.01, 0.01)])
    p = np.array([par[n] for n in layout.PARAMETERS])
    for j, name in enumerate(("l10", "l20")):
        lam = _lengths(y, p)[j]
        p[layout.PARAMETERS.index(name)] = lam / u(1.05, 1.5) if taut[j] else lam * u(1.05, 1.5)
    return y, p


def to_3d(y2, p2):
    """The 3-D (y, p) of a planar one: out-of-plane state 0, inertias 0 (point masses)."""
    y3 = np.zeros(12)
    y3[list(IN_PLANE)] = y2
    p3 = np.zeros(len(layout3d.PARAMETERS))
    p3[: len(p2)] = p2
    assert layout3d.PARAMETERS[: len(p2)] == layout.PARAMETERS
    return y3, p3


@pytest.fixture(scope="module")
def sample():
    rng = np.random.default_rng(SEED)
    cases = ((True, True), (True, False), (False, True), (False, False))
    return [_draw(rng, cases[n % 4]) for n in range(N_POINTS)]


def _close(got, want):
    scale = np.maximum(np.abs(want), FLOOR)
    return float(np.max(np.abs(got - want) / scale))


@pytest.mark.parametrize("planar, three_d", PAIRS)
def test_rhs_in_plane_equals_planar_and_out_of_plane_is_zero(sample, planar, three_d):
    worst = 0.0
    for y2, p2 in sample:
        y3, p3 = to_3d(y2, p2)
        d2, d3 = np.full(6, np.nan), np.full(12, np.nan)
        generated.MODELS[planar].rhs(0.0, y2, p2, d2)
        generated.MODELS[three_d].rhs(0.0, y3, p3, d3)
        worst = max(worst, _close(d3[list(IN_PLANE)], d2))
        assert np.all(d3[list(OUT_OF_PLANE)] == 0.0)
    assert worst <= REL_TOL, worst


@pytest.mark.parametrize("planar, three_d", PAIRS)
def test_family_forces_in_plane_equal_planar_and_out_of_plane_are_zero(sample, planar, three_d):
    worst = 0.0
    for y2, p2 in sample:
        y3, p3 = to_3d(y2, p2)
        o2, o3 = np.full((7, 3), np.nan), np.full((7, 6), np.nan)
        generated.MODELS[planar].family_forces(y2, p2, o2)
        generated.MODELS[three_d].family_forces(y3, p3, o3)
        worst = max(worst, _close(o3[:, list(Q_IN)], o2))
        assert np.all(o3[:, [2, 3, 5]] == 0.0)
    assert worst <= REL_TOL, worst


# each 3-D model's finite-difference Jacobian compiles for 15-20 s cold: the slow tier
# (tests/tiers.py); the fast tier checks the 3-D rhs and forces in the plane above
@pytest.mark.slow
@pytest.mark.parametrize("planar, three_d", PAIRS)
def test_jacobian_in_plane_block_equals_planar_and_planar_states_stay_planar(sample, planar, three_d):
    """∂(out-of-plane rates and accelerations)/∂(in-plane state) = 0: the plane is invariant."""
    worst = 0.0
    for y2, p2 in sample:
        y3, p3 = to_3d(y2, p2)
        J2, J3 = np.full((6, 6), np.nan), np.full((12, 12), np.nan)
        jacobian(BY_NAME[planar].index, 0.0, y2, p2, J2)
        jacobian(BY_NAME[three_d].index, 0.0, y3, p3, J3)
        block = J3[np.ix_(IN_PLANE, IN_PLANE)]
        # per row: the 3-D Jacobian is central differences (tethersim/engine/jacobian.py),
        # whose rate columns carry the rounding of the ~7.3 km/s air speed inside the drag
        scale = np.max(np.abs(J2), axis=1, keepdims=True)
        worst = max(worst, float(np.max(np.abs(block - J2) / scale)))
        assert np.all(J3[np.ix_(OUT_OF_PLANE, IN_PLANE)] == 0.0)
    assert worst <= 1e-8, worst


@pytest.mark.slow
@pytest.mark.parametrize("planar, three_d", PAIRS[:2])
def test_mass_matrix_and_f_reduce_symbolically(derived_model, planar, three_d):
    """3-D M and f at zero out-of-plane state and zero inertias = planar M and f."""
    m2, m3 = derived_model(planar), derived_3d(three_d)
    zero = {s3.STATE_SYMBOLS[i]: 0 for i in OUT_OF_PLANE}
    zero.update({p.symbol: 0 for p in s3.INERTIAS})
    for a, k in enumerate(Q_IN):
        assert sp.expand(m3.f[k].xreplace(zero) - m2.f[a]) == 0
        for b, m in enumerate(Q_IN):
            assert sp.simplify(m3.mass_matrix[k, m].xreplace(zero) - m2.mass_matrix[a, b]) == 0


def rk4(module, y, p, dt, steps):
    """Fixed-step classical RK4 with the generated rhs (same steps for every model)."""
    out, k = [y.copy()], [np.empty_like(y) for _ in range(4)]
    for _ in range(steps):
        module.rhs(0.0, y, p, k[0])
        module.rhs(0.0, y + 0.5 * dt * k[0], p, k[1])
        module.rhs(0.0, y + 0.5 * dt * k[1], p, k[2])
        module.rhs(0.0, y + dt * k[2], p, k[3])
        y = y + dt / 6 * (k[0] + 2 * k[1] + 2 * k[2] + k[3])
        out.append(y.copy())
    return np.array(out)


@pytest.mark.parametrize("planar, three_d", PAIRS)
def test_planar_run_equals_3d_run_and_stays_planar(planar, three_d):
    """SatI-like values, balloon released 3 m behind (tether 2 switches), θ0 = 0.4:
    0.1 orbit of fixed-step RK4 (0.5 s) with each model; the 3-D run's out-of-plane
    state stays exactly zero and its in-plane state equals the planar run's."""
    v = dict(m1=10.0, m2=105.0, m3=1.0, A1=0.1, A2=1.05, A3=12.0, a=1.0, b=10.5, l10=6.0,
             l20=6.0, E1=0.004, E2=0.0427, c1=3e-4, c2=3e-4, CD=2.0, r0=R0, mu=MU,
             omega=math.sqrt(MU / R0**3), omega_earth=7.292115e-5, rho1=2.8e-10,
             rho2=2.8e-10, rho3=2.8e-10)
    p2 = np.array([v[n] for n in layout.PARAMETERS])
    y2 = np.array([3.0, 1.0, 0.4, 0.0, 0.0, 0.0])
    y3, p3 = to_3d(y2, p2)
    steps = int(0.1 * 2 * math.pi / v["omega"] / 0.5)
    r2 = rk4(generated.MODELS[planar], y2, p2, 0.5, steps)
    r3 = rk4(generated.MODELS[three_d], y3, p3, 0.5, steps)
    lam2 = np.array([_lengths(s, p2)[1] for s in r2])
    assert (lam2 > v["l20"]).any() and (lam2 <= v["l20"]).any()  # tether 2 switches
    assert np.all(r3[:, list(OUT_OF_PLANE)] == 0.0)
    scale = np.max(np.abs(r2), axis=0)
    assert np.max(np.abs(r3[:, list(IN_PLANE)] - r2) / scale) <= 1e-9
