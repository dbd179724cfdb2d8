"""The committed 3-D kernels against the symbolic derivation (check (d)).

Truth: derive.three_d.reference.Reference3D, the DerivedModel3D's M, f, family
forces and Jacobi integral evaluated with mpmath at 40 digits and solved there
(M q̈ = Σ Q − f), at the same float64 inputs.  The Jacobian is checked against
a 40-digit central difference of that truth (step 1e-12 relative: truncation
error ~1e-24).
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

import tethersim.generated as generated
from derive.models import THREE_D_DEFINITIONS as DEFINITIONS_3D
from derive.printer import module_filename
from derive.three_d import symbols3d as s3
from derive.three_d.forces3d import FAMILY_ORDER
from derive.three_d.reference import Reference3D, derived_3d
from tethersim.engine.jacobian import jacobian
from tethersim.generated import three_d as layout3d  # every 3-D model has this layout
from tethersim.model.registry import BY_NAME

MODELS = tuple(n for n, m in generated.MODELS.items()
               if m.GEOMETRY == "3d" and m.ORBIT == "circular")
SEED = 20051303
N_POINTS = 16
R0 = 6.578e6
MU = 3.986004418e14
REL_TOL = 1e-11  # per component, relative to max(|truth|, FLOOR)
FLOOR = 1e-15
# per entry, relative to the largest truth entry of its row: the central differences of
# tethersim/engine/jacobian.py (its docstring: rounding of the air speed in the rate columns)
JAC_TOL = 1e-8
PI = s3.PARAMETER_NAMES.index


def _lengths(y, p):
    """3-D tether lengths (float64): boom ends at ±(b, −a)(cos φ sin θ, cos φ cos θ, sin φ)."""
    dx, dy, dz, phi, th = y[:5]
    e = np.array([math.cos(phi) * math.sin(th), math.cos(phi) * math.cos(th), math.sin(phi)])
    d = np.array([dx, dy, dz])
    return (float(np.linalg.norm(p[PI("b")] * e - d)), float(np.linalg.norm(-p[PI("a")] * e - d)))


def draw(rng, taut, axial):
    """Random (y, p): realistic scales, φ away from ±π/2, tether j taut/slack by ≥ 5 %."""
    u = rng.uniform
    par = dict(m1=u(5, 20), m2=u(50, 200), m3=u(0.5, 2), A1=u(0.1, 1), A2=u(0.1, 1),
               A3=u(5, 20), a=u(0.5, 2), b=u(5, 20), l10=0.0, l20=0.0, E1=u(1e-3, 0.1),
               E2=u(1e-3, 0.1), c1=u(1e-3, 0.1), c2=u(1e-3, 0.1), CD=2.0, r0=R0, mu=MU,
               omega=math.sqrt(MU / R0**3), omega_earth=7.292115e-5,
               rho1=u(2.5e-10, 3.1e-10), rho2=u(2.5e-10, 3.1e-10), rho3=u(2.5e-10, 3.1e-10))
    for body in (1, 2):
        for axis in s3.INERTIA_AXES:
            par[f"I{body}_{axis}"] = u(0.5, 30) if axial else 0.0
    y = np.array([u(-40, 40), u(-10, 10), u(-10, 10), u(-1.2, 1.2), u(-np.pi, np.pi),
                  u(-np.pi, np.pi), u(-0.5, 0.5), u(-0.5, 0.5), u(-0.5, 0.5),
                  u(-0.01, 0.01), u(-0.01, 0.01), u(-0.01, 0.01)])
    p = np.array([par[n] for n in s3.PARAMETER_NAMES])
    for j, name in enumerate(("l10", "l20")):
        lam = _lengths(y, p)[j]
        p[PI(name)] = lam / u(1.05, 1.5) if taut[j] else lam * u(1.05, 1.5)
    return y, p


@pytest.fixture(scope="module")
def sample():
    rng = np.random.default_rng(SEED)
    cases = ((True, True), (True, False), (False, True), (False, False))
    # points with and without axial inertia (the 2x2 and 3x3 attitude solves)
    return [draw(rng, cases[n % 4], axial=(n // 4) % 2 == 0) for n in range(N_POINTS)]


@pytest.fixture(scope="module")
def reference():
    return {name: Reference3D(derived_3d(name)) for name in MODELS}


def rel_err(got, truth):
    with mpmath.workdps(40):
        return float(abs(mpmath.mpf(float(got)) - truth) / max(abs(truth), mpmath.mpf(FLOOR)))


def test_layout_tables_match_derive_symbols():
    assert layout3d.STATE == s3.STATE_NAMES and layout3d.PARAMETERS == s3.PARAMETER_NAMES
    assert layout3d.STATE_UNITS == s3.STATE_UNITS and layout3d.FAMILIES == FAMILY_ORDER
    assert tuple(d.name for d in DEFINITIONS_3D) == MODELS
    for name, module in ((n, generated.MODELS[n]) for n in MODELS):
        assert module.__name__.endswith(module_filename(name)[:-3])
        assert (module.STATE, module.PARAMETERS, module.FAMILIES) == (
            layout3d.STATE, layout3d.PARAMETERS, layout3d.FAMILIES)


def test_sample_gates_agree_and_cover_every_case(sample, reference):
    seen = set()
    for y, p in sample:
        lam = _lengths(y, p)
        taut = (lam[0] > p[PI("l10")], lam[1] > p[PI("l20")])
        assert reference["3d"].forces(y, p)[1] == taut
        seen.add(taut)
    assert len(seen) == 4


@pytest.mark.parametrize("name", MODELS)
def test_generated_rhs_equals_symbolic_at_40_digits(sample, reference, name):
    worst = 0.0
    for y, p in sample:
        d = np.full(12, np.nan)
        generated.MODELS[name].rhs(0.0, y, p, d)
        assert np.array_equal(d[:6], y[6:])
        truth = reference[name].qdd(y, p)
        worst = max(worst, *(rel_err(d[6 + k], truth[k]) for k in range(6)))
    assert worst <= REL_TOL, worst


@pytest.mark.parametrize("name", MODELS)
def test_generated_family_forces_equal_symbolic_at_40_digits(sample, reference, name):
    worst = 0.0
    for y, p in sample:
        out = np.full((7, 6), np.nan)
        generated.MODELS[name].family_forces(y, p, out)
        fam, taut = reference[name].forces(y, p)
        for f in range(7):
            worst = max(worst, *(rel_err(out[f, k], fam[f][k]) for k in range(6)))
        assert np.all(out[:, 5] == 0.0)  # no family has a moment about the boom axis
    assert worst <= REL_TOL, worst


@pytest.mark.parametrize("name", MODELS)
def test_generated_jacobi_equals_symbolic_at_40_digits(sample, reference, name):
    worst = max(rel_err(generated.MODELS[name].jacobi(y, p), reference[name].jacobi(y, p))
                for y, p in sample)
    assert worst <= REL_TOL, worst


def fd_jacobian(ref, y, p):
    """12x12 central difference of the 40-digit rhs, step 1e-12 max(1, |y_c|)."""
    cols = []
    with mpmath.workdps(40):
        for c in range(12):
            h = 1e-12 * max(1.0, abs(y[c]))
            yp, ym = list(map(mpmath.mpf, y)), list(map(mpmath.mpf, y))
            yp[c] += h
            ym[c] -= h
            fp, fm = ref.rhs(yp, p), ref.rhs(ym, p)
            cols.append([(fp[i] - fm[i]) / (2 * h) for i in range(12)])
    return np.array([[float(cols[c][i]) for c in range(12)] for i in range(12)])


@pytest.mark.slow
@pytest.mark.parametrize("name", MODELS)
def test_jacobian_equals_symbolic_difference_quotient(sample, reference, name):
    """The engine's Jacobian (central differences of the generated rhs) against the 40-digit one."""
    worst = 0.0
    for y, p in sample[::3]:
        J = np.full((12, 12), np.nan)
        jacobian(BY_NAME[name].index, 0.0, y, p, J)
        truth = fd_jacobian(reference[name], y, p)
        scale = np.maximum(np.max(np.abs(truth), axis=1, keepdims=True), FLOOR)
        worst = max(worst, float(np.max(np.abs(J - truth) / scale)))
    assert worst <= JAC_TOL, worst


