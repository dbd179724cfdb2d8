"""The quantities that the docs quote, each computed with the project's own code.

Every entry of :data:`QUANTITIES` is a function of no argument that returns one
float in the unit the doc prints.  The equilibria, eigenvalues and torque balance
take milliseconds; the ``run_*`` quantities simulate (the slow tier).
"""
from __future__ import annotations

import math
import warnings
from functools import cache

import numpy as np

from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.metrics import wrap
from tethersim.engine.linearise import rk4_amplification, rk4_max_step
from tethersim.model.params import edge_value, with_values  # noqa: F401 (edge_value: figures)
from tethersim.model.presets import load_preset

FAITHFUL_STEP = (50, 10_000)  # Sec 5.2: 50 orbits in 10,000 steps
MODULI_STEP = (5, 1500)  # Sec 5.1: 5 orbits in 1500 steps
JUMP = 0.7  # rad: a continued branch that jumps further is lost (headlines.CONTINUATION_JUMP)


@cache
def sat(name: str = "satI", factor: float = 1.0, E1: float = 1.0, E2: float = 1.0):
    """A preset with its dampers times ``factor`` and its moduli times ``E1``, ``E2``."""
    s = load_preset(name)
    return with_values(s, {"c1": edge_value(s, "c1") * factor, "c2": edge_value(s, "c2") * factor,
                           "E1": edge_value(s, "E1") * E1, "E2": edge_value(s, "E2") * E2})


def _eq(s, model, guess):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return find_equilibrium(s, model, guess=guess)


@cache
def branch(model: str, theta0: float, factor: float):
    """The equilibrium near ``theta0`` at damping x 1, continued to x ``factor``.

    Continuation along 12 points per decade; None once the branch is lost (no
    root, or a jump of more than JUMP, as in ``headlines.damping_scan``).
    """
    s = sat()
    g = (s.initial[0], s.initial[1], theta0)
    n = max(1, int(math.ceil(12 * math.log10(factor)))) if factor > 1 else 1
    eq = None
    for f in np.geomspace(1.0, factor, n + 1) if factor > 1 else [1.0]:
        try:
            eq = _eq(sat(factor=float(f)), model, g)
        except RuntimeError:
            return None
        if abs(float(wrap(eq.theta - g[2]))) > JUMP:
            return None
        g = (eq.delta_x, eq.delta_y, eq.theta)
    return eq


def pitch_mode(eq) -> tuple:
    """(frequency [rad/s], damping ratio, decay time [s]) of the slowest (pitch) mode."""
    return eq.modes()[0]


@cache
def fold_factor(model: str = "derived", tol: float = 1e-3) -> float:
    """Damping factor where the inverted (θ ≈ π) equilibrium meets its saddle and vanishes.

    Bisection on the factor: the branch exists at f when it can be continued
    from the last factor where it existed, in four steps, each landing on a
    stable equilibrium within 0.1 rad of the last.

    Parameters
    ----------
    model : str
        Model variant (the thesis damper: ``derived`` or ``printed``).
    tol : float
        Width of the final bracket (in units of the damping factor).

    Returns
    -------
    float
        The largest factor (to ``tol``) at which the inverted equilibrium of SatI,
        with c1, c2 times that factor, still exists and is stable.
    """
    lo, hi = 1.0, 1000.0
    eq = branch(model, math.pi, lo)
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        g, ok = eq, True
        for f in np.linspace(lo, mid, 5)[1:]:
            try:
                e = _eq(sat(factor=float(f)), model, (g.delta_x, g.delta_y, g.theta))
            except RuntimeError:
                ok = False
                break
            if abs(float(wrap(e.theta - g.theta))) > 0.1 or not e.stable:
                ok = False
                break
            g = e
        if ok:
            lo, eq = mid, g
        else:
            hi = mid
    return lo


def step(periods_steps=FAITHFUL_STEP) -> float:
    """The thesis's RK4 step [s]: ``periods`` orbits of SatI in ``steps`` steps."""
    periods, n = periods_steps
    return periods * sat().period / n


