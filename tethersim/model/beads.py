"""Tethers with mass: each line a chain of N point-mass beads (issue 21, item 3).

Written once for any N over a planar, circular-orbit base model (``derived``,
``exact-gravity``, ``objective-damper``), not derived per N: every body of the
thesis model is a point mass, so in the rotating frame L the mass matrix is
diagonal (m3 on δx, δy; I = m1 b² + m2 a² on θ) and a bead obeys the balloon's
own translational equations (the model's gravity law, Coriolis and centrifugal
terms) plus the forces of its two segments.  The kernel therefore

1. calls the base model's generated ``rhs`` with the tethers switched off
   (E1 = E2 = c1 = c2 = 0 in a copy of p) for the boom and the balloon, drag
   included;
2. calls it again at each bead's position with every drag area zero, and
   takes the balloon rows (δẍ, δÿ) as the bead's gravity-inertial acceleration
   (those rows do not depend on θ nor, with Q = 0, on m3);
3. adds the segment forces: on the balloon divided by m3, on the boom as the
   torque Q_θ = F · ∂r_end/∂θ divided by I (Eq 3.31; the boom's COM is held, so a
   force on the boom acts only through Q_θ, as in the base model), on each bead
   divided by its mass.

Each line holds the boom at its attachment point r_end = s_j (sin θ, cos θ), s_j
from the COM toward the tip-mass (``s1``, ``s2`` in the parameter vector; the
thesis's ends b and −a by default, Eqs 3.10-3.11), anywhere from −a to b.

Segments (tether j, rest length l_j0, N beads, N + 1 segments of rest length
l_s = l_j0 / (N + 1)), each tension-only, slack when λ_s ≤ l_s, as Eqs 3.35-3.36:

* spring: T = E_j (λ_s / l_s − 1) along the segment, E_j being E·A [N] as in
  the base model, so a segment's stiffness E_j / l_s is (N + 1) times the
  tether's and the chain in series has the tether's static stiffness;
* damper, while taut: the base model's law with c_s = (N + 1) c_j (dashpots in
  series): −c_s (ṙ_far − ṙ_near) on the far node for the thesis damper
  (Eqs 3.43-3.44, inertial relative velocity), c_s λ̇_s along the segment for
  the Kelvin-Voigt damper of ``objective-damper``, clamped at minus the spring
  (a segment never pushes);
* drag (optional, ``CDt`` = 0 by default): a cylinder of diameter d_j and the
  segment's length, −½ ρ3 C_Dt d_j λ_s |v_n| v_n with v_n the air-relative
  velocity of the segment's midpoint normal to the segment (the cross-flow
  principle of KiteModels.jl's tether drag), half to each end node.  ρ3 is the
  balloon's density: the beads sit within a tether length of it.

Mass lumping (the lumped-mass rule of GTOSS and KiteModels.jl): each segment
carries μ_j / (N + 1) [kg], half to each end node, so an inner bead has
m_b = μ_j / (N + 1) and each end of the line gets μ_j / (2 (N + 1)): added to
the balloon's m3 and, for a line held at a boom end, to that end's body (m1 at b,
m2 at −a) before the base model runs, so the added end masses enter its
gravity-gradient torque and inertia exactly as the bodies' own masses do.  A line
held between the ends leaves its share e riding the boom at s: e s² more inertia
and the torque e a_free · ∂r/∂θ, a_free being a free particle's acceleration there
(the balloon rows again).  With N = 0 half of each line sits at each end.

State (SI): the base model's coordinates, then the beads' offsets from the
COM point (0, r0) in L, tether 1 then tether 2, each from the boom end to the
balloon, then all their rates in the same order; parameter vector: the base
model's, then :data:`EXTRA_PARAMETERS`.  tests/model/test_beads.py and
tests/derive/test_beads_lagrange.py check it (docs/beads.md).

Compiled code: the kernels here take the base as a literal that picks its generated
kernels (tethersim.model.bead_base, as tethersim/engine/dynamics.py picks a model's);
tethersim.model.bead_kernels
holds one cached entry point per base (``rhs_derived`` ...) and the chain's event
functions.  No evaluation allocates: the base model's parameter vector, state and
rates it builds live in the tail of the chain's parameter vector (``SCRATCH`` floats,
bead_layout.parameter_vector), the rule of tethersim/engine/integrators/borrow.py.
The engine runs it as a registered model (tethersim.model.registry.BEAD_INDEX).
"""
from __future__ import annotations

import math

from numba import literally, njit

