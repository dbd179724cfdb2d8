"""Steady configuration in the rotating frame and its linear stability.

An equilibrium is a state with zero rates where the generated accelerations
vanish: the balloon's drag trail (δx, δy) and the pitch θ set by the torque
balance of drag, gravity gradient and the two tethers.  Its Jacobian (generated
by derive/) gives the linear modes: frequencies, damping ratios, the slowest
decay time and a predicted settling time to the thesis's ±0.05 rad band.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import root

from tethersim.analysis.metrics import SETTLING_TOL, wrap
from tethersim.engine.bodies import bodies_from_states
from tethersim.engine.domain import state_violation
from tethersim.engine.linearise import attitude_jacobian, rk4_max_step
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import DEFAULT_MODEL, KERNELS, MODELS, get_model
from tethersim.model.satellite import Satellite

RESIDUAL_TOL = 1e-10  # largest |acceleration| accepted at an equilibrium [SI]
NEUTRAL_TOL = 1e-10  # |λ| [1/s] below which a mode is neutral (a cyclic coordinate)
# circular-orbit models, planar and 3-D (a free orbit's anomaly has no equilibrium)
CIRCULAR = tuple(m.name for m in MODELS if m.orbit == "circular")


class NoEquilibrium(RuntimeError, ValueError):
    """No equilibrium exists or none was found; a one-line message (a ValueError for the CLI)."""


@dataclass(frozen=True)
class Equilibrium:
    """A steady configuration in the rotating frame and its linearisation.

    Attributes
    ----------
    satellite : Satellite
        The satellite solved for.
    model : str
        Model variant (``tethersim.MODELS``).
    delta_x, delta_y : float
        Balloon offset from the COM [m] (+x: the wake, +y: up).
    theta : float
        Pitch [rad], wrapped to (−π, π].
    taut : tuple of bool
        Whether tethers 1 and 2 are taut there.
    residual : float
        Largest |q̈| left at the solution [m/s², rad/s²].
    eigenvalues : numpy.ndarray
        Eigenvalues of the generated Jacobian there [1/s].
    coordinates : dict
        Every coordinate of the model by name (3-D: also δz [m], roll φ and
        yaw ψ [rad]), rates zero.
    outside_domain : str
        Why the equilibrium lies outside the model's domain (a tether stretched
        beyond ``MAX_STRETCH`` x its rest length, the balloon beyond
        ``BALLOON_REACH``: tethersim.engine.domain), or "" inside it.  A run
        there would stop as ``left-domain``: such an equilibrium is a root of the
        equations, not a configuration the model describes.
    """

    satellite: Satellite
    model: str
    delta_x: float
    delta_y: float
    theta: float
    taut: tuple  # (tether 1 taut, tether 2 taut)
    residual: float
    eigenvalues: np.ndarray  # 1/s
    coordinates: dict = field(default_factory=dict, compare=False)
    outside_domain: str = ""

    @property
    def in_domain(self) -> bool:
        """Whether the equilibrium lies inside the model's domain (engine/domain.py)."""
        return not self.outside_domain

    @property
    def state(self) -> np.ndarray:
        """The model's state there (its STATE order, rates zero)."""
        if not self.coordinates:
            return np.array([self.delta_x, self.delta_y, self.theta, 0.0, 0.0, 0.0])
        q = list(self.coordinates.values())
        return np.array(q + [0.0] * len(q))

    @property
    def neutral(self) -> int:
        """Number of eigenvalues with |λ| < NEUTRAL_TOL: a coordinate nothing restores.

        In the 3-D models with the thesis's boxes (the same moment about every
        axis) the boom is symmetric about its own axis and no force acts about it,
        so the yaw ψ and its rate give two zero eigenvalues (docs/roll.md).
        """
        return int(np.sum(np.abs(self.eigenvalues) < NEUTRAL_TOL))

    @property
    def stable(self) -> bool:
        """Every mode that is not neutral decays (Re λ < 0)."""
        ev = self.eigenvalues[np.abs(self.eigenvalues) >= NEUTRAL_TOL]
        return bool(np.all(ev.real < 0))

    def modes(self) -> list:
        """(frequency [rad/s], damping ratio, decay time [s]) of each oscillatory pair.

        A real eigenvalue is no pair: :meth:`real_modes` lists those.
        """
        out = []
        for lam in self.eigenvalues:
            if lam.imag > 0 and abs(lam) >= NEUTRAL_TOL:
                w = abs(lam)
                out.append((lam.imag, -lam.real / w, math.inf if lam.real >= 0 else -1 / lam.real))
        return sorted(out)

    def real_modes(self) -> list:
        """(rate λ [1/s], e-folding time 1/|λ| [s]) of each real, non-neutral eigenvalue,
        fastest growing first: λ > 0 grows (a divergence: what makes a saddle
        unstable without any oscillation), λ < 0 decays without oscillating."""
        lams = [float(lam.real) for lam in self.eigenvalues
                if lam.imag == 0 and abs(lam) >= NEUTRAL_TOL]
        return [(lam, 1 / abs(lam)) for lam in sorted(lams, reverse=True)]

    def predicted_settling_time(self, amplitude: float) -> float:
        """Time [s] for the slowest mode to decay from ``amplitude`` to ±0.05 rad."""
        rate = -max(self.eigenvalues[np.abs(self.eigenvalues) >= NEUTRAL_TOL].real)
        if rate <= 0:
            return math.inf
        return max(0.0, math.log(abs(amplitude) / SETTLING_TOL) / rate)


