"""The steady configuration of a circular-orbit model: the root of its accelerations at rest.

:func:`steady_coordinates` solves q̈(q, q̇ = 0) = 0 with the model's generated
kernels (rhs and Jacobian).  It is the solver behind
:func:`tethersim.find_equilibrium` (which adds the modes) and behind a run's
equilibrium start (engine/start.py).

Soft tethers (the thesis's rubber bands) are solved as always: Powell's hybrid
method from the guess.  A stiff line (a real fibre, EA ~ 1e4-1e5 N) makes that
fail: its spring is ~1e10 times stiffer than the gravity-gradient and drag
torques that fix the pitch, and the Newton steps wander between the line's
narrow valley and the pitch's flat one.  For real lines (EA >= 100 N,
tethersim.model.materials.real_tethers) a fallback separates the two scales:

* for a fixed pitch θ, the balloon's own balance (its two equations: tethers,
  drag, tidal force) is solved for (δx, δy), from the previous θ's answer and
  from the geometric candidates (the apex of the bridle triangle on the wake
  side, each line straight downstream of its attachment);
* the pitch's residual r(θ) = θ̈ at that balloon position is scanned over a
  full turn, its sign changes bracketed and refined (Brent), and the root that
  is statically stable (r falls through zero) nearest the guess's θ chosen;
* Powell's method then polishes all coordinates from there.

Convergence is judged on a residual scaled to the tethers' stiffness
(:func:`residual_tolerance`): a line with k = EA / l0 ~ 1e4 N/m computes its
force to ~eps x k x λ, far above an absolute 1e-10 m/s².
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root

from tethersim.engine.jacobian import jacobian
from tethersim.model.inputs import parameter_vector
from tethersim.model.materials import real_tethers
from tethersim.model.registry import MODELS, get_model, kernels_of
from tethersim.model.satellite import Satellite

RESIDUAL_TOL = 1e-10  # largest |acceleration| accepted at an equilibrium [SI], soft lines
# accepted residual per unit of the stiffest line's scale k λ / m3 (residual_tolerance):
# ~1e4 eps, a force known to 2e-12 of what the line would pull stretched by its length
ROUNDING_FACTOR = 1e4 * np.finfo(float).eps
SCAN_POINTS = 144  # pitch samples of the stiff fallback's scan over a full turn (2.5 deg)
CIRCULAR = tuple(m.name for m in MODELS if m.orbit == "circular")


class NoEquilibrium(RuntimeError, ValueError):
    """No equilibrium exists or none was found; a one-line message (a ValueError for the CLI)."""


def residual_tolerance(sat: Satellite) -> float:
    """Largest |q̈| [SI] accepted at an equilibrium of ``sat``.

    ``RESIDUAL_TOL``, or the rounding level of the stiffest tether's force if that
    is larger: ``ROUNDING_FACTOR`` x (E_j / l_j0) x (l_j0 + boom reach) / m3.
    """
    reach = sat.a + sat.b
    scale = max(e / l0 * (l0 + reach) for e, l0 in ((sat.E1, sat.l10), (sat.E2, sat.l20)))
    return max(RESIDUAL_TOL, ROUNDING_FACTOR * scale / sat.m3)


def steady_coordinates(sat: Satellite, model: str, guess) -> tuple:
    """Coordinates q with q̈(q, 0) = 0 nearest ``guess``, and the residual.

    Parameters
    ----------
    sat : Satellite
        The satellite (circular orbit; the caller checks).
    model : str
        A circular-orbit model name (``CIRCULAR``).
    guess : numpy.ndarray
        Every coordinate of the model, in its order.

    Returns
    -------
    (numpy.ndarray, float)
        The coordinates (angles not wrapped) and max |q̈| there.

    Raises
    ------
    NoEquilibrium
        Neither Powell's method from the guess nor the stiff fallback
        (module docstring) reaches :func:`residual_tolerance`.
    """
    mdl = get_model(model)
    m, n = mdl.index, mdl.n_coordinates
    p = parameter_vector(sat, model)
    d = np.empty(2 * n)
    J = np.empty((2 * n, 2 * n))
    zeros = np.zeros(n)

    def f(q):
        kernels_of(m).rhs(0.0, np.concatenate([q, zeros]), p, d)
        return d[n:].copy()

    def jac(q):
        jacobian(m, 0.0, np.concatenate([q, zeros]), p, J)
        return J[n:, :n].copy()

    tol = residual_tolerance(sat)
    g = np.array(guess, float)
    q, res, why = _powell(f, jac, g, n)
    names = mdl.state[:n]
    planar = [names.index(k) for k in ("delta_x", "delta_y", "theta")]
    ith = planar[2]
    # the fallback is for real lines only: the thesis's tethers keep the answers (and the
    # refusals) they always had.  Powell's steps may leap to a root half a turn away (a
    # stiff line's valley throws them): such a root is kept only when the scan finds none
    # nearer the guess's pitch
    real = bool(real_tethers(sat))
    if res <= tol and (not real or _turn(q[ith] - g[ith]) <= math.pi / 2):
        return q, res
    start = None
    if real:
        p_free = parameter_vector(sat.replace(E1=0.0, E2=0.0, c1=0.0, c2=0.0), model)

        def pull(q):
            """q̈ without the tethers: the balloon's own tidal and drag acceleration."""
            kernels_of(m).rhs(0.0, np.concatenate([q, zeros]), p_free, d)
            return d[n:].copy()
        start = _stiff_start(sat, f, jac, g, planar, pull)
    if start is not None:
        q2, res2, why2 = _powell(f, jac, start, n)
        if res2 <= tol and (res > tol or _turn(q2[ith] - g[ith]) < _turn(q[ith] - g[ith])):
            return q2, res2
        if res2 < res:
            q, res, why = q2, res2, why2
    if res <= tol:
        return q, res
    if sat.CD == 0:  # the trailing equilibrium is drag against the tethers' pull
        why = ("CD = 0: without drag nothing holds the balloon trailing in the wake, so "
               "there is no trailing equilibrium to find (" + why + ")")
    raise NoEquilibrium(f"no equilibrium found from guess {tuple(float(x) for x in g)}: {why} "
                        f"(residual {res:.3g})")


