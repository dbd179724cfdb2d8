"""The bead-chain kernel (tethersim/model/beads.py) against Lagrange's equations of
the chain written out in sympy for N = 1 and 2 beads per tether.

The reference is built here from scratch: every body and bead a particle of
sympy.physics.mechanics in the frame L turning at ω about z (Eq 3.13), its
kinetic energy from its inertial velocity, its gravity −μ m/|r| (three binomial
terms, Eqs 3.20-3.25, truncated at 1/r0 as the `derived` model is, or exact), the
segment springs as potentials ½ (E/l_s)(λ_s − l_s)² gated by tautness, drag
(Eq 3.32), the segment dampers and the segments' cross-flow drag as explicit
forces through their partial velocities (Eq 3.31).  Evaluated in 30 digits at
random states with taut and slack segments; the kernel is compared row by row.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, Point, ReferenceFrame, dynamicsymbols

import tethersim as ts
from derive.pipeline import truncate_inverse_r0
from derive.symbols import P
from tethersim.model import bead_kernels, beads
from tethersim.model.bead_layout import SCRATCH
from tethersim.model.inputs import parameter_vector

t = dynamicsymbols._t
EXTRA = {n: sp.Symbol(n, positive=True) for n in beads.EXTRA_PARAMETERS}
BASE = tuple(P[n] for n in beads._BASE_NAMES)


@functools.cache
def chain_equations(n: int, base: str):
    """(state symbols, M diag, f, force terms) of the chain with n beads per tether.

    Force terms: list of (segment or None, (Q_1 ... Q_nq)); a segment is (j, s) and
    its terms count only while λ_s > l_s (``lengths[(j, s)]`` is λ_s).
    """
    r0, w, wE = P["r0"], P["omega"], P["omega_earth"]
    m1, m2, m3, a, b = (P[k] for k in ("m1", "m2", "m3", "a", "b"))
    mt = (EXTRA["mt1"], EXTRA["mt2"])
    q = list(dynamicsymbols("dx dy th"))
    for j in (1, 2):
        for k in range(1, n + 1):
            q += list(dynamicsymbols(f"x{j}_{k} y{j}_{k}"))
    qd = [x.diff(t) for x in q]
    NF = ReferenceFrame("N")
    L = NF.orientnew("L", "Axis", [w * t, NF.z])
    origin = Point("O")
    origin.set_vel(NF, 0)

    def point(name, x, y):
        pt = origin.locatenew(name, x * L.x + (r0 + y) * L.y)
        pt.set_vel(NF, pt.pos_from(origin).dt(NF).express(L))
        return pt, (x, y)

    th = q[2]
    tip = point("tip", b * sp.sin(th), b * sp.cos(th))
    bus = point("bus", -a * sp.sin(th), -a * sp.cos(th))
    balloon = point("balloon", q[0], q[1])
    lump = [mt[j] / (2 * (n + 1)) for j in range(2)]
    bodies = [(tip, m1 + lump[0]), (bus, m2 + lump[1]), (balloon, m3 + lump[0] + lump[1])]
    chains = []
    for j in range(2):
        chain = [(tip, bus)[j]]
        for k in range(n):
            i = 3 + 2 * (j * n + k)
            pt = point(f"bead{j}{k}", q[i], q[i + 1])
            chain.append(pt)
            bodies.append((pt, mt[j] / (n + 1)))
        chain.append(balloon)
        chains.append(chain)

    mu = w**2 * r0**3
    T = V = 0
    for (pt, (x, y)), m in bodies:
        v = pt.vel(NF)
        T += m * v.dot(v) / 2
        if base == "exact-gravity":
            V += -mu * m / sp.sqrt(x**2 + (r0 + y) ** 2)
        else:
            beta, n_ = 2 * r0 * y + x**2 + y**2, sp.Rational(-1, 2)  # Eqs 3.21-3.22
            inv = (r0**-1 + n_ * r0 ** (2 * (n_ - 1)) * beta
                   + n_ * (n_ - 1) / 2 * r0 ** (2 * (n_ - 2)) * beta**2)
            V += -mu * m * inv
    lhs = LagrangesMethod(T - V, q, frame=NF).form_lagranges_equations()

    qdd_s = sp.symbols(f"qdd0:{len(q)}", real=True)
    qd_s = sp.symbols(f"qd0:{len(q)}", real=True)
    q_s = sp.symbols(f"q0:{len(q)}", real=True)
    sub = dict(zip([x.diff(t, 2) for x in q], qdd_s))

    def plain(e):
        e = sp.sympify(e).xreplace(sub).xreplace(dict(zip(qd, qd_s)))
        return e.xreplace(dict(zip(q, q_s)))

    lhs = [sp.expand(plain(e)) for e in lhs]
    if base != "exact-gravity":
        lhs = [truncate_inverse_r0(e, 1) for e in lhs]
    M = [sp.diff(e, qdd_s[k]) for k, e in enumerate(lhs)]
    f = [e.subs(dict.fromkeys(qdd_s, 0)) for e in lhs]

    def Q(pt, F):
        v = pt.vel(NF)
        return tuple(plain(F.dot(v.diff(x, NF))) for x in qd)

    def air(pt, xy):  # V_rel, Eq 3.33
        return pt.vel(NF) - (wE * L.z).cross(xy[0] * L.x + (r0 + xy[1]) * L.y)

    terms = []
    for (pt, xy), A, rho in ((tip, P["A1"], P["rho1"]), (bus, P["A2"], P["rho2"]),
                             (balloon, P["A3"], P["rho3"])):
        v = air(pt, xy)
        terms.append((None, Q(pt, -P["CD"] * A * rho / 2 * sp.sqrt(v.dot(v)) * v)))
    lengths = {}
    for j, chain in enumerate(chains):
        E, c = (P["E1"], P["E2"])[j], (n + 1) * (P["c1"], P["c2"])[j]
        ls = (P["l10"], P["l20"])[j] / (n + 1)
        for s in range(n + 1):
            (pa, (xa, ya)), (pb, (xb, yb)) = chain[s], chain[s + 1]
            d = (xb - xa) * L.x + (yb - ya) * L.y
            lam = sp.sqrt((xb - xa) ** 2 + (yb - ya) ** 2)
            lengths[(j, s)] = plain(lam)
            Vs = E / (2 * ls) * (lam - ls) ** 2
            terms.append(((j, s), tuple(plain(-sp.diff(Vs, x)) for x in q)))
            w_rel = pb.vel(NF) - pa.vel(NF)
            tau = d / lam
            if base == "objective-damper":
                Fd = -c * tau.dot(w_rel) * tau
            else:
                Fd = -c * w_rel
            terms.append(((j, s), tuple(x + y for x, y in zip(Q(pb, Fd), Q(pa, -Fd)))))
            vm = (air(pa, (xa, ya)) + air(pb, (xb, yb))) / 2
            vn = vm - vm.dot(tau) * tau
            Fdr = -P["rho3"] * EXTRA["CDt"] * (EXTRA["dt1"], EXTRA["dt2"])[j] / 2 * lam \
                * sp.sqrt(vn.dot(vn)) * vn / 2
            terms.append((None, tuple(x + y for x, y in zip(Q(pa, Fdr), Q(pb, Fdr)))))
    state = q_s + qd_s
    args = state + BASE + tuple(EXTRA.values())
    num = functools.partial(sp.lambdify, args, modules="mpmath")
    return (num(M), num(f), [(g, num(list(e))) for g, e in terms],
            {k: num(v) for k, v in lengths.items()})


def reference_accelerations(n, base, y, p):
    M, f, terms, lengths = chain_equations(n, base)
    with mpmath.workdps(30):
        # the parameters without the kernel's scratch tail (bead_layout.SCRATCH)
        args = [mpmath.mpf(float(v)) for v in list(y) + list(p[:len(p) - SCRATCH])]
        Mv, fv = M(*args), f(*args)
        taut = {k: lam(*args) > args[len(y) + (8 if k[0] == 0 else 9)] / (n + 1)
                for k, lam in lengths.items()}
        Qv = [mpmath.mpf(0)] * len(Mv)
        scale = [abs(x) for x in fv]
        for gate, e in terms:
            if gate is None or taut[gate]:
                for k, v in enumerate(e(*args)):
                    Qv[k] += v
                    scale[k] += abs(v)
        acc = [(Qv[k] - fv[k]) / Mv[k] for k in range(len(Mv))]
        return (np.array([float(x) for x in acc]),
                np.array([float(s / m) for s, m in zip(scale, Mv)]), taut)


def _states(rng, n, p, count):
    """Balloon 3-9 m from the COM, beads near the straight lines (±0.8 m), random rates."""
    out = []
    for _ in range(count):
        r, ang = rng.uniform(3.0, 9.0), rng.uniform(0, 2 * math.pi)
        y6 = np.array([r * math.cos(ang), r * math.sin(ang), rng.uniform(-1, 1),
                       *rng.normal(0, 0.3, 2), rng.normal(0, 0.01)])
        y = beads.straight_chain(y6, n, p)
        nq = y.size // 2
        y[3:nq] += rng.uniform(-0.8, 0.8, nq - 3)
        y[nq + 3:] += rng.normal(0, 0.3, nq - 3)
        out.append(y)
    return out


@pytest.mark.slow
@pytest.mark.parametrize("base", beads.BASES)
@pytest.mark.parametrize("n", [1, 2])
def test_chain_kernel_equals_lagrange_equations_of_the_bead_chain(n, base):
    sat = ts.load_preset("satI").replace(l10=5.0, l20=4.0, E1=3.0, E2=5.0, c1=0.02, c2=0.03,
                                         allow_implausible=True)
    p = beads.parameter_vector(parameter_vector(sat, base), 0.2, 0.3, 1e-3, 2e-3, 2.2, n=n)
    k = bead_kernels.kernels(base)
    rng = np.random.default_rng(100 + n)
    seen = set()
    for y in _states(rng, n, p, 12):
        want, scale, taut = reference_accelerations(n, base, y, p)
        got = np.empty_like(y)
        k.rhs(0.0, y, p, got)
        nq = y.size // 2
        np.testing.assert_array_equal(got[:nq], y[nq:])
        err = np.abs(got[nq:] - want)
        assert np.all(err <= 1e-10 * np.maximum(np.abs(want), scale)), (err / scale, taut)
        seen |= set(taut.values())
    assert seen == {True, False}  # taut and slack segments both checked