def find_equilibrium(sat: Satellite, model: str = DEFAULT_MODEL, guess=None) -> Equilibrium:
    """Find the equilibrium q̈(δx, δy, θ, 0, 0, 0) = 0 nearest a guess, with its modes.

    Parameters
    ----------
    sat : Satellite
        The satellite.
    model : str, optional
        Model variant (default ``"derived"``): any circular-orbit model, planar
        or 3-D (``CIRCULAR``).
    guess : sequence of floats, optional
        Starting (δx [m], δy [m], θ [rad]) (the other coordinates of a 3-D
        model from zero), or every coordinate of the model in its order;
        default the initial offset and θ = 0.

    Returns
    -------
    Equilibrium
        The configuration, which tethers are taut, and the Jacobian's eigenvalues.

    Raises
    ------
    NoEquilibrium
        If no tether holds the balloon, or the solver finds no state with all
        accelerations below ``RESIDUAL_TOL`` (a RuntimeError and a ValueError).
    ValueError
        A satellite on a free orbit (one line): the equilibrium is that of the
        orbit held circular at ``altitude``; a free orbit decays and has none.

    Examples
    --------
    >>> import tethersim as ts
    >>> eq = ts.find_equilibrium(ts.load_preset("satI"))
    >>> round(eq.delta_x)
    29
    >>> eq3 = ts.find_equilibrium(ts.load_preset("satI"), "3d")  # roll, yaw, δz too
    >>> eq3.coordinates["phi"], eq3.neutral, eq3.stable  # yaw about the boom: neutral
    (0.0, 2, True)
    """
    if not isinstance(sat, Satellite):
        raise TypeError(f"sat must be a tethersim Satellite (load_preset/load), got "
                        f"{type(sat).__name__}")
    mdl = get_model(model, CIRCULAR, "find_equilibrium")
    if sat.orbit != "circular":
        # the free orbit's r, ν never stand still: the circular answer would be a
        # silent stand-in for an equilibrium that does not exist
        raise ValueError(f"orbit = {sat.orbit!r}: the equilibrium is that of the orbit held "
                         f"circular at altitude {sat.altitude / 1e3:g} km (a free orbit decays "
                         f"and has none); use orbit = 'circular' (drop --set orbit=free)")
    m, n = mdl.index, mdl.n_coordinates
    names = mdl.state[:n]
    if sat.E1 == 0 and sat.E2 == 0:
        # nothing holds the balloon against drag: the root finder would wander off
        raise NoEquilibrium("E1 = E2 = 0 N/mm^2: no tether holds the balloon, so drag carries "
                            "it away and there is no equilibrium; allowed range for an "
                            "equilibrium: E1 > 0 or E2 > 0")
    p = parameter_vector(sat, model)
    guess = _checked_guess(guess, n)
    if guess is not None and len(guess) == n:
        g = np.array(guess, float)
    else:
        start = dict(zip(("delta_x", "delta_y", "theta"),
                         guess if guess is not None else (sat.initial[0], sat.initial[1], 0.0)))
        g = np.array([float(start.get(k, 0.0)) for k in names])
    d = np.empty(2 * n)
    J = np.empty((2 * n, 2 * n))

    def f(q):
        KERNELS[m].rhs(0.0, np.concatenate([q, np.zeros(n)]), p, d)
        return d[n:].copy()

    def jac(q):
        KERNELS[m].jacobian(0.0, np.concatenate([q, np.zeros(n)]), p, J)
        return J[n:, :n].copy()

    sol = root(f, g, jac=jac, method="hybr", options={"xtol": 1e-14})
    if n > 3 and float(np.max(np.abs(f(sol.x)))) > RESIDUAL_TOL:
        # a neutral coordinate (yaw of a boom symmetric about its axis) makes the
        # Jacobian singular: Levenberg-Marquardt still converges
        sol = root(f, g, jac=jac, method="lm", options={"xtol": 1e-15, "ftol": 1e-15})
    q = sol.x
    res = float(np.max(np.abs(f(q))))
    if not sol.success and res > RESIDUAL_TOL:
        why = " ".join(str(sol.message).split())  # scipy's message spans lines
        if sat.CD == 0:  # the trailing equilibrium is drag against the tethers' pull
            why = ("CD = 0: without drag nothing holds the balloon trailing in the wake, so "
                   "there is no trailing equilibrium to find (" + why + ")")
        raise NoEquilibrium(f"no equilibrium found from guess {tuple(float(x) for x in g)}: {why} "
                           f"(residual {res:.3g})")
    i_th = names.index("theta")
    q[i_th] = float(wrap(q[i_th]))
    if "psi" in names:
        q[names.index("psi")] = float(wrap(q[names.index("psi")]))
    coords = {k: float(v) for k, v in zip(names, q)}
    y = np.concatenate([q, np.zeros(n)])
    off = bodies_from_states(sat, model, 0.0, y).offset
    lam1, lam2 = np.linalg.norm(off[0] - off[2]), np.linalg.norm(off[1] - off[2])
    ev = np.linalg.eigvals(attitude_jacobian(sat, y, model))
    return Equilibrium(sat, model, coords["delta_x"], coords["delta_y"], coords["theta"],
                       (bool(lam1 > sat.l10), bool(lam2 > sat.l20)), res, ev,
                       coords if n > 3 else {}, state_violation(sat, model, y))


