"""One contract for every registered model (``tethersim.MODELS``): generated kernels = sympy.

Truth: derive.reference.Reference, the model's own derivation (derive.model.derive:
M, f, force families, tether lengths, Jacobi integral, body positions)
evaluated with mpmath at 40 digits and solved there (M q̈ = Σ Q − f by LU),
at the same float64 inputs.  Nothing of the printer (derive/emit.py, the
solves) is used, so each kernel is checked against an independent evaluation.
At random states of every model, tethers taut and slack (each case drawn,
gates 5 % or more from λ = l0), with and without the boxes' axial inertia for
the 3-D models:

* ``rhs`` = (q̇, q̈ of the derivation);
* ``family_forces`` = each family's generalized force (0 on a slack tether),
  so Σ family_forces = Q, the forces rhs solves with;
* ``jacobi`` = the Jacobi integral (free orbit: T + V) plus the taut springs' energy;
* ``tether_margins`` = λ_j − l_j0 with λ_j the derivation's tether lengths
  (Eqs 3.41-3.42), ``body_radii`` = |R_i| from its positions (Eqs 3.10-3.12).

* the engine's Jacobian (tethersim/engine/jacobian.py) = the 40-digit difference
  quotient of the derivation's rhs.

The energy rate and the Jacobian's consistency with rhs: tests/derive/test_contract.py.
Parametrised over tethersim.MODELS: a model `make derive` adds is checked with no
edit here.  The 3-D and free models (sympy derivations of up to a minute, kernels
that compile for tens of seconds) are in the slow tier.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import pytest

import tethersim as ts
from derive.reference import Reference, derived
from tethersim.engine.jacobian import jacobian
from tethersim.model.registry import BY_NAME, KERNELS

SEED = 20051207
N_POINTS = 24  # 4 tether cases × (boxes, point masses) × 3
CASES = ((True, True), (True, False), (False, True), (False, False))
R0 = 6.578e6  # m, a 200 km orbit (docs/sources.md)
MU = 3.986004418e14  # m^3/s^2
FLOOR = 1e-15  # where the truth is 0: slack families, drag on a coordinate its body does not move
# Per component |generated − truth| ≤ REL · |truth| + ABS.  Circular orbit: the
# thesis variants' 1e-12 and the 3-D models' 1e-11 relative (a few hundred ulps of
# cse'd straight-line code).  Free orbit: the offset rows' ~1e-5 m/s² tidal
# accelerations are the difference of ~9 m/s² gravity and centrifugal terms, which
# round at ~3e-15 m/s² (measured): 1e-13 absolute, 1e-20 rad/s² for ν.
REL = {("planar", "circular"): 1e-12, ("3d", "circular"): 1e-11,
       ("planar", "free"): 1e-12, ("3d", "free"): 1e-12}
FREE_ABS, FREE_NU_ABS = 1e-13, 1e-20
RANGES = dict(delta_x=40, delta_y=10, delta_z=10, phi=1.2, theta=math.pi, psi=math.pi,
              delta_x_dot=0.5, delta_y_dot=0.5, delta_z_dot=0.5, phi_dot=0.01,
              theta_dot=0.01, psi_dot=0.01, nu=math.pi, r_dot=50.0)


def _params():
    # the 3-D and free models derive for up to a minute and compile cold: the slow tier
    return [name if (BY_NAME[name].geometry, BY_NAME[name].orbit) == ("planar", "circular")
            else pytest.param(name, marks=pytest.mark.slow) for name in ts.MODELS]


@functools.cache
def reference(name) -> Reference:
    return Reference(derived(name))


def _draw(rng, name, taut, axial):
    """Random (y, p) at realistic scales; l10, l20 set so tether j is taut or slack by ≥ 5 %."""
    model, u = BY_NAME[name], rng.uniform
    par = dict(m1=u(5, 20), m2=u(50, 200), m3=u(0.5, 2), A1=u(0.1, 1), A2=u(0.1, 1),
               A3=u(5, 20), a=u(0.5, 2), b=u(5, 20), l10=1.0, l20=1.0, E1=u(1e-3, 0.1),
               E2=u(1e-3, 0.1), c1=u(1e-3, 0.1), c2=u(1e-3, 0.1), CD=2.0, r0=R0, mu=MU,
               omega=math.sqrt(MU / R0**3), omega_earth=7.292115e-5,
               # distinct densities per body catch swapped parameter slots
               rho1=u(2.5e-10, 3.1e-10), rho2=u(2.5e-10, 3.1e-10), rho3=u(2.5e-10, 3.1e-10),
               J2=u(0.8, 1.25) * 1.08263e-3, R_E=6378.137e3)
    for body in (1, 2):
        for ax in ("roll", "pitch", "yaw"):
            par[f"I{body}_{ax}"] = u(0.5, 30) if axial else 0.0
    r = R0 + u(-5e4, 5e4)
    y = np.array([r if n == "r" else math.sqrt(MU / r**3) * u(0.98, 1.02) if n == "nu_dot"
                  else u(-RANGES[n], RANGES[n]) for n in model.state])
    p = np.array([par[n] for n in model.parameters])
    lam = reference(name).tether_lengths(y, p)
    for j, n in enumerate(("l10", "l20")):
        ratio = u(1.05, 1.5)
        p[model.parameters.index(n)] = float(lam[j]) / ratio if taut[j] else float(lam[j]) * ratio
    return y, p


@functools.cache
def sample(name):
    rng = np.random.default_rng(SEED)
    return [_draw(rng, name, CASES[n % 4], axial=(n // 4) % 2 == 0) for n in range(N_POINTS)]


def _tolerance(name, k, truth):
    """Allowed |generated − truth| of rhs component k (see REL)."""
    model = BY_NAME[name]
    if model.orbit == "free":
        return REL[(model.geometry, model.orbit)] * abs(truth) + (
            FREE_NU_ABS if model.state[k] == "nu_dot" else FREE_ABS)
    return REL[(model.geometry, model.orbit)] * max(abs(truth), FLOOR)


def _err(got, truth):
    with mpmath.workdps(40):
        return float(abs(mpmath.mpf(float(got)) - truth))


@pytest.mark.parametrize("name", _params())
def test_sample_covers_every_tether_case_and_margins_decide_as_the_derivation(name):
    """Both taut, each alone, both slack all occur; the generated tether_margins
    (g_j = λ_j − l_j0) decide tautness as the 40-digit λ does, to rounding."""
    mod, ref, seen = KERNELS[BY_NAME[name].index], reference(name), set()
    for y, p in sample(name):
        g = np.empty(2)
        mod.tether_margins(y, p, g)
        lam = ref.tether_lengths(y, p)
        rest = [p[BY_NAME[name].parameters.index(n)] for n in ("l10", "l20")]
        for j in range(2):
            assert _err(g[j], lam[j] - mpmath.mpf(float(rest[j]))) <= 4e-16 * (float(lam[j]) + rest[j])
        assert tuple(g > 0.0) == ref.taut(y, p)
        seen.add(tuple(g > 0.0))
    assert seen == set(CASES)


@pytest.mark.parametrize("name", _params())
def test_generated_rhs_equals_the_derivation(name):
    mod, ref, n = KERNELS[BY_NAME[name].index], reference(name), BY_NAME[name].n_coordinates
    worst = 0.0
    for y, p in sample(name):
        d = np.full(2 * n, np.nan)
        mod.rhs(0.0, y, p, d)
        assert np.array_equal(d[:n], y[n:])  # q̇ passes through
        truth = ref.qdd(y, p)
        assert all(v == 0 or abs(v) > 1e3 * FLOOR for v in truth)  # FLOOR relaxes no non-zero truth
        worst = max(worst, *(_err(d[n + k], truth[k]) / _tolerance(name, n + k, truth[k])
                             for k in range(n)))
    assert worst <= 1.0, worst  # in units of the tolerance


def _family_tolerance(model, truth):
    """Allowed |generated − truth| of a family's force component.  Free orbit: the
    expanded tether families' r·(...) terms of ~1e6 N m cancel (derive/model.py
    _tidy), so the bound of the planar free models' check, 1e-10 |truth| + 1e-14
    (measured 1.3e-12 relative in ``3d-free-objective-damper``'s φ row)."""
    if model.orbit == "free":
        return 1e-10 * abs(truth) + 1e-14
    return REL[(model.geometry, model.orbit)] * max(abs(truth), FLOOR)


@pytest.mark.parametrize("name", _params())
def test_family_forces_equal_the_derived_families_and_sum_to_q(name):
    model, ref = BY_NAME[name], reference(name)
    mod, n = KERNELS[model.index], model.n_coordinates
    worst = 0.0
    for y, p in sample(name):
        out = np.full((len(model.families), n), np.nan)
        mod.family_forces(y, p, out)
        fam, taut = ref.forces(y, p), ref.taut(y, p)
        assert all(v == 0 or abs(v) > 1e3 * FLOOR for q in fam for v in q)
        for f, tether in enumerate(ref.tethers):
            worst = max(worst, *(_err(out[f, k], fam[f][k]) / _family_tolerance(model, fam[f][k])
                                 for k in range(n)))
            if tether is not None and not taut[tether - 1]:
                assert np.all(out[f] == 0.0)  # a slack tether pulls nothing (Eqs 3.35-3.36)
        for k in range(n):  # Σ family_forces = Q, the total force of the derivation
            Q = sum(fam[f][k] for f in range(len(fam)))
            assert _err(np.sum(out[:, k]), Q) <= sum(_family_tolerance(model, fam[f][k])
                                                     for f in range(len(fam)))
        if "psi" in model.state:  # no family has a moment about the boom axis
            assert np.all(out[:, model.state.index("psi")] == 0.0)
    assert worst <= 1.0, worst  # in units of the tolerance


@pytest.mark.parametrize("name", _params())
def test_jacobi_equals_the_derived_integral_plus_spring_energy(name):
    """Circular orbit: relative to Σ |terms| of h (the exact-gravity h of ~0.1 J is the
    difference of terms of ~1e3 J; measured ≤ 1.4e-15 of that sum).  Free orbit: to the
    total energy's rounding (|T + V| ~ 3.5e9 J: 1e-6 J + 1e-15 |h|, the bound of the
    free models' energy tests)."""
    model, ref, mod = BY_NAME[name], reference(name), KERNELS[BY_NAME[name].index]
    for y, p in sample(name):
        h = ref.jacobi(y, p)
        got = mod.jacobi(y, p)
        if model.orbit == "free":
            rel = 1e-15 if model.geometry == "planar" else 2e-15
            assert _err(got, h) <= 1e-6 + rel * abs(float(h)), (got, float(h))
        else:
            assert _err(got, h) <= REL[(model.geometry, model.orbit)] * float(ref.jacobi_scale(y, p))


@pytest.mark.parametrize("name", _params())
def test_body_radii_are_the_distances_of_the_derived_positions(name):
    """|R_i| ≈ 6.6e6 m, printed as hypot/√ of the position components: a few ulps."""
    ref, mod = reference(name), KERNELS[BY_NAME[name].index]
    for y, p in sample(name):
        got, truth = mod.body_radii(y, p), ref.body_radii(y, p)
        for i in range(3):
            assert _err(got[i], truth[i]) <= 4e-16 * float(truth[i]), (i, got[i], float(truth[i]))


# per entry, relative to the largest truth entry of its row: the engine's Jacobian
# (tethersim/engine/jacobian.py, its docstring: the analytic one of the thesis variants,
# else central differences of rhs, whose rounding follows the ~7.3 km/s air speed in
# the rate columns and, on a free orbit, the ~9 m/s² gravity cancelling in the δ rows)
JAC_TOL = {"circular": 1e-8, "free": 1e-4}


@pytest.mark.slow  # 40-digit difference quotients: 2n reference solves per state
@pytest.mark.parametrize("name", ts.MODELS)
def test_jacobian_equals_the_derivations_difference_quotient(name):
    """The engine's Jacobian against the 40-digit central difference of the derivation's
    rhs, step 1e-12 max(1, |y_c|) (truncation error ~1e-24), at five states."""
    model, ref = BY_NAME[name], reference(name)
    m = model.n_state
    for y, p in sample(name)[::5]:
        J = np.full((m, m), np.nan)
        jacobian(model.index, 0.0, y, p, J)
        truth = np.empty((m, m))
        with mpmath.workdps(40):
            for c in range(m):
                h = mpmath.mpf(1e-12) * max(1.0, abs(y[c]))
                yp, ym = [mpmath.mpf(float(v)) for v in y], [mpmath.mpf(float(v)) for v in y]
                yp[c] += h
                ym[c] -= h
                fp, fm = ref.rhs(yp, p), ref.rhs(ym, p)
                truth[:, c] = [float((fp[i] - fm[i]) / (2 * h)) for i in range(m)]
        scale = np.maximum(np.max(np.abs(truth), axis=1, keepdims=True), FLOOR)
        worst = float(np.max(np.abs(J - truth) / scale))
        assert worst <= JAC_TOL[model.orbit], worst
