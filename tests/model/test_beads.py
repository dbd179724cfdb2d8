"""Bead chains (tethersim/model/beads.py): N = 0 is the base model, the bead-string
modes, the Jacobi integral, and one-line refusals of bad input."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import tethersim as ts
from tethersim.model import bead_kernels, beads
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import get_model

SAT = ts.load_preset("satI")


def _random_states(rng, count, reach=40.0):
    """Balloon anywhere within ``reach`` of the COM, any pitch, rates up to ~1 m/s."""
    y = np.empty((count, 6))
    y[:, 0:2] = rng.uniform(-reach, reach, (count, 2))
    y[:, 2] = rng.uniform(-math.pi, math.pi, count)
    y[:, 3:5] = rng.normal(0.0, 0.5, (count, 2))
    y[:, 5] = rng.normal(0.0, 0.02, count)
    return y


def _tether_terms(y, p):
    """|F_j| / m3 on the balloon rows and arm_j |F_j| / I on θ̈, summed over the taut
    tethers, |F_j| = spring tension + c_j × the ends' relative inertial speed."""
    m1, m2, m3, a, b = p[0], p[1], p[2], p[6], p[7]
    w = p[17]
    s, c = math.sin(y[2]), math.cos(y[2])
    out = np.zeros(6)
    for arm, l0, E, cj in ((b, p[8], p[10], p[12]), (-a, p[9], p[11], p[13])):
        dx, dy = y[0] - arm * s, y[1] - arm * c
        lam = math.hypot(dx, dy)
        if lam > l0:
            vx = y[3] - arm * y[5] * c - w * dy
            vy = y[4] + arm * y[5] * s + w * dx
            f = E * (lam / l0 - 1.0) + cj * math.hypot(vx, vy)
            out[3:5] += f / m3
            out[5] += abs(arm) * f / (m1 * b**2 + m2 * a**2)
    return out


# each base compiles its own chain kernel (~10-20 s cold): the other two in the slow tier
@pytest.mark.parametrize("base", ["derived", *(pytest.param(b, marks=pytest.mark.slow)
                                               for b in beads.BASES[1:])])
def test_zero_beads_reproduce_the_base_model_to_1e_12(base):
    """N = 0, massless lines: the chain kernel's own tether forces (one segment per
    line) against the generated rhs, taut and slack tethers, drag and dampers on."""
    rng = np.random.default_rng(21)
    k = bead_kernels.kernels(base)
    ref_rhs = get_model(base).module.rhs
    # thesis lines and a stiff real line, so the tether terms dominate some rows
    for E1, E2, c1, c2 in ((SAT.E1, SAT.E2, SAT.c1, SAT.c2), (9e4, 5e4, 30.0, 20.0)):
        p0 = parameter_vector(SAT.replace(E1=E1, E2=E2, c1=c1, c2=c2,
                                          allow_implausible=True), base)
        p = beads.parameter_vector(p0, 0.0, 0.0, n=0)
        taut = np.zeros(2, dtype=int)
        for y in _random_states(rng, 200):
            ref, got = np.empty(6), np.empty(6)
            ref_rhs(0.0, y, p0, ref)
            k.rhs(0.0, y, p, got)
            # the size of the terms each row adds up: the row itself, the base model with
            # its tethers off, and the tether forces (whose torques may cancel in θ̈)
            off = np.empty(6)
            p_off = p0.copy()
            p_off[10:14] = 0.0
            ref_rhs(0.0, y, p_off, off)
            scale = np.maximum(np.maximum(np.abs(ref), np.abs(off)), _tether_terms(y, p0))
            assert np.all(np.abs(got - ref) <= 1e-12 * scale), (y, got, ref)
            g = np.empty(2)
            get_model(base).module.tether_margins(y, p0, g)
            taut += g > 0
        assert 0 < taut[0] < 200 and 0 < taut[1] < 200  # both branches visited


def _static_chain(n, stretch=1.2, E=5.0, mt=0.3):
    """Tether 1 straight along +x from the tip-mass (θ = π/2) to the balloon, stretched
    by ``stretch``; orbit and air made negligible (ω = 1e-9 rad/s, no drag); tether 2
    slack (rest length 1 km)."""
    sat = SAT.replace(E1=E, E2=E, c1=0.0, c2=0.0, CD=0.0, l20=1000.0, allow_implausible=True)
    p0 = parameter_vector(sat, "derived")
    p0[17] = 1e-9  # omega
    p0[18] = 0.0  # omega_earth
    L = stretch * sat.l10
    y6 = np.array([sat.b + L, 0.0, math.pi / 2, 0.0, 0.0, 0.0])
    p = beads.parameter_vector(p0, mt, mt, n=n)
    return beads.straight_chain(y6, n, p), p, sat, L