from tethersim.generated.trig import sincos
from tethersim.model.bead_base import GENERATED, _base_family_forces, _base_jacobi, _base_rhs
from tethersim.model.bead_layout import (  # noqa: F401  (the layout, re-exported: one import for users)
    _A,
    _A1,
    _A2,
    _A3,
    _B,
    _BASE_NAMES,
    _C1,
    _C2,
    _E1,
    _E2,
    _L10,
    _M1,
    _M2,
    _M3,
    _OMEGA,
    _OMEGA_E,
    _R0,
    _RHO3,
    _S1,
    BASES,
    EXTRA_PARAMETERS,
    EXTRA_RANGES,
    EXTRA_UNITS,
    N_MAX,
    NB,
    SCRATCH,
    check_base,
    check_beads,
    parameter_vector,
    state_names,
    straight_chain,
)

# the kernels' scratch, the tail of the parameter vector (bead_layout.SCRATCH): base p,
# base state, base rates
_S_PB = NB + len(EXTRA_PARAMETERS)
_S_YB = _S_PB + NB
_S_DB = _S_YB + 6
_OBJECTIVE = BASES.index("objective-damper")  # its segments damp along their stretch rate
# the base models' drag families (the same FAMILIES in every base): the chain's dissipated
# power takes the base's generalized drag forces on the boom and the balloon
_FAMILIES = GENERATED[BASES[0]].FAMILIES
assert all(GENERATED[b].FAMILIES == _FAMILIES for b in BASES)
_DRAG = tuple(i for i, f in enumerate(_FAMILIES) if f.startswith("drag"))
N_FAMILIES = len(_FAMILIES)


@njit(cache=True, inline="always")
def node(y, p, n, j, k):
    """(x, y, ẋ, ẏ) of tether j's node k in L: 0 boom end, 1..n beads, n+1 balloon."""
    nq = 3 + 4 * n
    if k == n + 1:
        return y[0], y[1], y[nq], y[nq + 1]
    if k == 0:
        th, thd = y[2], y[nq + 2]
        s, c = sincos(th)  # the generated kernels' sin and cos (generated/trig.py)
        arm = p[_S1 + j]  # the attachment point along the boom (thesis: +b, −a)
        return arm * s, arm * c, arm * thd * c, -arm * thd * s
    i = 3 + 2 * (j * n + k - 1)
    return y[i], y[i + 1], y[nq + i], y[nq + i + 1]


@njit(cache=True, inline="always")
def _segment(y, p, n, j, s, objective):
    """Tether j's segment s (node s to s+1): (force on the far node (x, y) from the
    spring and damper, drag on each end node (x, y), spring tension [N], λ_s [m])."""
    l_s = p[_L10 + j] / (n + 1)
    x0, y0, u0, v0 = node(y, p, n, j, s)
    x1, y1, u1, v1 = node(y, p, n, j, s + 1)
    ddx, ddy = x1 - x0, y1 - y0
    lam = math.sqrt(ddx * ddx + ddy * ddy)
    tx, ty = ddx / lam, ddy / lam  # from the near node (s) to the far one (s+1)
    omega = p[_OMEGA]
    fx = fy = ten = 0.0
    if lam > l_s:  # taut (Eqs 3.35-3.36)
        c_s = (n + 1) * p[_C1 + j]
        # inertial relative velocity of the ends: Δṙ_L + ω ẑ × Δr (Eq 3.13)
        wx = u1 - u0 - omega * ddy
        wy = v1 - v0 + omega * ddx
        ten = p[_E1 + j] * (lam / l_s - 1.0)
        fx -= ten * tx
        fy -= ten * ty
        if objective:  # Kelvin-Voigt: c λ̇ along the segment, clamped at minus the
            # spring so the segment never pushes (derive/forces.py damper_pull)
            pull = max(c_s * (tx * wx + ty * wy), -ten)
            fx -= pull * tx
            fy -= pull * ty
        else:  # thesis damper, Eqs 3.43-3.44
            fx -= c_s * wx
            fy -= c_s * wy
    dx = dy = 0.0
    cdt = 0.5 * p[_RHO3] * p[NB + 4] * p[NB + 2 + j]  # ½ ρ3 C_Dt d_j
    if cdt > 0.0:  # cross-flow drag of the segment, half to each end
        w_air = omega - p[_OMEGA_E]  # air-relative rotation rate of L (Eq 3.33)
        vx = 0.5 * (u0 + u1) - w_air * (p[_R0] + 0.5 * (y0 + y1))
        vy = 0.5 * (v0 + v1) + w_air * 0.5 * (x0 + x1)
        along = vx * tx + vy * ty
        nx, ny = vx - along * tx, vy - along * ty
        kd = -0.5 * cdt * lam * math.sqrt(nx * nx + ny * ny)
        dx, dy = kd * nx, kd * ny
    return fx, fy, dx, dy, ten, lam