def _turn(angle: float) -> float:
    """|angle| wrapped to [0, π]."""
    return abs(math.remainder(angle, 2 * math.pi))


def _powell(f, jac, g, n: int) -> tuple:
    """(q, max |f(q)|, solver message) of Powell's hybrid method from ``g``."""
    sol = root(f, g, jac=jac, method="hybr", options={"xtol": 1e-14})
    if n > 3 and float(np.max(np.abs(f(sol.x)))) > RESIDUAL_TOL:
        # a neutral coordinate (yaw of a boom symmetric about its axis) makes the
        # Jacobian singular: Levenberg-Marquardt still converges
        sol = root(f, g, jac=jac, method="lm", options={"xtol": 1e-15, "ftol": 1e-15})
    return sol.x, float(np.max(np.abs(f(sol.x)))), " ".join(str(sol.message).split())


def _stiff_start(sat, f, jac, g, planar, pull) -> np.ndarray | None:
    """The fallback's starting point (module docstring): the balloon balanced at each
    pitch, the stable pitch root nearest the guess; None if the scan finds no root."""
    ix, iy, ith = planar
    q = np.array(g, float)
    tol = residual_tolerance(sat)
    balloon = [ix, iy]

    def balanced(theta, near):
        """q at pitch theta with the balloon's two equations solved (or None)."""
        best = None
        qq = q.copy()
        qq[ith] = theta
        hung = _hung(sat, theta, lambda xy: pull(_at(qq, balloon, xy))[balloon])
        for cand in [hung, near] + _candidates(sat, theta):
            if cand is None:
                continue
            qq = q.copy()
            qq[ith] = theta

            def fb(xy, qq=qq):
                qq[balloon] = xy
                return f(qq)[balloon]

            def jb(xy, qq=qq):
                qq[balloon] = xy
                return jac(qq)[np.ix_(balloon, balloon)]
            # finite differences first: the analytic Jacobian's kink where a line
            # goes slack sends hybr astray more often; then the Jacobian
            for jj, how in ((None, "hybr"), (jb, "hybr"), (jb, "lm")):
                sol = root(fb, np.asarray(cand, float), jac=jj, method=how,
                           options={"xtol": 1e-14} if how == "hybr" else
                           {"xtol": 1e-15, "ftol": 1e-15})
                r = float(np.max(np.abs(fb(sol.x))))
                if best is None or r < best[1]:
                    best = (sol.x.copy(), r)
                if r <= tol:
                    break
            if best[1] <= tol:
                break
        if best is None or best[1] > tol:
            return None
        qq = q.copy()
        qq[ith], qq[balloon] = theta, best[0]
        return qq

    th0 = g[ith]
    grid = th0 + np.linspace(-math.pi, math.pi, SCAN_POINTS + 1)
    states, resid, near = [], [], None
    for th in grid:
        qq = balanced(th, near)
        states.append(qq)
        resid.append(np.nan if qq is None else f(qq)[ith])
        near = near if qq is None else qq[balloon]  # a failed pitch keeps the last balance
    roots = []
    ok = [k for k in range(SCAN_POINTS + 1) if np.isfinite(resid[k])]
    for k, k1 in zip(ok, ok[1:]):  # brackets across a pitch whose balance failed too
        r0, r1 = resid[k], resid[k1]
        if np.sign(r0) == np.sign(r1):
            continue
        cache = {}

        def torque(th, k=k, cache=cache):
            qq = balanced(th, states[k][balloon])
            if qq is None:
                raise _Unbalanced
            cache[th] = qq
            return f(qq)[ith]
        try:
            th = brentq(torque, grid[k], grid[k1], xtol=1e-14, rtol=4 * np.finfo(float).eps)
        except _Unbalanced:
            continue
        stable = r0 > 0 > r1  # the torque restores: θ̈ falls through zero as θ grows
        roots.append((not stable, abs(th - th0), cache.get(th, balanced(th, None))))
    roots = [r for r in roots if r[2] is not None]
    return min(roots, key=lambda r: r[:2])[2] if roots else None


