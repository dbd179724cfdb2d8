"""Roll and yaw: what the balloon adds out of the orbit plane (issue 13, docs/roll.md).

At a planar equilibrium (δz = φ = ψ = 0) the 3-D models are symmetric under
z → −z, so their Jacobian (central differences of the generated rhs,
tethersim.engine.jacobian) splits exactly into an in-plane block (δx, δy, θ)
and an out-of-plane block (δz, roll φ, yaw ψ and rates).  The out-of-plane
block's eigenvalues are the roll, yaw and balloon-sideways modes.  Compared
here with:

* the gravity-gradient boom alone (tethers off, E = c = 0: the boom's rows
  then do not depend on the balloon), whose linear roll–yaw motion is the
  classical quartic s⁴ + s²n²(1 + 3k1 + k1k3) + 4n⁴k1k3 = 0,
  k1 = (I_pitch − I_yaw)/I_roll, k3 = (I_pitch − I_roll)/I_yaw;
* a boom carrying the balloon's drag area itself: on the bus (A2 + A3), or
  split between the ends so that the drag still passes through the COM
  (A1' b = A2' a, A1' + A2' = A1 + A2 + A3).

End-body drag damps roll at the rate D / (2 I_roll),
D = ½ C_D ρ V (A1 b² + A2 a²), V = (ω − ω_E) r0 the air speed: a body moving
sideways at v feels ½ C_D ρ A V v against it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from tethersim.analysis.equilibrium import NEUTRAL_TOL, find_equilibrium
from tethersim.engine.jacobian import jacobian
from tethersim.model.constants import OMEGA_EARTH
from tethersim.model.inputs import box_inertias, parameter_vector
from tethersim.model.registry import KERNELS, get_model
from tethersim.model.satellite import Satellite

OUT_OF_PLANE = ("delta_z", "phi", "psi")
IN_PLANE = ("delta_x", "delta_y", "theta")
CASES = ("balloon", "boom alone", "drag area on the bus", "drag area split")


@dataclass(frozen=True)
class Mode:
    """One linear mode: its eigenvalue and the coordinate that dominates it.

    Attributes
    ----------
    name : str
        ``"roll"``, ``"yaw"``, ``"balloon sideways"`` (δz), ``"pitch"``, ...
    eigenvalue : complex
        λ [1/s] (the upper one of a complex pair).
    """

    name: str
    eigenvalue: complex

    @property
    def frequency(self) -> float:
        """Damped angular frequency Im λ [rad/s]."""
        return abs(self.eigenvalue.imag)

    @property
    def decay_time(self) -> float:
        """e-folding time −1/Re λ [s] (inf when neutral or growing)."""
        return -1.0 / self.eigenvalue.real if self.eigenvalue.real < 0 else math.inf

    @property
    def neutral(self) -> bool:
        """|λ| below NEUTRAL_TOL: nothing restores or damps this coordinate."""
        return abs(self.eigenvalue) < NEUTRAL_TOL


def boom_inertias(sat: Satellite) -> dict:
    """Principal moments of the boom about its COM [kg m²]: "roll", "pitch", "yaw"."""
    box = box_inertias(sat)
    pts = sat.pitch_inertia
    return {"roll": pts + box["I1_roll"] + box["I2_roll"],
            "pitch": pts + box["I1_pitch"] + box["I2_pitch"],
            "yaw": box["I1_yaw"] + box["I2_yaw"]}


def roll_yaw_quartic(sat: Satellite) -> tuple:
    """The boom alone: roots s² / n² of s⁴ + s²n²(1 + 3k1 + k1k3) + 4n⁴k1k3 = 0.

    Returns
    -------
    tuple of float
        (s²/n² of roll-like mode, of yaw-like mode); negative values are
        oscillations at n √(−s²/n²), zero is a neutral yaw.
    """
    i = boom_inertias(sat)
    k1 = (i["pitch"] - i["yaw"]) / i["roll"]
    k3 = (i["pitch"] - i["roll"]) / i["yaw"] if i["yaw"] > 0 else 0.0
    bq, cq = 1 + 3 * k1 + k1 * k3, 4 * k1 * k3
    disc = math.sqrt(bq * bq - 4 * cq)
    return ((-bq - disc) / 2, (-bq + disc) / 2)


def roll_drag_rate(sat: Satellite, areas: tuple | None = None) -> float:
    """Roll damping rate of the end bodies' drag, D / (2 I_roll) [1/s].

    ``areas``: (A1, A2) carried by the boom instead of the satellite's own.
    """
    A1, A2 = areas if areas is not None else (sat.A1, sat.A2)
    V = (sat.omega - OMEGA_EARTH) * sat.r0
    D = 0.5 * sat.CD * sat.rho * V * (A1 * sat.b**2 + A2 * sat.a**2)
    return D / (2 * boom_inertias(sat)["roll"])


def _block(J: np.ndarray, names: tuple, keep: tuple) -> np.ndarray:
    n = len(names) // 2
    idx = [names.index(k) for k in keep] + [n + names.index(k) for k in keep]
    return J[np.ix_(idx, idx)]


def _modes(A: np.ndarray, keep: tuple, weights: dict) -> list:
    """Modes of the block A over ``keep`` (+ rates), named by kinetic-energy share."""
    lam, vec = np.linalg.eig(A)
    names = {"delta_z": "balloon sideways", "phi": "roll", "psi": "yaw",
             "delta_x": "balloon along-track", "delta_y": "balloon radial", "theta": "pitch"}
    out = []
    for j, ev in enumerate(lam):
        if ev.imag < 0 or (ev.imag == 0 and ev.real < 0 and abs(ev) >= NEUTRAL_TOL):
            continue
        if abs(ev) < NEUTRAL_TOL:
            if any(m.neutral and m.name == "yaw" for m in out):
                continue
            share = np.array([1.0 if c == "psi" else 0.0 for c in keep])
        else:
            share = np.array([weights[c] * abs(vec[i, j]) ** 2 for i, c in enumerate(keep)])
        out.append(Mode(names[keep[int(np.argmax(share))]], complex(ev)))
    return sorted(out, key=lambda m: (m.neutral, m.frequency))


def _weights(sat: Satellite) -> dict:
    i = boom_inertias(sat)
    return {"delta_z": sat.m3, "delta_x": sat.m3, "delta_y": sat.m3, "phi": i["roll"],
            "theta": i["pitch"], "psi": max(i["yaw"], 1e-30)}


def _boom_pitch_equilibrium(p: np.ndarray, model: str, guess: float) -> np.ndarray:
    """State of the boom alone (tethers off) at its pitch equilibrium near ``guess``."""
    m = get_model(model)
    n = m.n_coordinates

    def state(theta):
        y = np.zeros(2 * n)
        y[m.state.index("delta_x")] = 30.0  # the balloon is anywhere: tethers off
        y[m.state.index("theta")] = theta
        return y

    d = np.empty(2 * n)

    def f(th):
        KERNELS[m.index].rhs(0.0, state(th), p, d)
        return d[n + m.state.index("theta")]

    lo, hi = guess - 0.3, guess + 0.3
    grid = np.linspace(lo, hi, 61)
    vals = [f(t) for t in grid]
    for a, b, fa, fb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:]):
        if fa == 0.0:
            return state(a)
        if fa * fb < 0 and (fb - fa) / (b - a) < 0:  # restoring: θ̈ falls through zero
            return state(brentq(f, a, b, xtol=1e-15, rtol=1e-15))
    raise RuntimeError(f"no stable pitch equilibrium of the boom alone within ±0.3 rad "
                       f"of {guess:g} rad")


def case_parameters(sat: Satellite, case: str, model: str = "3d") -> tuple:
    """(satellite, parameter vector) of one comparison case.

    The box inertias stay those of ``sat``: thesis Eq 4.4 ties a box's inertia
    to its area, and moving the balloon's area onto the boom must not make
    the boom heavier.
    """
    s = case_satellite(sat, case)
    m = get_model(model)
    p = parameter_vector(s, model)
    for k, v in box_inertias(sat).items():
        p[m.parameters.index(k)] = v
    return s, p


def case_satellite(sat: Satellite, case: str) -> Satellite:
    """The satellite of one comparison case (``CASES``)."""
    if case == "balloon":
        return sat
    off = sat.replace(E1=0.0, E2=0.0, c1=0.0, c2=0.0)
    total = sat.A1 + sat.A2 + sat.A3
    if case == "boom alone":
        return off
    if case == "drag area on the bus":
        return off.replace(A2=sat.A2 + sat.A3)
    if case == "drag area split":
        return off.replace(A1=total * sat.a / (sat.a + sat.b),
                           A2=total * sat.b / (sat.a + sat.b))
    raise ValueError(f"case = {case!r}: allowed values {', '.join(CASES)}")


@dataclass(frozen=True)
class RollCase:
    """Linear roll and yaw of one case at its planar equilibrium.

    Attributes
    ----------
    case : str
        One of ``CASES``.
    satellite : Satellite
        The case's satellite.
    theta : float
        Pitch of the planar equilibrium [rad].
    modes : list of Mode
        Out-of-plane modes (roll, yaw, balloon sideways), slow first, neutral last.
    pitch : Mode
        The slowest in-plane (pitch-dominated) mode, for comparison.
    coupling : float
        Largest |entry| coupling the in-plane and out-of-plane blocks (0 by symmetry).
    """

    case: str
    satellite: Satellite
    theta: float
    modes: list
    pitch: Mode
    coupling: float

    def mode(self, name: str) -> Mode:
        """The first mode called ``name``."""
        return next(m for m in self.modes if m.name == name)


def roll_case(sat: Satellite, case: str = "balloon", model: str = "3d") -> RollCase:
    """Out-of-plane linear modes of one case (``CASES``) at its planar equilibrium.

    Parameters
    ----------
    sat : Satellite
        The satellite (the nominal one; the case modifies it).
    case : str, optional
        ``"balloon"`` (as given), ``"boom alone"`` (tethers off),
        ``"drag area on the bus"`` or ``"drag area split"`` (tethers off, the
        balloon's area carried by the boom's end bodies).
    model : str, optional
        A 3-D model.

    Returns
    -------
    RollCase

    Examples
    --------
    >>> import tethersim
    >>> from tethersim.analysis.roll import roll_case
    >>> c = roll_case(tethersim.load_preset("satI"), "boom alone")
    >>> round(c.mode("roll").frequency / c.satellite.omega, 4)  # √(1 + 3 k1)
    1.9886
    """
    s, p = case_parameters(sat, case, model)
    m = get_model(model)
    names = m.state
    if case == "balloon":
        eq = find_equilibrium(s, model)
        y = eq.state
        out_keys, in_keys = OUT_OF_PLANE, IN_PLANE
    else:
        # drag on the bus alone is ~30x the largest gravity-gradient torque: the
        # boom weathervanes, bus in the wake (θ near −90°)
        guess = -math.pi / 2 if case == "drag area on the bus" else 0.0
        y = _boom_pitch_equilibrium(p, model, guess)
        out_keys, in_keys = ("phi", "psi"), ("theta",)
    J = np.empty((m.n_state, m.n_state))
    jacobian(m.index, 0.0, np.ascontiguousarray(y, dtype=float), p, J)
    n = m.n_coordinates
    i_out = [names.index(k) for k in OUT_OF_PLANE] + [n + names.index(k) for k in OUT_OF_PLANE]
    i_in = [names.index(k) for k in IN_PLANE] + [n + names.index(k) for k in IN_PLANE]
    coupling = float(max(np.max(np.abs(J[np.ix_(i_out, i_in)])),
                         np.max(np.abs(J[np.ix_(i_in, i_out)]))))
    w = _weights(sat)
    modes = _modes(_block(J, names, out_keys), out_keys, w)
    pitch = [md for md in _modes(_block(J, names, in_keys), in_keys, w) if md.name == "pitch"]
    return RollCase(case, s, float(y[names.index("theta")]), modes,
                    min(pitch, key=lambda md: md.frequency), coupling)


@dataclass(frozen=True)
class RollResponse:
    """A 3-D run from the planar equilibrium with an out-of-plane start.

    Attributes
    ----------
    result : SimResult
        The run.
    theta_eq : float
        Pitch of the planar equilibrium it started from [rad].
    orbit_peaks : dict
        Per orbit k = 0, 1, ...: the largest |φ| [rad], |θ − θ_eq| [rad] and
        |δz| [m] in that orbit, arrays under "phi", "theta", "delta_z".
    roll_decay_rate : float
        Fitted e-folding rate of the per-orbit roll peaks [1/s] (least squares
        on their logarithm, the first orbit left out).
    """

    result: object
    theta_eq: float
    orbit_peaks: dict
    roll_decay_rate: float


def roll_response(sat: Satellite, model: str = "3d", phi0_deg: float = 5.0,
                  psi0_deg: float = 5.0, delta_z0: float = 1.0,
                  periods: float = 40.0) -> RollResponse:
    """Simulate the planar equilibrium disturbed out of the plane; measure roll decay.

    Parameters
    ----------
    sat : Satellite
        The satellite (its own initial state is replaced by the equilibrium).
    model : str, optional
        A 3-D model.
    phi0_deg, psi0_deg : float, optional
        Initial roll and yaw [deg].
    delta_z0 : float, optional
        Initial out-of-plane balloon offset [m].
    periods : float, optional
        Length of the run [orbits].

    Returns
    -------
    RollResponse

    Examples
    --------
    >>> import tethersim
    >>> from tethersim.analysis.roll import roll_response
    >>> r = roll_response(tethersim.load_preset("satI"), periods=4)
    >>> round(float(r.orbit_peaks["phi"][0]), 5)  # 5 deg
    0.08727
    """
    from tethersim.engine.simulate import simulate

    eq = find_equilibrium(sat, model)
    s = sat.replace(initial=(eq.delta_x, eq.delta_y, eq.theta, 0.0, 0.0, 0.0),
                    initial_3d={"phi": math.radians(phi0_deg), "psi": math.radians(psi0_deg),
                                "delta_z": delta_z0})
    res = simulate(s, periods=periods, model=model, progress=False)
    k = np.minimum((res.t / s.period).astype(int), int(math.ceil(periods)) - 1)
    series = {"phi": np.abs(res.series("phi")), "theta": np.abs(res.series("theta") - eq.theta),
              "delta_z": np.abs(res.series("delta_z"))}
    peaks = {name: np.array([v[k == j].max() for j in range(int(math.ceil(periods)))
                             if np.any(k == j)]) for name, v in series.items()}
    t_mid = (np.arange(len(peaks["phi"])) + 0.5) * s.period
    fit = np.polyfit(t_mid[1:], np.log(peaks["phi"][1:]), 1) if len(t_mid) > 2 else [0.0]
    return RollResponse(res, eq.theta, peaks, float(-fit[0]))
