"""Steady configuration in the rotating frame and its linear stability.

An equilibrium is a state with zero rates where the generated accelerations
vanish: the balloon's drag trail (δx, δy) and the pitch θ set by the torque
balance of drag, gravity gradient and the two tethers.  Its Jacobian (generated
by derive/) gives the linear modes: frequencies, damping ratios, the slowest
decay time and a predicted settling time to the thesis's ±0.05 rad band.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import root

from tethersim.generated import dispatch

from tethersim.analysis.metrics import SETTLING_TOL, wrap
from tethersim.model.registry import DEFAULT_MODEL, THESIS_VARIANTS, model_index
from tethersim.model.satellite import Satellite, parameter_vector
from tethersim.engine.linearise import attitude_jacobian, rk4_max_step

RESIDUAL_TOL = 1e-10  # largest |acceleration| accepted at an equilibrium [SI]


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
    """

    satellite: Satellite
    model: str
    delta_x: float
    delta_y: float
    theta: float
    taut: tuple  # (tether 1 taut, tether 2 taut)
    residual: float
    eigenvalues: np.ndarray  # 1/s

    @property
    def state(self) -> np.ndarray:
        return np.array([self.delta_x, self.delta_y, self.theta, 0.0, 0.0, 0.0])

    @property
    def stable(self) -> bool:
        return bool(np.all(self.eigenvalues.real < 0))

    def modes(self) -> list:
        """(frequency [rad/s], damping ratio, decay time [s]) of each oscillatory pair."""
        out = []
        for lam in self.eigenvalues:
            if lam.imag > 0:
                w = abs(lam)
                out.append((lam.imag, -lam.real / w, math.inf if lam.real >= 0 else -1 / lam.real))
        return sorted(out)

    def predicted_settling_time(self, amplitude: float) -> float:
        """Time [s] for the slowest mode to decay from ``amplitude`` to ±0.05 rad."""
        rate = -max(self.eigenvalues.real)
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
        Model variant (default ``"derived"``).
    guess : sequence of 3 floats, optional
        Starting (δx [m], δy [m], θ [rad]); default the initial offset and θ = 0.

    Returns
    -------
    Equilibrium
        The configuration, which tethers are taut, and the Jacobian's eigenvalues.

    Raises
    ------
    NoEquilibrium
        If no tether holds the balloon, or the solver finds no state with all
        accelerations below ``RESIDUAL_TOL`` (a RuntimeError and a ValueError).

    Examples
    --------
    >>> import tethersim as ts
    >>> eq = ts.find_equilibrium(ts.load_preset("satI"))
    >>> round(eq.delta_x)
    29
    """
    m = model_index(model, THESIS_VARIANTS, "find_equilibrium")
    if sat.E1 == 0 and sat.E2 == 0:
        # nothing holds the balloon against drag: the root finder would wander off
        raise NoEquilibrium("E1 = E2 = 0 N/mm^2: no tether holds the balloon, so drag carries "
                            "it away and there is no equilibrium; allowed range for an "
                            "equilibrium: E1 > 0 or E2 > 0")
    p = parameter_vector(sat)
    g = np.array(guess if guess is not None else (sat.initial[0], sat.initial[1], 0.0), float)
    d = np.empty(6)
    J = np.empty((6, 6))

    def f(q):
        dispatch.rhs(m, 0.0, np.array([q[0], q[1], q[2], 0.0, 0.0, 0.0]), p, d)
        return d[3:].copy()

    def jac(q):
        dispatch.jacobian(m, 0.0, np.array([q[0], q[1], q[2], 0.0, 0.0, 0.0]), p, J)
        return J[3:, :3].copy()

    sol = root(f, g, jac=jac, method="hybr", options={"xtol": 1e-14})
    q = sol.x
    res = float(np.max(np.abs(f(q))))
    if not sol.success and res > RESIDUAL_TOL:
        why = " ".join(str(sol.message).split())  # scipy's message spans lines
        raise NoEquilibrium(f"no equilibrium found from guess {tuple(float(x) for x in g)}: {why} "
                           f"(residual {res:.3g})")
    th = float(wrap(q[2]))
    lam1 = math.hypot(sat.b * math.sin(th) - q[0], sat.b * math.cos(th) - q[1])
    lam2 = math.hypot(-sat.a * math.sin(th) - q[0], -sat.a * math.cos(th) - q[1])
    ev = np.linalg.eigvals(attitude_jacobian(sat, [q[0], q[1], th, 0, 0, 0], model))
    return Equilibrium(sat, model, float(q[0]), float(q[1]), th,
                       (lam1 > sat.l10, lam2 > sat.l20), res, ev)


def format_equilibrium(eq: Equilibrium) -> str:
    s = eq.satellite
    lines = [f"{s.name}, model {eq.model}: equilibrium in the rotating frame",
             f"  delta_x {eq.delta_x:.6g} m   delta_y {eq.delta_y:.6g} m   "
             f"theta {eq.theta:.6g} rad ({math.degrees(eq.theta):.4g} deg)",
             f"  tether 1 {'taut' if eq.taut[0] else 'slack'}, tether 2 "
             f"{'taut' if eq.taut[1] else 'slack'}; residual {eq.residual:.2g}",
             f"  linearly {'stable' if eq.stable else 'UNSTABLE'}; modes "
             "(frequency [rad/s], period [s], damping ratio, decay time [h]):"]
    for w, zeta, tau in eq.modes():
        lines.append(f"    {w:.5g}  {2 * math.pi / w:10.5g}  {zeta:.3g}  {tau / 3600:.4g}")
    ts_ = eq.predicted_settling_time(s.initial[2] - eq.theta)
    lines.append(f"  predicted settling from theta0 to +-{SETTLING_TOL} rad: "
                 f"{ts_ / 3600:.4g} h ({ts_ / s.period:.4g} orbits)")
    lines.append(f"  largest stable RK4 step here: {rk4_max_step(s, eq.model, eq.state):.4g} s")
    return "\n".join(lines)