def mode_freq(which: int) -> float:
    """Frequency [rad/s] of SatI's nominal equilibrium mode ``which`` (sorted; -1: fastest)."""
    return branch("derived", 0.0, 1.0).modes()[which][0]


def rest_torque(factor: float) -> float:
    """The thesis damper's constant torque at rest ω (c1 b² + c2 a²) [N m]."""
    s = sat(factor=factor)
    return s.omega * (s.c1 * s.b ** 2 + s.c2 * s.a ** 2)


def mirror(E1: float, guess: float) -> float:
    """Equilibrium pitch [rad] with E1 x ``E1`` and no damping, near ``guess``."""
    s = sat(factor=0.0, E1=E1)
    return _eq(s, "derived", (s.initial[0], s.initial[1], guess)).theta


def inverted_mod_2pi(model: str, factor: float) -> float:
    """The inverted equilibrium at damping x ``factor``, as an angle in [0, 2π)."""
    return branch(model, math.pi, factor).theta % (2 * math.pi)


def scan_row(factor: float, what: str) -> float:
    """One fast column of the damping-scan table at x ``factor`` (model derived)."""
    s = sat(factor=factor)
    if what == "amp":
        return rk4_amplification(s, step(), "derived")
    if what == "max_step":
        return rk4_max_step(s, "derived")
    return branch("derived", math.pi, factor).theta


def air_speed() -> float:
    """Air speed of the COM (ω − ω_E) r0 [km/s] at SatI's altitude."""
    from tethersim.model.constants import OMEGA_EARTH

    s = sat()
    return (s.omega - OMEGA_EARTH) * s.r0 / 1000


# --- torque balance (docs/torque-balance.md) -------------------------------------------
@cache
def balance(name: str) -> dict:
    """TB terms at the preset's θ = 0 trail, the exact balance and the equilibrium pitch."""
    from tethersim.analysis.torque_balance import (
        balanced_E2,
        balloon_trail_at_zero_pitch,
        torque_balance_terms,
    )

    s = load_preset(name)
    dx, dy = balloon_trail_at_zero_pitch(s)[:2]
    out = dict(torque_balance_terms(s, dx, dy))
    out.update(exact=balanced_E2(s) / s.E1, preset=s.E2 / s.E1, dx=dx, dy=dy,
               theta_eq=find_equilibrium(s).theta)
    return out


@cache
def balanced_at(E1: float) -> tuple:
    """(balanced E2/E1, trail δx [m] at balance) for SatI with E1 [N/mm²]."""
    from tethersim.analysis.torque_balance import balanced_E2, balloon_trail_at_zero_pitch

    s = load_preset("satI").replace(E1=E1)
    e2 = balanced_E2(s)
    return e2 / E1, balloon_trail_at_zero_pitch(s.replace(E2=e2))[0]


# --- runs (slow tier) --------------------------------------------------------------------
@cache
def run_satI() -> dict:
    """SatI, 50 orbits, adaptive: settling, trail and largest forces (README)."""
    from tethersim.analysis.force_peaks import largest_forces
    from tethersim.analysis.outcome import outcome
    from tethersim.engine.simulate import simulate

    s = load_preset("satI")
    res = simulate(s, 50.0, progress=False)
    o = outcome(res, forces=False)
    m = o.metrics
    peaks = {r.coordinate: r.peak for r in largest_forces(res)}
    return {"settling_h": m.settling_time / 3600, "settling_orbits": m.settling_time / s.period,
            "trail": o.trail_delta_x, **peaks}


@cache
def headline(case: str, model: str = "derived") -> dict:
    """The converged (DOP853) run of one headline case (``headlines.run_headlines``)."""
    from tethersim.experiments.headlines import run_headlines

    rows = run_headlines(models=(model,), cases=(case,), schemes=("dop853",), progress=False)
    return rows[0]
