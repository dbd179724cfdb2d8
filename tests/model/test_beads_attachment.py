"""Tethers held between the boom's ends (Satellite.s1, s2; tethersim/model/beads.py): the
torque by the arm against a numpy Newton computation, a line through the COM leaves the
pitch to the gravity gradient, an end share riding the boom keeps the Jacobi integral, the
single-line trim is its closed-form torque balance, and bad input is refused in one line."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.model import bead_kernels, beads
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import get_model

SAT = ts.load_preset("satI")
NB = beads.NB


def _states(rng, count):
    y = np.empty((count, 6))
    y[:, 0:2] = rng.uniform(-40.0, 40.0, (count, 2))
    y[:, 2] = rng.uniform(-math.pi, math.pi, count)
    y[:, 3:5] = rng.normal(0.0, 0.5, (count, 2))
    y[:, 5] = rng.normal(0.0, 0.02, count)
    return y


def test_a_line_held_between_the_ends_pulls_the_boom_by_its_arm():
    """N = 0, massless lines held at s1 = 0.3 b and s2 = −0.5 a: the chain's accelerations
    are the base model's with its tethers off plus each taut line's spring and thesis
    damper, F = −(E (λ/l0 − 1) u + c ṽ) on the balloon and its torque F · ∂r/∂θ with
    r = s (sin θ, cos θ) on the boom, written here in numpy (Newton, not the kernel)."""
    rng = np.random.default_rng(7)
    p0 = parameter_vector(SAT, "derived")
    s1, s2 = 0.3 * SAT.b, -0.5 * SAT.a
    p = beads.parameter_vector(p0, 0.0, 0.0, n=0, s1=s1, s2=s2)
    off = p0.copy()
    off[10:14] = 0.0  # E1, E2, c1, c2
    rhs = get_model("derived").module.rhs
    k = bead_kernels.kernels("derived")
    inertia, m3, w = SAT.pitch_inertia, SAT.m3, SAT.omega
    taut = 0
    for y in _states(rng, 300):
        base, got = np.empty(6), np.empty(6)
        rhs(0.0, y, off, base)
        k.rhs(0.0, y, p, got)
        want, scale = base.copy(), np.abs(base)
        sn, cs = math.sin(y[2]), math.cos(y[2])
        for s, l0, E, c in ((s1, SAT.l10, SAT.E1, SAT.c1), (s2, SAT.l20, SAT.E2, SAT.c2)):
            d = y[:2] - s * np.array([sn, cs])  # from the point on the boom to the balloon
            lam = float(np.hypot(*d))
            if lam <= l0:
                continue
            taut += 1
            u = d / lam
            rel = y[3:5] - s * y[5] * np.array([cs, -sn]) + w * np.array([-d[1], d[0]])
            F = -(E * (lam / l0 - 1.0) * u + c * rel)  # on the balloon
            want[3:5] += F / m3
            want[5] -= float(F @ (s * np.array([cs, -sn]))) / inertia
            scale[3:5] += np.abs(F) / m3
            scale[5] += abs(s) * float(np.hypot(*F)) / inertia
        assert np.all(np.abs(got - want) <= 1e-12 * scale + 1e-300), (y, got, want)
    assert taut > 100


def test_a_line_through_the_com_leaves_the_pitch_to_the_gravity_gradient():
    """One line held at the COM (s1 = 0, tether 2 absent): θ̈ is the boom's own, bit for
    bit, wherever the balloon is and however hard the line pulls; the balloon's rows are
    not."""
    rng = np.random.default_rng(8)
    sat = SAT.replace(E1=9e4, c1=5.0, E2=0.0, c2=0.0, l10=30.0, allow_implausible=True)
    p0 = parameter_vector(sat, "derived")
    p = beads.parameter_vector(p0, 0.0, 0.0, n=0, s1=0.0)
    off = p0.copy()
    off[10:14] = 0.0
    k, rhs = bead_kernels.kernels("derived"), get_model("derived").module.rhs
    pulled = 0
    for y in _states(rng, 200):
        base, got = np.empty(6), np.empty(6)
        rhs(0.0, y, off, base)
        k.rhs(0.0, y, p, got)
        assert got[5] == base[5]
        pulled += not np.allclose(got[3:5], base[3:5], rtol=1e-6, atol=0.0)
    assert pulled > 20  # the line did pull the balloon at those states


def test_a_line_end_share_riding_the_boom_keeps_the_jacobi_integral():
    """Two beads per 0.5 kg line, held at 0.4 b and −0.6 a (their end shares ride the boom
    as point masses), springs in, drag and dampers off: the Jacobi integral's rate along
    the chain's own rhs, central differences of h, is zero to the differences' rounding.
    It fails with the riding share's inertia or its gravity-inertial torque left out of
    the rhs (both mutations tried)."""
    rng = np.random.default_rng(9)
    sat = SAT.replace(CD=0.0, c1=0.0, c2=0.0)
    n = 2
    p = beads.parameter_vector(parameter_vector(sat, "derived"), 0.5, 0.5, n=n,
                               s1=0.4 * sat.b, s2=-0.6 * sat.a)
    k = bead_kernels.kernels("derived")
    checked = 0
    for y6 in _states(rng, 40):
        y6[:2] = rng.uniform(-3.0, 3.0, 2) + [20.0, 0.0]  # behind, lines near taut
        y = beads.straight_chain(y6, n, p)
        y[3:3 + 4 * n] += rng.normal(0.0, 0.05, 4 * n)
        f = np.empty_like(y)
        k.rhs(0.0, y, p, f)
        eps = 1e-6 / max(1.0, float(np.max(np.abs(f))))
        rate = (k.jacobi(y + eps * f, p) - k.jacobi(y - eps * f, p)) / (2 * eps)
        # the size of the terms: each coordinate's share of the rate
        terms = np.empty(y.size)
        for i in range(y.size):
            e = np.zeros_like(y)
            e[i] = eps * f[i]
            terms[i] = (k.jacobi(y + e, p) - k.jacobi(y - e, p)) / (2 * eps)
        assert abs(rate) <= 1e-6 * np.sum(np.abs(terms)), (rate, np.sum(np.abs(terms)))
        checked += np.sum(np.abs(terms)) > 0
    assert checked == 40


@pytest.mark.slow
@pytest.mark.parametrize("s", [0.0, 0.01, 0.02, 0.05, 1.0])
def test_a_single_line_trims_the_pitch_by_its_closed_form_torque_balance(s):
    """SatI on one 30 m Dyneema line held at s: the equilibrium start's pitch is
    asin(s / s_c), s_c = 3 ω² I / T with T the line's tension (the balloon's drag), to the
    end bodies' own drag (1e-4 rad); beyond s_c the boom lies along the flow (π/2)."""
    from tethersim.engine.start import equilibrium_satellite
    from tethersim.experiments.real_tethers import single_line_reach
    from tethersim.model.materials import with_tethers
    sat = with_tethers(SAT.replace(l10=30.0, E2=0.0, c2=0.0, s1=s), "dyneema-sk75", 1e-3,
                       tethers=(1,))
    got = equilibrium_satellite(sat, "objective-damper+beads0")
    dx, dy, th = got.initial[:3]
    lam = math.hypot(dx - s * math.sin(th), dy - s * math.cos(th))
    tension = sat.E1 * (lam / sat.l10 - 1.0)
    s_c = 3 * sat.omega ** 2 * sat.pitch_inertia / tension
    want = math.asin(s / s_c) if s < s_c else math.pi / 2
    assert abs(th - want) <= 1e-4, (th, want, s_c)
    # the report's closed form, from the balloon's drag ½ ρ C_D A3 v² alone
    assert single_line_reach(sat) == pytest.approx(s_c, rel=1e-6)