@pytest.mark.parametrize("name", MODELS)
def test_zero_axial_inertia_branch_is_the_limit_of_small_axial_inertia(sample, name):
    """With axisymmetric boxes (I_roll = I_pitch) and axial inertia ε → 0, the 3×3
    attitude solve's φ̈, θ̈ tend to the J_ax = 0 branch's (2×2, ψ̈ = 0) as O(ε):
    eliminating ψ̈ leaves the 2×2 system plus terms ∝ ε.  So ψ̈ = 0 with point
    masses is the continuous choice, not an arbitrary one."""
    module = generated.MODELS[name]
    for y, p in sample[4:8]:  # the point-mass draws, all four tether cases
        q = p.copy()
        for body in (1, 2):
            q[PI(f"I{body}_roll")] = q[PI(f"I{body}_pitch")] = 5.0 * body
        d0 = np.full(12, np.nan)
        module.rhs(0.0, y, q, d0)
        assert d0[11] == 0.0
        diffs = []
        for eps in (1e-3, 1e-4):
            q[PI("I1_yaw")] = q[PI("I2_yaw")] = eps / 2
            d = np.full(12, np.nan)
            module.rhs(0.0, y, q, d)
            diffs.append(np.abs(d[9:11] - d0[9:11]) / np.max(np.abs(d0[9:11])))
        assert np.all(diffs[1] < 1e-3)  # close to the J_ax = 0 branch
        assert np.all((diffs[0] / diffs[1] > 8) & (diffs[0] / diffs[1] < 12))  # O(ε)
