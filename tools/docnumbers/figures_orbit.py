"""Figures of docs/orbit.md: the free-orbit kernels against closed forms (issue 12, part 6).

Each function runs the generated ``rhs`` of the module it is given with scipy's DOP853
at rtol 1e-12 (free_orbit.py) and returns what tests/derive/test_orbit_physics.py and
tests/derive/test_free3d_kernels.py bound; the doc prints the values for ``free`` (and
``3d-free``), so the doc's figures and the tests' bounds come from the same runs.
Closed forms are from docs/sources.md.
"""
from __future__ import annotations

import math
from functools import cache
from typing import NamedTuple

import numpy as np
from scipy.integrate import solve_ivp

from tethersim.generated import free, free_exact_gravity, free_objective_damper, three_d_free
from tethersim.model.constants import J2_EARTH, MU_EARTH, OMEGA_EARTH, R_EARTH
from tools.docnumbers.check import Figure
from tools.docnumbers.free_orbit import (
    apsides,
    ballistic,
    dumbbell,
    integrate,
    params,
    semi_major_axis,
    state,
    work,
)

ORBIT = "docs/orbit.md"
MODULES = (free, free_exact_gravity, free_objective_damper)
R200 = R_EARTH + 200e3
RHO = 2.8e-10  # kg/m³, the constant air of the decay and energy checks (about 200 km)


def _frozen(a) -> np.ndarray:
    a = np.asarray(a, dtype=np.float64)
    a.setflags(write=False)  # a cached result: nobody edits it
    return a


class Decay(NamedTuple):
    """Δa [m] in 3000 s of the run and of the decay law with and without co-rotating air."""

    run: float
    law: float
    still_air: float


@cache
def decay(module, **start) -> Decay:
    """SatI at 200 km on a circular start (ṙ = 0, ν̇ = √(μ/r³)), ρ = 2.8e-10 at every
    body, the balloon 29 m behind (``start`` adds or overrides state values by name).

    The law is da/dt = −ρ (Σ C_D A_i / m) √(μ a) (1 − ω_E/n)² (Vallado ch. 8 for still
    air; the factor for air co-rotating with an equatorial prograde orbit from
    docs/sources.md), integrated from the run's a(0), the COM's osculating a.
    """
    p = params(module, rho1=RHO, rho2=RHO, rho3=RHO)
    y0 = state(module, **dict(dict(delta_x=29.0, r=R200, nu_dot=math.sqrt(MU_EARTH / R200**3)),
                              **start))
    t_end = 3000.0
    sol = integrate(module, p, y0, t_end, dense_output=True)
    a0, a1 = (semi_major_axis(module, p, sol.sol(t)) for t in (0.0, t_end))
    k = ballistic()

    def law(corotating):
        def dadt(t, a):
            n = math.sqrt(MU_EARTH / a[0] ** 3)
            return [-RHO * k * math.sqrt(MU_EARTH * a[0])
                    * ((1 - OMEGA_EARTH / n) ** 2 if corotating else 1.0)]
        return solve_ivp(dadt, (0.0, t_end), [a0], rtol=1e-12, atol=1e-9).y[0, -1] - a0

    return Decay(float(a1 - a0), float(law(True)), float(law(False)))


J2_PERIGEE, J2_E0 = R_EARTH + 300e3, 0.02


def _j2_start(module) -> np.ndarray:
    """Perigee at 300 km, ν̇ of a Keplerian e = 0.02 (J2 then makes e ≈ 0.0185)."""
    return state(module, r=J2_PERIGEE, nu_dot=math.sqrt(MU_EARTH * (1 + J2_E0) / J2_PERIGEE**3))


def _circular_period(r) -> float:
    return 2 * math.pi * math.sqrt(r**3 / MU_EARTH)


class J2Rates(NamedTuple):
    """The measured rates of an equatorial J2 orbit against Vallado Eqs 9-41."""

    e: float  # from the first perigee and apogee radii
    a_mean: float  # time average of the osculating a over the first radial period [m]
    apsidal_error: np.ndarray  # per radial period: measured/(3/2 n ε) − 1
    mean_motion_error: np.ndarray  # per radial period: J2 part measured/predicted − 1
    apsidal_theory: float  # (3/2) n ε [rad/s]
    radial_period: float  # the first [s]