@njit(cache=True)
def _base_inputs(y, p, n, pb, yb):
    """pb = the base p with the tethers off and the line's end masses added (a boom end's
    to its end body; one held between the ends is :func:`_held_share`'s); yb = the boom's
    and balloon's coordinates and rates (the base model's state)."""
    for i in range(NB):
        pb[i] = p[i]
    pb[_E1] = pb[_E2] = pb[_C1] = pb[_C2] = 0.0
    e1 = p[NB] / (2.0 * (n + 1))
    e2 = p[NB + 1] / (2.0 * (n + 1))
    for j, e in ((0, e1), (1, e2)):
        if p[_S1 + j] == p[_B]:
            pb[_M1] += e
        elif p[_S1 + j] == -p[_A]:
            pb[_M2] += e
    pb[_M3] += e1 + e2
    nq = y.shape[0] // 2
    for i in range(3):
        yb[i] = y[i]
        yb[3 + i] = y[nq + i]


@njit(cache=True, inline="always")
def _held_share(p, n, j):
    """Mass [kg] of tether j's boom-side end share held at a point between the boom's ends
    (0 at an end: there it is the end body's, :func:`_base_inputs`)."""
    s = p[_S1 + j]
    if s == p[_B] or s == -p[_A]:
        return 0.0
    return p[NB + j] / (2.0 * (n + 1))


@njit(cache=True, inline="always")
def _add_force(dydt, p, n, j, k, fx, fy, sc, m3, inertia):
    """Add a force (fx, fy) [N] on tether j's node k to the accelerations in dydt."""
    nq = 3 + 4 * n
    if k == 0:  # the boom: Q_θ = F · ∂r_end/∂θ, r_end = arm (sin θ, cos θ) (Eq 3.31)
        arm = p[_S1 + j]
        dydt[nq + 2] += arm * (fx * sc[1] - fy * sc[0]) / inertia
    elif k == n + 1:
        dydt[nq] += fx / m3
        dydt[nq + 1] += fy / m3
    else:
        mb = p[NB + j] / (n + 1)
        i = nq + 3 + 2 * (j * n + k - 1)
        dydt[i] += fx / mb
        dydt[i + 1] += fy / mb


@njit(cache=True)
def chain_rhs(kind, t, y, p, dydt):
    """dy/dt of the chain model over base ``BASES[kind]`` (SI; layout: module docstring).

    Its scratch (the base p, state and rates) is the tail of p (:data:`SCRATCH`): no
    allocation, as the engine's time loops require (integrators/borrow.py).
    """
    literally(kind)
    nq = y.shape[0] // 2
    n = (nq - 3) // 4
    pb = p[_S_PB:_S_PB + NB]
    yb = p[_S_YB:_S_YB + 6]
    db = p[_S_DB:_S_DB + 6]
    _base_inputs(y, p, n, pb, yb)
    _base_rhs(kind, t, yb, pb, db)
    inertia = pb[_M1] * p[_B] ** 2 + pb[_M2] * p[_A] ** 2
    for i in range(nq):
        dydt[i] = y[nq + i]
    dydt[nq] = db[3]
    dydt[nq + 1] = db[4]
    dydt[nq + 2] = db[5]
    # the beads' gravity-inertial accelerations: the balloon rows, no drag areas
    pb[_A1] = pb[_A2] = pb[_A3] = 0.0
    for i in range(3, nq, 2):
        yb[0] = y[i]
        yb[1] = y[i + 1]
        yb[3] = y[nq + i]
        yb[4] = y[nq + i + 1]
        _base_rhs(kind, t, yb, pb, db)
        dydt[nq + i] = db[3]
        dydt[nq + i + 1] = db[4]
    sc = sincos(y[2])
    # a line's end share held between the boom's ends: a point mass e riding the boom at
    # r = s (sin θ, cos θ); its r̈ · ∂r/∂θ is s² θ̈, so it adds e s² to the inertia and
    # e a_free · ∂r/∂θ to the torque, a_free being a free particle's acceleration there
    # (the balloon rows again, as a bead's)
    held, torque = 0.0, 0.0
    for j in range(2):
        e = _held_share(p, n, j)
        if e > 0.0:
            yb[0], yb[1], yb[3], yb[4] = node(y, p, n, j, 0)
            _base_rhs(kind, t, yb, pb, db)
            arm = p[_S1 + j]
            held += e * arm * arm
            torque += e * arm * (db[3] * sc[1] - db[4] * sc[0])
    if held > 0.0:
        dydt[nq + 2] = (dydt[nq + 2] * inertia + torque) / (inertia + held)
        inertia += held
    m3 = p[_M3] + (p[NB] + p[NB + 1]) / (2.0 * (n + 1))
    for j in range(2):
        for s in range(n + 1):
            fx, fy, dx, dy, _, _ = _segment(y, p, n, j, s, kind == _OBJECTIVE)
            _add_force(dydt, p, n, j, s + 1, fx + dx, fy + dy, sc, m3, inertia)
            _add_force(dydt, p, n, j, s, dx - fx, dy - fy, sc, m3, inertia)


