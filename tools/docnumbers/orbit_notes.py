"""Figures of docs/orbit.md's notes for the runtime: SatI's decay from 200 km to 120 km.

The runs are the generated ``free`` kernel with scipy's DOP853 at rtol 1e-12
(free_orbit.py), started as the runtime starts a free orbit
(tethersim.model.inputs.initial_model_state: SatI's δx = 29 m, θ = π/6, at rest in L),
with the air density of each body taken, before every ``rhs`` call, from Vallado's table
(tethersim.model.atmosphere) at that body's altitude: what the runtime's per-body mode
does (tethersim.engine.dynamics), without its domain checks: the runs go on to 120 km
where the runtime stops at tether 1's stretch limit (20 × its rest length).  The closed
form is docs/orbit.md's row 2, da/dt = −ρ (Σ C_D A_i / m) √(μa)(1 − ω_E/n)², with ρ(a)
from the same table.
"""
from __future__ import annotations

import math
from functools import cache
from typing import NamedTuple

import numpy as np
from scipy.integrate import solve_ivp

from tethersim.generated import free
from tethersim.model.atmosphere import TABLE, density_kernel
from tethersim.model.constants import J2_EARTH, MU_EARTH, OMEGA_EARTH, R_EARTH
from tethersim.model.inputs import initial_model_state
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure
from tools.docnumbers.free_orbit import (
    apsides,
    ballistic,
    inertial_com,
    integrate,
    params,
    semi_major_axis,
)

ORBIT = "docs/orbit.md"
REENTRY = R_EARTH + 120e3  # m: the runtime's default reentry_altitude, from the boom COM's r
R200 = R_EARTH + 200e3
PERIOD = 2 * math.pi * math.sqrt(R200**3 / MU_EARTH)  # s, the circular period at 200 km
T_LONG = 6 * 3600.0  # s: past every lifetime here, so a run that never re-enters fails
_RHO = [free.PARAMETERS.index(n) for n in ("rho1", "rho2", "rho3")]
_R = free.STATE.index("r")


def _start(j2_speed: bool) -> np.ndarray:
    """SatI's start in the runtime's own words: circular speed with or without J2's factor.

    ``j2_speed`` False gives the Keplerian ν̇ = √(μ/r³), the circular speed when J2 is off.
    """
    return initial_model_state(load_preset("satI").replace(orbit="free", j2=j2_speed), "free")


def _per_body(y, p) -> list:
    # each body's own altitude |r_i| − R_E, as the runtime's per-body mode
    return [density_kernel(r - R_EARTH, TABLE) for r in free.body_radii(y, p)]


def _at_a(y, p) -> float:
    # one density for all three bodies, at the COM's osculating a: the closed form's air
    return density_kernel(semi_major_axis(free, p, y) - R_EARTH, TABLE)


class _InAir:
    """``free`` with ρ1..ρ3 set from the state before each ``rhs`` call.

    It stands in for the module in :func:`~tools.docnumbers.free_orbit.integrate`
    (which reads ``STATE``, ``MODEL`` and ``rhs``); the kernel takes the densities as
    parameters, constant within one call, as the runtime's loop supplies them.
    """

    STATE, PARAMETERS, MODEL = free.STATE, free.PARAMETERS, free.MODEL

    def __init__(self, densities):
        self.densities = densities

    def rhs(self, t, y, p, dydt):
        pw = p.copy()
        pw[_RHO] = self.densities(y, p)
        free.rhs(t, y, pw, dydt)


def _down(t, y) -> float:
    return y[_R] - REENTRY


_down.terminal, _down.direction = True, -1.0


class Flight(NamedTuple):
    """One run of SatI to 120 km: its duration and dense solution."""

    hours: float  # time for r to fall to R_E + 120 km [h]
    sol: object  # scipy OdeResult with ``sol`` (dense output)
    p: np.ndarray  # parameter vector (densities 0: they are set per call)


@cache
def flight(j2: bool, j2_speed: bool) -> Flight:
    """SatI from 200 km in Vallado's air per body until r = R_E + 120 km.

    Parameters
    ----------
    j2 : bool
        Earth's J2 in the kernel.
    j2_speed : bool
        Start with ν̇² = (μ/r³)(1 + (3/2) J2 (R_E/r)²), circular with J2; False: the
        Keplerian ν̇ = √(μ/r³) (circular without J2, below circular speed with it).

    Returns
    -------
    Flight
        The time to 120 km and the run.
    """
    p = params(free, J2=J2_EARTH if j2 else 0.0)
    sol = integrate(_InAir(_per_body), p, _start(j2_speed), T_LONG, events=_down,
                    dense_output=True)
    if not sol.t_events[0].size:
        raise RuntimeError(f"SatI (J2 {j2}, J2 speed {j2_speed}) still above 120 km at {T_LONG} s")
    return Flight(float(sol.t_events[0][0]) / 3600, sol, p)


@cache
def kepler_start() -> tuple:
    """(e, r_start − r_perigee [m]) of the Keplerian start with J2 on, drag off.

    Below the J2-consistent circular speed the start (ṙ = 0) is the apogee; e is from it
    and the first perigee (ṙ − → +), e = (r_a − r_p)/(r_a + r_p), as for the J2 check.
    Drag off, because drag lowers the first perigee by several km more in half an orbit.
    """
    p = params(free, J2=J2_EARTH)
    y0 = _start(False)
    _, _, y_per, _ = apsides(free, p, y0, 0.75 * PERIOD)
    r_a, r_p = y0[_R], y_per[0][_R]
    return float((r_a - r_p) / (r_a + r_p)), float(r_a - r_p)