@cache
def j2_rates(module) -> J2Rates:
    """Equatorial orbit, dumbbell, drag off: the line of apsides turns at ω̇ + Ω̇ =
    (3/4) n J2 (R_E/p)² (4 − 5 sin² i) − (3/2) n J2 (R_E/p)² cos i = (3/2) n J2 (R_E/p)²
    at i = 0 (in the equatorial plane the perigee is measured from the moving node, so
    the inertial apsidal line turns at the sum), and the anomalistic mean motion is
    n [1 + (3/4) J2 (R_E/p)² √(1 − e²)(2 − 3 sin² i)] (Vallado Eqs 9-41), with
    n = √(μ/ā³) of the mean a = the time average of the osculating a over a radial
    period (Kozai's short-period term in a averages to zero).  3.2 orbits.
    """
    p = params(module, **dumbbell(J2=J2_EARTH))
    nu = module.STATE.index("nu")
    r = module.STATE.index("r")
    sol, t_per, y_per, y_apo = apsides(module, p, _j2_start(module),
                                       3.2 * _circular_period(J2_PERIGEE))
    if len(t_per) < 3:
        raise RuntimeError(f"{module.MODEL}: {len(t_per)} perigees in 3.2 orbits")
    t_r = np.diff(t_per)
    t_grid = np.linspace(t_per[0], t_per[1], 4001)[:-1]
    a_mean = float(np.mean([semi_major_axis(module, p, sol.sol(t)) for t in t_grid]))
    r_p, r_a = y_per[0][r], y_apo[0][r]
    e = float((r_a - r_p) / (r_a + r_p))
    n = math.sqrt(MU_EARTH / a_mean**3)
    eps = J2_EARTH * (R_EARTH / (a_mean * (1 - e * e))) ** 2
    apsidal = (np.diff(y_per[:, nu]) - 2 * math.pi) / t_r
    mean_motion = 2 * math.pi / t_r
    apsidal_th = 1.5 * n * eps
    mean_motion_th = n * (1 + 1.5 * eps * math.sqrt(1 - e * e))
    return J2Rates(e, a_mean, _frozen(apsidal / apsidal_th - 1),
                   _frozen((mean_motion - n) / (mean_motion_th - n) - 1), apsidal_th, float(t_r[0]))


@cache
def kepler_ellipse(module) -> tuple:
    """The J2 start with J2 = 0, 2.2 orbits: (turn of the line of apsides in one radial
    period [rad], radial period / 2π √(a³/μ) − 1): both 0 for Kepler's closed ellipse."""
    p = params(module, **dumbbell())
    y0 = _j2_start(module)
    _, t_per, y_per, _ = apsides(module, p, y0, 2.2 * _circular_period(J2_PERIGEE))
    a = semi_major_axis(module, p, y0)
    nu = module.STATE.index("nu")
    return (float(np.diff(y_per[:, nu])[0] - 2 * math.pi),
            float((t_per[1] - t_per[0]) / _circular_period(a) - 1))


@cache
def forced_pitch_error(module, e: float = 1e-3) -> float:
    """max |θ − θ_forced| / e over 3 orbits of a dumbbell from 200 km perigee, θ_forced =
    −e sin ν.  Beletsky's (1 + e cos ν)θ″ − 2e sin ν(θ′ + 1) + 3K sin θ cos θ = 0 has the
    periodic solution θ_B ≈ 2e sin ν/(3K − 1) = e sin ν for a dumbbell (K = 1), first-order
    error ≈ 0.2 % at e = 1e-3 (docs/sources.md); θ_B turns with the orbit, our θ the
    other way (docs/conventions.md).  Starts on it: θ = 0, θ̇ = −e ν̇ at perigee."""
    p = params(module, **dumbbell())
    nu_dot_p = math.sqrt(MU_EARTH * (1 + e) / R200**3)
    y0 = state(module, r=R200, nu_dot=nu_dot_p, theta_dot=-e * nu_dot_p)
    period = _circular_period(R200 / (1 - e))
    sol = integrate(module, p, y0, 3 * period, t_eval=np.linspace(0, 3 * period, 3001))
    theta = sol.y[module.STATE.index("theta")]
    anomaly = sol.y[module.STATE.index("nu")] - y0[module.STATE.index("nu")]
    return float(np.max(np.abs(theta + e * np.sin(anomaly))) / e)


class EnergyBalance(NamedTuple):
    """E = T + V + springs (the generated ``jacobi``) and the work done, at 0, 500 … 2000 s [J]."""

    energy: np.ndarray
    drag_work: np.ndarray
    damper_work: np.ndarray


@cache
def energy_balance(module, air: bool) -> EnergyBalance:
    """J2 on, dampers at c = 0.3 N s/m, ρ = (1, 1.1, 0.9) × 2.8e-10 (or no air), from a
    circular 200 km start with the balloon 25 m behind, 3 m up and moving, θ = π/6."""
    rho = RHO if air else 0.0
    p = params(module, rho1=rho, rho2=1.1 * rho, rho3=0.9 * rho, c1=0.3, c2=0.3, J2=J2_EARTH)
    y0 = state(module, delta_x=25.0, delta_y=3.0, theta=math.pi / 6, r=R200,
               delta_x_dot=2.0, delta_y_dot=-1.0, nu_dot=math.sqrt(MU_EARTH / R200**3))
    t_eval = np.linspace(0.0, 2000.0, 5)
    sol = integrate(module, p, y0, 2000.0, extra=work(module, p), t_eval=t_eval)
    n = len(module.STATE)
    energy = [module.jacobi(sol.y[:n, i].copy(), p) for i in range(len(t_eval))]
    return EnergyBalance(_frozen(energy), _frozen(sol.y[n]), _frozen(sol.y[n + 1]))