@njit(cache=True)
def tensions(y, p, out):
    """out[j, s] = spring tension of tether j's segment s [N] (0 slack), boom end first."""
    n = (y.shape[0] // 2 - 3) // 4
    for j in range(2):
        for s in range(n + 1):
            out[j, s] = _segment(y, p, n, j, s, False)[4]


@njit(cache=True)
def chain_jacobi(kind, y, p):
    """Jacobi integral of the chain model [J]: constant with every drag and damper off.

    The base model's (tethers off, end masses added), each bead's as a balloon of
    the bead's mass with no boom, and ½ (E_j / l_s)(λ_s − l_s)² per taut segment.
    Scratch: the tail of p, as :func:`chain_rhs`.
    """
    literally(kind)
    nq = y.shape[0] // 2
    n = (nq - 3) // 4
    pb = p[_S_PB:_S_PB + NB]
    yb = p[_S_YB:_S_YB + 6]
    _base_inputs(y, p, n, pb, yb)
    h = _base_jacobi(kind, yb, pb)
    pb[_M1] = pb[_M2] = 0.0
    yb[2] = yb[5] = 0.0
    for j in range(2):
        if n > 0:
            pb[_M3] = p[NB + j] / (n + 1)
            for k in range(n):
                i = 3 + 2 * (j * n + k)
                yb[0] = y[i]
                yb[1] = y[i + 1]
                yb[3] = y[nq + i]
                yb[4] = y[nq + i + 1]
                h += _base_jacobi(kind, yb, pb)
        e = _held_share(p, n, j)
        if e > 0.0:  # its end share held between the boom's ends: a point mass riding it
            pb[_M3] = e
            yb[0], yb[1], yb[3], yb[4] = node(y, p, n, j, 0)
            h += _base_jacobi(kind, yb, pb)
        l_s = p[_L10 + j] / (n + 1)
        for s in range(n + 1):
            lam = _segment(y, p, n, j, s, False)[5]
            if lam > l_s:
                h += 0.5 * p[_E1 + j] / l_s * (lam - l_s) ** 2
    return h


@njit(cache=True)
def chain_power(kind, y, p, fam):
    """Power of drag and dampers [W]: the Jacobi integral's rate, dh/dt = Σ Q_k q̇_k.

    The boom's and balloon's drag as the base model's drag families (tethers off, end
    masses added) on its rates; each segment's damper force (its force less the
    spring's tension along it) on the relative velocity of its ends in L, and its
    drag on both end nodes' velocities in L (a boom end's is arm θ̇ (cos θ, −sin θ),
    so F · v is its Q_θ θ̇).  fam: scratch (N_FAMILIES, 3); scratch in p's tail as
    :func:`chain_rhs`.
    """
    literally(kind)
    nq = y.shape[0] // 2
    n = (nq - 3) // 4
    pb = p[_S_PB:_S_PB + NB]
    yb = p[_S_YB:_S_YB + 6]
    _base_inputs(y, p, n, pb, yb)
    _base_family_forces(kind, yb, pb, fam)
    power = 0.0
    for f in _DRAG:
        for k in range(3):
            power += fam[f, k] * yb[3 + k]
    for j in range(2):
        for s in range(n + 1):
            fx, fy, dx, dy, ten, lam = _segment(y, p, n, j, s, kind == _OBJECTIVE)
            x0, y0, u0, v0 = node(y, p, n, j, s)
            x1, y1, u1, v1 = node(y, p, n, j, s + 1)
            if lam > 0.0:  # the damper's share of the far node's force
                fx += ten * (x1 - x0) / lam
                fy += ten * (y1 - y0) / lam
            power += fx * (u1 - u0) + fy * (v1 - v0) + dx * (u0 + u1) + dy * (v0 + v1)
    return power
