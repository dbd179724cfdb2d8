"""Linear attitude modes of the 3-D kernels against closed forms (checks (b), (c)).

Jacobian of the generated kernels at the nominal attitude (y = 0), drag and
tethers off (central differences of rhs, tethersim/engine/jacobian.py).  References (docs/sources.md):

* rigid dumbbell (point masses on a rod): in-plane libration √3·n, out-of-plane
  2·n (Cosmo & Lorenzini, Tethers in Space Handbook, 1997);
* rigid body (also through the public Satellite fields I1, I2 and
  ``inertia = "points"``), principal inertias on roll (x, along-track), pitch (z, orbit
  normal), yaw (y, radial): pitch ω² = 3n²(I_roll − I_yaw)/I_pitch and the
  roll–yaw quartic s⁴ + s²n²(1 + 3k1 + k1k3) + 4n⁴k1k3 = 0 with
  k1 = (I_pitch − I_yaw)/I_roll, k3 = (I_pitch − I_roll)/I_yaw (Hughes,
  Spacecraft Attitude Dynamics, ch. 9), with growth rates outside the Lagrange
  region I_pitch > I_roll > I_yaw.

The end bodies are equal and equidistant (m1 = m2, a = b, I1 = I2): the
O(b/r0) gravity corrections then cancel, and what is left is O((b/r0)²) ≈ 1e-11.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim.generated as generated
from tethersim.engine.jacobian import jacobian
from tethersim.generated import three_d as layout3d  # every 3-D model has this layout
from tethersim.model.registry import BY_NAME

# compiles the 3-D kernels and their difference loops: the slow tier (make test-slow, CI)
pytestmark = pytest.mark.slow

MODELS = tuple(n for n, m in generated.MODELS.items()
               if m.GEOMETRY == "3d" and m.ORBIT == "circular")
R0 = 6.578e6
MU = 3.986004418e14
N = math.sqrt(MU / R0**3)
IX = {n: layout3d.STATE.index(n) for n in layout3d.STATE}
PHI, THETA, PSI = IX["phi"], IX["theta"], IX["psi"]
RATE = {k: k + 6 for k in (PHI, THETA, PSI)}
TOL = 1e-9  # on eigenvalues, relative to n


def params(m=50.0, half_length=5.0, box=(0.0, 0.0, 0.0)):
    """Symmetric boom (m1 = m2 = m, a = b), equal boxes (roll, pitch, yaw), no drag or tethers."""
    v = dict.fromkeys(layout3d.PARAMETERS, 0.0)
    v.update(m1=m, m2=m, m3=1.0, A1=1.0, A2=1.0, A3=10.0, a=half_length, b=half_length,
             l10=30.0, l20=30.0, CD=2.0, r0=R0, mu=MU, omega=N, omega_earth=7.292115e-5)
    for body in (1, 2):
        for axis, value in zip(("roll", "pitch", "yaw"), box):
            v[f"I{body}_{axis}"] = value
    return np.array([v[n] for n in layout3d.PARAMETERS])


def jacobian_at_rest(model, p):
    J = np.full((12, 12), np.nan)
    jacobian(BY_NAME[model].index, 0.0, np.zeros(12), p, J)
    return J


def eigs(J, coords):
    idx = list(coords) + [c + 6 for c in coords]  # coordinates, then their rates
    return np.linalg.eigvals(J[np.ix_(idx, idx)])


def assert_same_roots(got, want, n=N):
    got, want = np.asarray(got, complex), np.asarray(want, complex)
    for w in want:  # nearest-match, each closed-form root found once
        k = int(np.argmin(np.abs(got - w)))
        assert abs(got[k] - w) <= TOL * n, (got, want)
        got = np.delete(got, k)


def assert_attitude_decoupled(J):
    """No coupling between attitude and balloon at rest without tethers."""
    att = [PHI, THETA, PSI] + [RATE[c] for c in (PHI, THETA, PSI)]
    bal = [i for i in range(12) if i not in att]
    assert np.all(J[np.ix_(att, bal)] == 0.0) and np.all(J[np.ix_(bal, att)] == 0.0)


@pytest.mark.parametrize("model", MODELS)
def test_dumbbell_librates_at_root3_n_in_plane_and_2n_out_of_plane(model):
    J = jacobian_at_rest(model, params())
    assert_attitude_decoupled(J)
    assert_same_roots(eigs(J, [THETA]), [1j * math.sqrt(3) * N, -1j * math.sqrt(3) * N])
    assert_same_roots(eigs(J, [PHI]), [2j * N, -2j * N])
    # pitch and roll do not couple at rest; yaw is no degree of freedom (no axial inertia)
    assert J[RATE[THETA], PHI] == 0.0 and J[RATE[PHI], THETA] == 0.0
    assert np.all(J[RATE[PSI]] == 0.0)


def totals(m, half_length, box):
    """(I_roll, I_pitch, I_yaw) of the whole boom about the COM [kg m²]."""
    points = 2 * m * half_length**2
    return points + 2 * box[0], points + 2 * box[1], 2 * box[2]


def closed_form(Ir, Ip, Iy, n=N):
    """Pitch eigenvalues ±√(−ω²) and the roll–yaw quartic's roots (Hughes)."""
    w2 = 3 * n**2 * (Ir - Iy) / Ip
    pitch = [np.sqrt(complex(-w2)), -np.sqrt(complex(-w2))]
    k1, k3 = (Ip - Iy) / Ir, (Ip - Ir) / Iy
    quartic = np.roots([1.0, 0.0, n**2 * (1 + 3 * k1 + k1 * k3), 0.0, 4 * n**4 * k1 * k3])
    return pitch, quartic