@pytest.mark.parametrize("changes, words", [
    (dict(s1=11.0), "s1 = 11.0 m: allowed -1 to 10.5 m"),
    (dict(s2=-1.5), "s2 = -1.5 m: allowed -1 to 10.5 m"),
    (dict(s1="x"), "s1 = 'x' m: allowed -1 to 10.5 m"),
])
def test_an_attachment_off_the_boom_is_refused_in_one_line(changes, words):
    with pytest.raises(ValueError) as e:
        SAT.replace(**changes)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_a_model_that_holds_its_lines_at_the_ends_refuses_attachment_points():
    """A sweep, the atlas, a 3-D or free-orbit model: one line, not a silent boom end."""
    with pytest.raises(ValueError) as e:
        parameter_vector(SAT.replace(s1=0.0), "3d")
    msg = str(e.value)
    assert "s1, s2 = 0.0, None m" in msg and "bead chain" in msg and "\n" not in msg
    # a run of such a model (a free orbit here) says the same, not a word about beads
    with pytest.raises(ValueError) as e:
        ts.simulate(SAT.replace(s1=0.0, orbit="free"), periods=0.01, progress=False)
    assert "model 'free' holds its tethers at the boom ends" in str(e.value)
    # the ends given explicitly are the thesis's lines
    assert np.array_equal(parameter_vector(SAT.replace(s1=SAT.b, s2=-SAT.a), "derived"),
                          parameter_vector(SAT, "derived"))


@pytest.mark.slow
def test_a_line_through_the_com_leaves_the_pitch_mode_the_boom_alones():
    """find_equilibrium of one Dyneema line held at the COM (it runs the chain of no beads):
    the pitch mode is the boom's own libration, √3 ω (the end bodies' drag shifts it by
    ~1e-6), and the balloon adds no damping: it decays as slowly as the boom alone, in
    years (the bridle's slowest mode: days, docs/real-tethers.md)."""
    from tethersim.analysis.equilibrium import find_equilibrium
    from tethersim.model.materials import with_tethers
    sat = with_tethers(SAT.replace(l10=30.0, E2=0.0, c2=0.0, s1=0.0), "dyneema-sk75", 1e-3,
                       tethers=(1,))
    eq = find_equilibrium(sat, "objective-damper")
    assert eq.model == "objective-damper+beads0"
    w, _, tau = min(eq.modes(), key=lambda m: m[0])
    assert w == pytest.approx(math.sqrt(3) * sat.omega, rel=1e-4)
    assert tau > 1e4 * 3600
