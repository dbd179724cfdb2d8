"""The trail bound: the drag that trails the balloon is the drag that lowers the orbit.

docs/design.md derives it; in short, for a satellite of total mass M on a circular
orbit of radius r at rate n (speed v = n r), with the bodies' drags D_i = ½ ρ C_D A_i v_rel²
(v_rel = (n − ω_E) r in air co-rotating with the Earth):

* **how strongly the balloon trails** -- its differential drag (its own drag less its
  share m_b D/M of the deceleration every body feels) against the gravity-gradient
  restoring force over the trail length L,  ε = ΔD / (3 n² m_b L);
  the tethers carry the vector sum,  T = ΔD √(1 + 1/ε²);
* **how fast the same drag lowers the orbit** -- ȧ = −2 r D/(M v) (energy: d(−μM/2r)/dt =
  −D v; the air co-rotates with the Earth, so D is at the speed (n − ω_E) r), so the
  orbit decays from r to the re-entry altitude in
  T_decay = ∫ dr / |ȧ(r)| (the air of ``density``), the quasi-circular decay time (a
  free run's life stays within 20 % of it: tests/analysis/test_trail_bound_runs.py);
* **the fastest settling the trail allows** -- the boom (pitch inertia I, gravity-gradient
  libration at √3 n) is turned only by the tethers (their net force acts on a line
  through the balloon, so its moment about the COM is at most L T) and by its own bodies'
  drag (at most D_1 b + D_2 a).  A torque τ changes the libration amplitude A at most at
  |τ| / (√3 n I cos A), so bringing A from the start's A_0 = |θ_0| into the band
  (2 tol: the trim and the swing each at most tol) takes at least
  t_min = √3 n I cos A_0 (A_0 − 2 tol) / (L T + D_1 b + D_2 a).

Both scale as 1/ρ, so their ratio t_min / T_decay does not depend on the air: a design
cannot buy a faster settling with more drag without losing its orbit as much faster.  A
design settles before its orbit decays only if that ratio is below 1; every reported
design of ``tethersim design`` is checked against it.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from tethersim.model import atmosphere
from tethersim.model.constants import MU_EARTH, OMEGA_EARTH, R_EARTH

QUADRATURE_POINTS = 2001  # trapezoid nodes over the decay's altitudes (error << 1e-4)


@dataclass(frozen=True)
class TrailBound:
    """The bound of one design (SI).

    Attributes
    ----------
    epsilon : float
        Trail strength ΔD / (3 n² m_b L) [1].
    differential_drag, tension : float
        ΔD and the tethers' quasi-static pull T = √(ΔD² + (3 n² m_b L)²) [N].
    decay_rate : float
        |ȧ| at the start [m/s].
    decay_life : float
        Time for the circular orbit to decay to the re-entry altitude [s].
    settle_min : float
        Fewest seconds the libration can take to reach the band.
    ratio : float
        ``settle_min / decay_life``: no design with ratio >= 1 can settle before re-entry.
    """

    epsilon: float
    differential_drag: float
    tension: float
    decay_rate: float
    decay_life: float
    settle_min: float
    ratio: float

    def to_dict(self) -> dict:
        return asdict(self)


def drags(sat, rho: float) -> tuple:
    """(D_1, D_2, D_3) [N]: each body's drag in air of density ``rho`` co-rotating with the
    Earth (the model's air: relative speed (n − ω_E) r on the equatorial orbit)."""
    v = (sat.omega - OMEGA_EARTH) * sat.r0
    q = 0.5 * rho * v * v * sat.CD
    return q * sat.A1, q * sat.A2, q * sat.A3


def decay_rate(sat, rho: float, r: float | None = None) -> float:
    """|ȧ| [m/s] of a circular orbit of radius ``r`` (default: the satellite's) in air ``rho``.

    ȧ = −ρ (C_D ΣA_i / M) √(μ r) (1 − ω_E/n)²: the orbit energy −μM/(2r) falls at the
    drag's power, D = ½ ρ C_D ΣA_i v_rel² against the orbital speed √(μ/r), in air
    co-rotating with the Earth (v_rel = (n − ω_E) r; docs/orbit.md checks a free run
    against this form to 0.07 %).
    """
    r = sat.r0 if r is None else float(r)
    area = sat.CD * (sat.A1 + sat.A2 + sat.A3)
    mass = sat.m1 + sat.m2 + sat.m3
    n = math.sqrt(MU_EARTH / r ** 3)
    return rho * area * math.sqrt(MU_EARTH * r) * (1 - OMEGA_EARTH / n) ** 2 / mass


def decay_life(sat, density=atmosphere.density, scale: float = 1.0,
               reentry_altitude: float | None = None) -> float:
    """Seconds for the circular orbit to decay from the satellite's altitude to re-entry.

    T = ∫ dh / |ȧ(h)| from the re-entry altitude to the start, |ȧ| of :func:`decay_rate`
    in air ``scale`` x ``density(h)`` (trapezoid rule on a grid even in log density, so
    each node carries a like share of the integral).

    Parameters
    ----------
    sat : Satellite
        The design.
    density : callable, optional
        Air density [kg/m^3] at altitude h [m] (default: Vallado's table).
    scale : float, optional
        Factor on the density (a solar case, ``density_scale``).
    reentry_altitude : float, optional
        Where the decay ends [m] (default: the satellite's).
    """
    h0 = sat.altitude
    h1 = sat.reentry_altitude if reentry_altitude is None else float(reentry_altitude)
    if not h1 < h0:
        return 0.0
    h = np.linspace(h1, h0, QUADRATURE_POINTS)
    inv = np.array([1.0 / decay_rate(sat, scale * density(x), R_EARTH + x) for x in h])
    return float(np.trapezoid(inv, h))


def settle_min(sat, trail_length: float, rho: float, tol: float) -> float:
    """Fewest seconds the boom's libration can take from its start into the band ±tol.

    The torque on the boom is at most L T + D_1 b + D_2 a (module docstring); the
    amplitude from the start's energy (at rest: |θ_0|; with a rate, the gravity-gradient
    energy's amplitude).  0 when the start is already within 2 tol.
    """
    n = sat.omega
    theta0, rate0 = sat.initial[2], sat.initial[5]
    s2 = math.sin(theta0) ** 2 + rate0 ** 2 / (3 * n * n)  # ½Iθ̇² + (3/2)n²I sin²θ = (3/2)n²I sin²A
    if s2 >= 1.0:  # over the separatrix: the boom turns over; no libration to settle yet
        amp = math.pi / 2
    else:
        amp = math.asin(math.sqrt(s2))
    if amp <= 2 * tol:
        return 0.0
    d1, d2, _ = drags(sat, rho)
    torque = trail_length * tension(sat, trail_length, rho) + d1 * sat.b + d2 * sat.a
    return math.sqrt(3) * n * sat.pitch_inertia * math.cos(amp) * (amp - 2 * tol) / torque


def differential_drag(sat, rho: float) -> float:
    """ΔD = |D_3 − m_b (D_1 + D_2 + D_3) / M| [N]: the balloon's drag beyond its share."""
    d = drags(sat, rho)
    return abs(d[2] - sat.m3 * sum(d) / (sat.m1 + sat.m2 + sat.m3))


def tension(sat, trail_length: float, rho: float) -> float:
    """The tethers' quasi-static pull on the balloon, √(ΔD² + (3 n² m_b L)²) [N]."""
    return math.hypot(differential_drag(sat, rho), 3 * sat.omega ** 2 * sat.m3 * trail_length)


def trail_bound(sat, trail_length: float, tol: float, scale: float = 1.0,
                density=atmosphere.density) -> TrailBound:
    """The trail bound of ``sat`` with the balloon ``trail_length`` [m] from the COM.

    Parameters
    ----------
    sat : Satellite
        The design (its altitude, masses, areas, C_D, boom and start).
    trail_length : float
        The balloon's distance from the COM [m] (a run's mean trail, or the tethers' reach).
    tol : float
        The settling band [rad].
    scale : float, optional
        Factor on the air density (both the trail's air and the decay's).
    density : callable, optional
        Air density [kg/m^3] at altitude [m] (default: Vallado's table).

    Returns
    -------
    TrailBound

    Raises
    ------
    ValueError
        For a trail length that is not a positive finite number.
    """
    if not (isinstance(trail_length, (int, float)) and math.isfinite(trail_length)
            and trail_length > 0):
        raise ValueError(f"trail_length = {trail_length!r}: must be a finite length > 0 m")
    rho = scale * density(sat.altitude)
    dd = differential_drag(sat, rho)
    gg = 3 * sat.omega ** 2 * sat.m3 * trail_length
    life = decay_life(sat, density, scale)
    smin = settle_min(sat, float(trail_length), rho, tol)
    return TrailBound(epsilon=dd / gg, differential_drag=dd, tension=math.hypot(dd, gg),
                      decay_rate=decay_rate(sat, rho), decay_life=life, settle_min=smin,
                      ratio=smin / life if life > 0 else math.inf)