def _checked_guess(guess, n: int):
    """``guess`` as a tuple of 3 (δx, δy, θ) or ``n`` (every coordinate) finite floats."""
    if guess is None:
        return None
    sizes = "3 (delta_x, delta_y, theta)" + (f" or {n} (every coordinate)" if n != 3 else "")
    try:
        g = np.asarray(guess, dtype=float)
    except (TypeError, ValueError):
        g = None
    if g is None or g.ndim != 1 or g.size not in (3, n) or not np.all(np.isfinite(g)):
        raise ValueError(f"guess = {guess!r:.60}: must be {sizes} finite numbers")
    return tuple(float(x) for x in g)


def format_equilibrium(eq: Equilibrium) -> str:
    s = eq.satellite
    lines = [f"{s.name}, model {eq.model}: equilibrium in the rotating frame"]
    if eq.outside_domain:
        lines.append(f"  OUTSIDE THE MODEL'S DOMAIN: {eq.outside_domain}; a run there stops "
                     f"as left-domain, so this is a root of the equations, not a "
                     f"configuration the model describes (docs/limits.md)")
    lines += [
             f"  delta_x {eq.delta_x:.6g} m   delta_y {eq.delta_y:.6g} m   "
             f"theta {eq.theta:.6g} rad ({math.degrees(eq.theta):.4g} deg)"
             + "".join(f"   {k} {v:.6g}" for k, v in eq.coordinates.items()
                       if k in ("delta_z", "phi", "psi")),
             f"  tether 1 {'taut' if eq.taut[0] else 'slack'}, tether 2 "
             f"{'taut' if eq.taut[1] else 'slack'}; residual {eq.residual:.2g}",
             f"  linearly {'stable' if eq.stable else 'UNSTABLE'}"
             + (f" ({eq.neutral} neutral eigenvalues: yaw about the boom)" if eq.neutral else "")
             + "; oscillatory modes "
             "(frequency [rad/s], period [s], damping ratio, decay time [h]):"]
    for w, zeta, tau in eq.modes():
        lines.append(f"    {w:.5g}  {2 * math.pi / w:10.5g}  {zeta:.3g}  {tau / 3600:.4g}")
    real = eq.real_modes()
    if real:
        lines.append("  real modes, no oscillation (rate [1/s], e-folding time [h]):")
        for lam, tau in real:
            lines.append(f"    {lam:+.5g}  {tau / 3600:.4g}  {'GROWS' if lam > 0 else 'decays'}")
    ts_ = eq.predicted_settling_time(s.initial[2] - eq.theta)
    lines.append(f"  predicted settling from theta0 to +-{SETTLING_TOL} rad: "
                 f"{ts_ / 3600:.4g} h ({ts_ / s.period:.4g} orbits)")
    lines.append(f"  largest stable RK4 step here: {rk4_max_step(s, eq.model, eq.state):.4g} s")
    return "\n".join(lines)