# (box roll, pitch, yaw) per end body, for m = 50 kg, a = b = 5 m (points: 2500 kg m²)
CASES = {
    "Lagrange region": (400.0, 1200.0, 300.0),  # I_p 4900 > I_r 3300 > I_y 600
    "roll-yaw unstable (I_roll > I_pitch)": (1200.0, 400.0, 300.0),
    "pitch unstable (I_yaw > I_roll)": (100.0, 1200.0, 2000.0),
    "k1, k3 < 0 outside the DeBra-Delp region": (3000.0, 0.0, 2000.0),
}


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("case", list(CASES))
def test_rigid_body_pitch_and_roll_yaw_quartic(model, case):
    box = CASES[case]
    Ir, Ip, Iy = totals(50.0, 5.0, box)
    J = jacobian_at_rest(model, params(box=box))
    assert_attitude_decoupled(J)
    pitch, quartic = closed_form(Ir, Ip, Iy)
    got_pitch, got_ry = eigs(J, [THETA]), eigs(J, [PHI, PSI])
    assert_same_roots(got_pitch, pitch)
    assert_same_roots(got_ry, quartic)
    lagrange = Ip > Ir > Iy
    growth = max(np.max(got_pitch.real), np.max(got_ry.real))
    if lagrange:
        assert growth <= TOL * N  # all neutral
    else:
        assert growth > 0.05 * N  # a genuine growth rate, not rounding


# The same through the public Satellite fields I1, I2 (tethersim.model.inertia): each end
# body's moments a rigid body's (the triangle inequality, which the kernel-level boxes
# above need not obey), the totals in the same four regions.
PHYSICAL_CASES = {
    "Lagrange region": (300.0, 500.0, 400.0),  # I_p 3500 > I_r 3100 > I_y 800
    "roll-yaw unstable (I_roll > I_pitch)": (500.0, 300.0, 400.0),
    "pitch unstable (I_yaw > I_roll)": (100.0, 1500.0, 1500.0),
    "k1, k3 < 0 outside the DeBra-Delp region": (1500.0, 0.0, 1500.0),  # a thin plate
}


def rigid_satellite(**inertia):
    """m1 = m2 = 50 kg at a = b = 5 m, tethers and drag off, the moments as given."""
    from tethersim import Satellite

    return Satellite(name="rigid", m1=50.0, m2=50.0, m3=1.0, A1=1.0, A2=1.0, A3=10.0, a=5.0,
                     b=5.0, l10=30.0, l20=30.0, E1=0.0, E2=0.0, c1=0.0, c2=0.0,
                     altitude=200e3, initial=(30.0, 0.0, 0.0, 0.0, 0.0, 0.0), CD=0.0, **inertia)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("case", list(PHYSICAL_CASES))
def test_satellite_moments_give_the_rigid_body_pitch_and_roll_yaw_quartic(model, case):
    from tethersim.model.inputs import parameter_vector

    box = PHYSICAL_CASES[case]
    sat = rigid_satellite(I1=box, I2=list(box))
    n = sat.omega
    J = np.full((12, 12), np.nan)
    jacobian(BY_NAME[model].index, 0.0, np.zeros(12), parameter_vector(sat, model), J)
    assert_attitude_decoupled(J)
    pitch, quartic = closed_form(*totals(50.0, 5.0, box), n=n)
    got_pitch, got_ry = eigs(J, [THETA]), eigs(J, [PHI, PSI])
    assert_same_roots(got_pitch, pitch, n)
    assert_same_roots(got_ry, quartic, n)
    growth = max(np.max(got_pitch.real), np.max(got_ry.real))
    Ir, Ip, Iy = totals(50.0, 5.0, box)
    if Ip > Ir > Iy:
        assert growth <= TOL * n  # all neutral
    else:
        assert growth > 0.05 * n  # a genuine growth rate, not rounding


@pytest.mark.parametrize("model", MODELS)
def test_satellite_point_masses_give_the_dumbbell_librations(model):
    from tethersim.model.inputs import parameter_vector

    sat = rigid_satellite(inertia="points")
    n = sat.omega
    J = np.full((12, 12), np.nan)
    jacobian(BY_NAME[model].index, 0.0, np.zeros(12), parameter_vector(sat, model), J)
    assert_same_roots(eigs(J, [THETA]), [1j * math.sqrt(3) * n, -1j * math.sqrt(3) * n], n)
    assert_same_roots(eigs(J, [PHI]), [2j * n, -2j * n], n)
    assert np.all(J[RATE[PSI]] == 0.0)  # no axial moment: yaw is no degree of freedom


@pytest.mark.parametrize("model", MODELS)
def test_free_balloon_has_clohessy_wiltshire_modes(model):
    """Without tethers or drag the balloon moves by Hill's (Clohessy–Wiltshire)
    equations about G: in-plane eigenvalues 0, 0, ±i n, out-of-plane ±i n
    (ẍ − 2nẏ = 0, ÿ + 2nẋ − 3n²y = 0, z̈ + n²z = 0 in these axes)."""
    J = jacobian_at_rest(model, params())
    assert_same_roots(eigs(J, [IX["delta_x"], IX["delta_y"]]), [0, 0, 1j * N, -1j * N])
    assert_same_roots(eigs(J, [IX["delta_z"]]), [1j * N, -1j * N])
    z, zdd = IX["delta_z"], IX["delta_z"] + 6
    assert J[zdd, z] == pytest.approx(-N**2, rel=1e-12)