@pytest.mark.parametrize("n", [1, 2, 5, 8])
def test_transverse_and_axial_modes_of_a_taut_chain_match_the_bead_string(n):
    """Fixed ends (perturb the beads of tether 1 only): the transverse block's
    frequencies are 2 √(T/(m_b l_s)) sin(kπ/(2(N+1))) with T the tether's tension and
    l_s the stretched segment length, the axial block's 2 √((E/l_s0)/m_b) sin(...)
    (the textbook bead string; the kernel never forms this formula)."""
    y, p, sat, L = _static_chain(n)
    k = bead_kernels.kernels("derived")
    nq = y.size // 2
    f0 = np.empty_like(y)
    k.rhs(0.0, y, p, f0)
    idx = [3 + 2 * i for i in range(n)]  # x of tether 1's beads; y is +1
    for axis in (0, 1):
        cols = [i + axis for i in idx]
        K = np.empty((n, n))
        for c, i in enumerate(cols):
            h = 1e-6
            yp, ym = y.copy(), y.copy()
            yp[i] += h
            ym[i] -= h
            fp, fm = np.empty_like(y), np.empty_like(y)
            k.rhs(0.0, yp, p, fp)
            k.rhs(0.0, ym, p, fm)
            K[:, c] = -(fp[[nq + r for r in cols]] - fm[[nq + r for r in cols]]) / (2 * h)
        got = np.sort(np.sqrt(np.linalg.eigvals(K).real))
        mb = 0.3 / (n + 1)
        T = sat.E1 * (L / sat.l10 - 1.0)
        stiff = sat.E1 / (sat.l10 / (n + 1)) if axis == 0 else T / (L / (n + 1))
        kk = np.arange(1, n + 1)
        want = 2.0 * np.sqrt(stiff / mb) * np.sin(kk * math.pi / (2 * (n + 1)))
        np.testing.assert_allclose(got, want, rtol=1e-6)
    assert np.max(np.abs(f0[nq + 3:nq + 3 + 2 * n])) < 1e-9  # the straight chain is static


@pytest.mark.slow
def test_jacobi_integral_of_a_bead_chain_is_conserved_without_drag_and_dampers():
    """Two beads per line, springs in, drag and dampers off, balloon released 4 m
    behind so segments go slack and taut: h drifts ≤ 1e-8 of |h| and of the spring energy
    exchanged over half an orbit of scipy's DOP853 at rtol 1e-13 (the span of
    tests/engine/test_energy.py's check of the base models).  The drift falls with the
    tolerance (integration error, not a model inconsistency); scipy does not land its
    steps on the segments' slack/taut kinks, so it grows faster over longer runs."""
    sat = SAT.replace(CD=0.0, c1=0.0, c2=0.0)
    n = 2
    p = beads.parameter_vector(parameter_vector(sat, "derived"), 0.5, 0.5, n=n)
    y0 = beads.straight_chain(np.array([4.0, 0.0, 0.3, 0.0, 0.0, 0.0]), n, p)
    k = bead_kernels.kernels("derived")

    def f(t, y):
        d = np.empty_like(y)
        k.rhs(t, y, p, d)
        return d

    span = 0.5 * 2 * math.pi / p[17]
    r = solve_ivp(f, (0.0, span), y0, method="DOP853", rtol=1e-13, atol=1e-15,
                  dense_output=False, t_eval=np.linspace(0.0, span, 1001))
    assert r.status == 0
    h = np.array([k.jacobi(y, p) for y in r.y.T])
    T = np.empty((r.t.size, 2, n + 1))
    for i, y in enumerate(r.y.T):
        k.tensions(y, p, T[i])
    stiffness = p[10:12, None] / (p[8:10, None] / (n + 1))  # E_j / l_s [N/m]
    scale = np.ptp(np.sum(T**2 / (2 * stiffness), axis=(1, 2)))  # ½ k (λ − l_s)² summed
    taut = T > 0
    assert np.all(T >= 0.0) and np.any(taut.all(axis=0) != taut.any(axis=0))  # switches
    assert np.max(np.abs(h - h[0])) <= 1e-8 * min(scale, abs(h[0]))


@pytest.mark.parametrize("kw, words", [
    (dict(mt1=-1.0), "mt1 = -1.0: allowed 0 to 10000 kg"),
    (dict(mt2=0.0), "mt2 = 0.0: a chain of 2 beads needs a tether mass > 0"),
    (dict(CDt=9.0), "CDt = 9.0: allowed 0 to 4"),
    (dict(n=65), "beads = 65: allowed an integer 0 to 64 (beads per tether)"),
    (dict(n=1.5), "beads = 1.5: allowed an integer 0 to 64 (beads per tether)"),
])
def test_bad_chain_input_is_one_line_naming_the_field_and_range(kw, words):
    args = dict(mt1=0.1, mt2=0.1, n=2) | kw
    with pytest.raises(ValueError) as e:
        beads.parameter_vector(parameter_vector(SAT, "derived"), **args)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_an_unknown_base_model_is_refused_in_one_line():
    with pytest.raises(ValueError) as e:
        bead_kernels.kernels("3d")
    assert "bead base model = '3d': allowed values derived, exact-gravity" in str(e.value)