def law_rate(a: float) -> float:
    """da/dt [m/s] of the near-circular closed form with ρ(a − R_E) from Vallado's table."""
    n = math.sqrt(MU_EARTH / a**3)
    rho = density_kernel(a - R_EARTH, TABLE)
    return -rho * ballistic() * math.sqrt(MU_EARTH * a) * (1 - OMEGA_EARTH / n) ** 2


@cache
def closed_form():
    """The closed form from the J2-off start's osculating a until a = R_E + 120 km (dense)."""
    a0 = semi_major_axis(free, params(free), _start(False))
    down = lambda t, a: a[0] - REENTRY
    down.terminal = True
    sol = solve_ivp(lambda t, a: [law_rate(a[0])], (0.0, T_LONG), [a0], rtol=1e-12, atol=1e-9,
                    events=down, dense_output=True)
    if not sol.t_events[0].size:
        raise RuntimeError("the closed form stays above 120 km")
    return sol


@cache
def follow_error() -> tuple:
    """(times [s], |a_free − a_law| [m]) every 60 s for 2 h, J2 off.

    The free model with ρ(a) at every body in place of each body's own density: the same
    air as the closed form, so what is left is the mechanics (and the closed form's
    near-circular averaging).  2 h, not to 120 km: at about 2.4 h DOP853 stops this run
    (step size underflow).
    """
    p = params(free)
    t = np.arange(0.0, 7200.0 + 1.0, 60.0)
    sol = integrate(_InAir(_at_a), p, _start(False), t[-1], dense_output=True)
    law = closed_form().sol
    gap = [abs(semi_major_axis(free, p, sol.sol(ti)) - law(ti)[0]) for ti in t]
    return t, np.array(gap)


def _largest_gap(t_end: float) -> float:
    t, gap = follow_error()
    return float(gap[t <= t_end].max())


@cache
def onset_swing() -> tuple:
    """(min, max) of the COM's |R| − a [m] over the first orbit of the J2-off run.

    a is the osculating semi-major axis (vis-viva, point-mass μ: J2 off, so r − a of a
    circle is 0); 2001 samples.
    """
    fl = flight(False, False)
    d = [inertial_com(free, fl.p, y)[0] - semi_major_axis(free, fl.p, y)
         for y in fl.sol.sol(np.linspace(0.0, PERIOD, 2001)).T]
    return float(min(d)), float(max(d))


def _at_2h(name: str) -> float:
    return float(flight(False, False).sol.sol(7200.0)[free.STATE.index(name)])


QUANTITIES = {
    "orbit_note_life_j2": lambda: flight(True, True).hours,
    "orbit_note_life_kepler": lambda: flight(True, False).hours,
    "orbit_note_life_no_j2": lambda: flight(False, False).hours,
    "orbit_note_kepler_e": lambda: kepler_start()[0],
    "orbit_note_kepler_perigee_km": lambda: kepler_start()[1] / 1e3,
    "orbit_note_rate_200": lambda: law_rate(R200),
    "orbit_note_swing_low_km": lambda: onset_swing()[0] / 1e3,
    "orbit_note_swing_high_km": lambda: onset_swing()[1] / 1e3,
    # half the swing over a (≈ R_E + 200 km): the eccentricity of the radial oscillation
    "orbit_note_onset_e": lambda: (onset_swing()[1] - onset_swing()[0]) / 2 / R200,
    "orbit_note_law_life": lambda: closed_form().t_events[0][0] / 3600,
    "orbit_note_follow_half_hour": lambda: _largest_gap(1800.0),
    "orbit_note_follow_2h": lambda: _largest_gap(7200.0),
    "orbit_note_dx_start": lambda: _start(False)[free.STATE.index("delta_x")],
    "orbit_note_dx_2h": lambda: _at_2h("delta_x"),
    "orbit_note_theta_2h": lambda: _at_2h("theta"),
}

_CIRC, _ONSET, _CMP = "* **Circular start with J2.**", "* **Drag onset.**", "* For comparison, the near"
# every figure but the start's δx integrates hours of flight: slow
FIGURES = [Figure(ORBIT, at, key, slow=key != "orbit_note_dx_start") for at, key in (
    (("## Notes for the runtime", "SatI from its start (δx = "), "orbit_note_dx_start"),
    ((_CIRC, "instead gives e = "), "orbit_note_kepler_e"),
    ((_CIRC, "and a perigee "), "orbit_note_kepler_perigee_km"),
    ((_CIRC, "from **"), "orbit_note_life_j2"),
    ((_CIRC, "from **", " h to "), "orbit_note_life_kepler"),
    ((_CIRC, "the lifetime is "), "orbit_note_life_j2"),
    ((_CIRC, "same as with J2 off ("), "orbit_note_life_no_j2"),
    ((_ONSET, "ṙ ≈ da/dt = "), "orbit_note_rate_200"),
    ((_ONSET, "runs from "), "orbit_note_swing_low_km"),
    ((_ONSET, "runs from ", " km to "), "orbit_note_swing_high_km"),
    ((_ONSET, "e ≈ "), "orbit_note_onset_e"),
    ((_CMP, "from the same table gives "), "orbit_note_law_life"),
    ((_CMP, "follows it to within "), "orbit_note_follow_half_hour"),
    ((_CMP, "follows it to within ", " and "), "orbit_note_follow_2h"),
    ((_CMP, "J2 off: δx "), "orbit_note_dx_start"),
    ((_CMP, "J2 off: δx ", " → "), "orbit_note_dx_2h"),
    ((_CMP, "drifts down: θ = "), "orbit_note_theta_2h"))]