def _at(q, idx, values):
    q = q.copy()
    q[idx] = values
    return q


def _hung(sat, theta: float, pull, iterations: int = 30):
    """The balloon at rest on stiff lines at pitch θ, by geometry (a first guess of its
    balance that Powell's steps need not find across the lines' taut/slack kink).

    A line's stretch under the balloon's load is ~1e-7 of its length, so the balloon
    sits where the lines reach, stretched by their tensions: at the apex of the bridle
    triangle when the load ``pull`` (its acceleration without the tethers, at the
    balloon's position) lies between the two lines (both tensions T_j ≥ 0 in
    m3 a + T1 u1 + T2 u2 = 0, u_j towards line j's end), else hanging straight along the
    load from the one taut line's end (a line of EA 0 is none: a single line hangs
    the balloon from its point on the boom).  The tensions stretch the lengths to
    l_j0 (1 + T_j / E_j) and the position is iterated with the load at it.  None where
    the geometry has no answer (the lines cannot meet, or no load).
    """
    ends = _ends(sat, theta)
    rest, ea = (sat.l10, sat.l20), (sat.E1, sat.E2)
    live = [j for j in (0, 1) if ea[j] > 0]  # a line of EA 0 holds nothing
    x = _apex(ends, rest) if len(live) == 2 else None
    if x is None and len(live) == 1:  # one line: from straight downstream of its point
        x = ends[live[0]] + np.array([rest[live[0]], 0.0])
    if x is None:
        return None
    for _ in range(iterations):
        a = np.asarray(pull(x), float)
        load = sat.m3 * float(np.hypot(*a))
        if not load > 0:
            return None
        t = np.array([-1.0, -1.0])
        if len(live) == 2:
            u = [(e - x) / np.hypot(*(e - x)) for e in ends]
            try:
                t = np.linalg.solve(np.column_stack(u), -sat.m3 * a)
            except np.linalg.LinAlgError:
                pass
        if t[0] >= 0 and t[1] >= 0:
            lengths = [l0 * (1 + tj / e) for l0, tj, e in zip(rest, t, ea)]
            new = _apex(ends, lengths)
        else:  # one line holds the balloon: the one the load leans on
            j = (0 if t[0] > t[1] else 1) if len(live) == 2 else live[0]
            new = ends[j] + rest[j] * (1 + load / ea[j]) * a / np.hypot(*a)
        if new is None:
            return None
        if np.max(np.abs(new - x)) <= 1e-13 * max(rest):
            return new
        x = new
    return x


def _ends(sat, theta: float) -> tuple:
    """The tethers' attachment points at pitch θ: s1, s2 along the boom (the thesis's
    tip-mass +b and bus −a; tethersim.model.bead_layout.attachment_points)."""
    from tethersim.model.bead_layout import attachment_points
    s, c = math.sin(theta), math.cos(theta)
    return tuple(np.array([arm * s, arm * c]) for arm in attachment_points(sat))


def _apex(ends, lengths):
    """The wake-side (+x) point at distances ``lengths`` from ``ends``, or None."""
    p1, p2 = ends
    base = p2 - p1
    d = float(np.hypot(*base))
    l1, l2 = lengths
    if not (d > 0 and abs(l1 - l2) < d < l1 + l2):
        return None
    along = (l1 ** 2 - l2 ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(max(l1 ** 2 - along ** 2, 0.0))
    u = base / d
    normal = np.array([u[1], -u[0]])
    if normal[0] < 0:
        normal = -normal  # the wake side
    return p1 + along * u + h * normal


class _Unbalanced(Exception):
    """The balloon's balance has no solution at a pitch of the bracket."""


def _candidates(sat, theta: float) -> list:
    """Guesses of the balloon's (δx, δy) at pitch θ: the bridle triangle's apex on the
    wake side (+x) and each line straight downstream of its attachment point."""
    p1, p2 = _ends(sat, theta)
    out = [p1 + [sat.l10, 0.0], p2 + [sat.l20, 0.0]]
    apex = _apex((p1, p2), (sat.l10, sat.l20))
    if apex is not None:
        out.insert(0, apex)
    return out