def _damper_work(air: bool) -> list:
    return [energy_balance(m, air).damper_work[-1] for m in MODULES]


def _pct(x) -> float:
    return 100 * float(np.mean(x))


QUANTITIES = {
    "orbit_decay_run": lambda: decay(free).run,
    "orbit_decay_law": lambda: decay(free).law,
    "orbit_decay_error_pct": lambda: 100 * (decay(free).run / decay(free).law - 1),
    "orbit_decay_still_air_pct": lambda: 100 * (decay(free).run / decay(free).still_air - 1),
    "orbit_j2_e": lambda: j2_rates(free).e,
    "orbit_j2_apsidal_pct": lambda: _pct(j2_rates(free).apsidal_error),
    "orbit_j2_mean_motion_pct": lambda: _pct(j2_rates(free).mean_motion_error),
    # the rate against ω̇ = 3 n J2 (R_E/p)² alone, twice (3/2) n J2 (R_E/p)²
    "orbit_j2_vs_omega_dot_pct": lambda: _pct((1 + j2_rates(free).apsidal_error) / 2 - 1),
    # the second-order term 21ε/4, ε = J2 (R_E/ā)², of the near-circular epicyclic rate
    "orbit_j2_second_order_pct":
        lambda: 100 * 21 / 4 * J2_EARTH * (R_EARTH / j2_rates(free).a_mean) ** 2,
    "orbit_forced_pitch_pct": lambda: 100 * forced_pitch_error(free),
    "orbit_energy": lambda: energy_balance(free, True).energy[0],
    "orbit_drag_work": lambda: energy_balance(free, True).drag_work[-1],
    "orbit_damper_work_least": lambda: max(_damper_work(True)),
    "orbit_damper_work_most": lambda: min(_damper_work(True)),
    "orbit_damper_only_work_least": lambda: max(_damper_work(False)),
    "orbit_damper_only_work_most": lambda: min(_damper_work(False)),
    # the balloon 2 m out of the plane
    "orbit_3d_decay_run": lambda: decay(three_d_free, delta_z=2.0).run,
    "orbit_3d_decay_law": lambda: decay(three_d_free, delta_z=2.0).law,
    "orbit_3d_decay_error_pct":
        lambda: 100 * (decay(three_d_free, delta_z=2.0).run / decay(three_d_free, delta_z=2.0).law - 1),
}

_DECAY, _DRAG = "| decay, 3000 s at 200 km", "| energy, 2000 s, J2 on, drag + dampers"
_DAMP, _3D = "| energy, dampers only | ΔE = W_damper (", "with the balloon 2 m out of the plane, Δa = "
# every figure integrates the free kernels for seconds (3d-free: a 7 s cold compile): slow
FIGURES = [Figure(ORBIT, at, key, slow=True, absolute=absolute) for at, key, absolute in (
    ((_DECAY, "Δa = "), "orbit_decay_run", False),
    ((_DECAY, " m vs "), "orbit_decay_law", False),
    ((_DECAY, "m: **"), "orbit_decay_error_pct", False),
    ((_DECAY, "still-air form: off by "), "orbit_decay_still_air_pct", True),
    (("| J2 apsidal rate", "e ≈ "), "orbit_j2_e", False),
    (("| J2 apsidal rate", "| **"), "orbit_j2_apsidal_pct", False),
    (("| J2 anomalistic mean motion", "J2 part **"), "orbit_j2_mean_motion_pct", False),
    (("| forced pitch", "= **"), "orbit_forced_pitch_pct", False),
    ((_DRAG, "of E = "), "orbit_energy", False),
    ((_DRAG, "(W_drag "), "orbit_drag_work", False),
    ((_DRAG, "(W_drag ", "W_damper "), "orbit_damper_work_least", False),
    ((_DRAG, "(W_drag ", "W_damper ", " to "), "orbit_damper_work_most", False),
    ((_DAMP,), "orbit_damper_only_work_least", False),
    ((_DAMP, " to "), "orbit_damper_only_work_most", False),
    (("the measured rate is half of it, ",), "orbit_j2_vs_omega_dot_pct", False),
    (("averages to zero). The ",), "orbit_j2_apsidal_pct", False),
    (("ε = J2 (R_E/ā)², i.e. ",), "orbit_j2_second_order_pct", False),
    ((_3D,), "orbit_3d_decay_run", False),
    ((_3D, " m vs "), "orbit_3d_decay_law", False),
    ((_3D, "m, **"), "orbit_3d_decay_error_pct", False))]
