"""The 3-D circular kernels' layout and their zero-axial-inertia rule.

Each generated kernel equals its own derivation for every model
(tests/derive/test_contract_symbolic.py, 40-digit truth of derive/reference.py);
here: the layout tables are the derivation's symbols, and the rule for point
masses (ψ̈ = 0, the (φ, θ) block alone) is the limit of a vanishing axial inertia.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim.generated as generated
from derive.models import THREE_D_DEFINITIONS as DEFINITIONS_3D
from derive.printer import module_filename
from derive.three_d import symbols3d as s3
from derive.three_d.forces3d import FAMILY_ORDER
from tethersim.generated import three_d as layout3d  # every 3-D model has this layout

MODELS = tuple(n for n, m in generated.MODELS.items()
               if m.GEOMETRY == "3d" and m.ORBIT == "circular")
SEED = 20051303
N_POINTS = 16
R0 = 6.578e6
MU = 3.986004418e14
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


def test_layout_tables_match_derive_symbols():
    assert layout3d.STATE == s3.STATE_NAMES and layout3d.PARAMETERS == s3.PARAMETER_NAMES
    assert layout3d.STATE_UNITS == s3.STATE_UNITS and layout3d.FAMILIES == FAMILY_ORDER
    assert tuple(d.name for d in DEFINITIONS_3D) == MODELS
    for name, module in ((n, generated.MODELS[n]) for n in MODELS):
        assert module.__name__.endswith(module_filename(name)[:-3])
        assert (module.STATE, module.PARAMETERS, module.FAMILIES) == (
            layout3d.STATE, layout3d.PARAMETERS, layout3d.FAMILIES)


@pytest.mark.parametrize("name", MODELS)
def test_zero_axial_inertia_branch_is_the_limit_of_small_axial_inertia(sample, name):
    """With axisymmetric boxes (I_roll = I_pitch) and axial inertia ε → 0, the 3×3
    attitude solve's φ̈, θ̈ tend to the J_ax = 0 branch's (2×2, ψ̈ = 0) as O(ε):
    eliminating ψ̈ leaves the 2×2 system plus terms ∝ ε.  So ψ̈ = 0 with point
    masses is the continuous choice, not an arbitrary one."""
    # the generated function's own arithmetic, uncompiled: a 3-D rhs costs 10-15 s to
    # compile, and this limit is a property of the printed formulas, not of the compiler
    rhs = generated.MODELS[name].rhs.py_func
    for y, p in sample[4:8]:  # the point-mass draws, all four tether cases
        q = p.copy()
        for body in (1, 2):
            q[PI(f"I{body}_roll")] = q[PI(f"I{body}_pitch")] = 5.0 * body
        d0 = np.full(12, np.nan)
        rhs(0.0, y, q, d0)
        assert d0[11] == 0.0
        diffs = []
        for eps in (1e-3, 1e-4):
            q[PI("I1_yaw")] = q[PI("I2_yaw")] = eps / 2
            d = np.full(12, np.nan)
            rhs(0.0, y, q, d)
            diffs.append(np.abs(d[9:11] - d0[9:11]) / np.max(np.abs(d0[9:11])))
        assert np.all(diffs[1] < 1e-3)  # close to the J_ax = 0 branch
        assert np.all((diffs[0] / diffs[1] > 8) & (diffs[0] / diffs[1] < 12))  # O(ε)
