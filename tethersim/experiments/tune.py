"""Nominal tether values by computation, the way the thesis found them by hand (p. 5-18, 5-7).

1. Moduli: for a given E1, the E2 at the centre of the stable band.  The band
   is where the steady-state pitch stays within ±tol of zero; θ_ss falls
   steadily as E2 rises (thesis p. 5-5: "increasing the second modulus ...
   increases the average pitch" — the sign depends on the θ convention, see
   docs/conventions.md), so the band edges are the E2 where θ_ss = ±tol.  A
   scan over E2 around the torque-balance estimate (b/a)·E1 brackets them and
   bisection finds each edge.
2. Damping: with those moduli, (c1, c2) = k × the starting values, for k on a
   log grid; the choice is the k that settles fastest while staying stable
   (not offset, tumbling or upside down).

Every evaluation is a full converged run of the sweep's point function, so
``tune`` agrees with ``sweep`` by construction.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tethersim.analysis.classify import CLASSES, STABLE, TUMBLING, UPSIDE_DOWN
from tethersim.analysis.metrics import SETTLING_TOL, long_enough, min_run_orbits
from tethersim.experiments.sweep.batch import run_block
from tethersim.experiments.sweep.runner import map_points
from tethersim.experiments.sweep.spec import SweepSpec
from tethersim.model.params import from_si
from tethersim.model.satellite import Satellite

SCAN_POINTS = 33  # E2 scan points over [0.5, 2] x the torque-balance estimate
EDGE_RTOL = 1e-4  # relative precision of each band edge in E2
DAMPING_FACTORS = np.logspace(-1, 2, 16)  # k in (c1, c2) = k x the starting values
DEFAULT_DAMPING = 3e-4  # N s/m, used when the satellite has no damping to scale


class TuningError(ValueError):
    """No stable band or no stable damping in the searched range."""


@dataclass(frozen=True)
class TuneResult:
    satellite: Satellite  # the tuned satellite
    band: tuple  # (E2 low, E2 high) [N] at the tuned E1
    damping_scan: list  # [(k, class name, settling time [s], steady-state pitch [rad])]
    damping_factor: float
    runs: int


def check_periods(periods: float) -> None:
    """Refuse runs too short to decide a class (tethersim.analysis.metrics.long_enough):
    every point of a tuning would be ``undecided``."""
    if not long_enough(periods):
        raise ValueError(f"periods = {periods!r}: too short to decide a stability class; "
                         f"tuning needs at least {min_run_orbits():.4g} orbits")


def _run(sat: Satellite, name: str, value_si: float, periods: float, model: str) -> dict:
    spec = SweepSpec(sat, ((name, [from_si(name, value_si)]),), periods=periods, model=model)
    return run_block(spec, [0])[0][1]  # the sweep's compiled path, not simulate() + outcome()


def _theta_ss(rec: dict) -> float:
    if rec["stability_class"] in (TUMBLING, UPSIDE_DOWN) or rec["status"] != 0:
        return math.nan
    return rec["steady_state_pitch"]


def stable_band_E2(sat: Satellite, periods: float = 50.0, model: str = "derived",
                   tol: float = SETTLING_TOL, workers: int | None = None) -> tuple:
    """(E2 low, E2 high, runs) [N]: the E2 interval with |θ_ss| <= tol at the satellite's E1."""
    check_periods(periods)
    guess = sat.E1 * sat.b / sat.a  # torque balance about the COM (docs/torque-balance.md)
    if guess <= 0:
        raise ValueError(f"E1 = {sat.E1} N: tuning E2 needs E1 > 0")
    grid = np.linspace(0.5 * guess, 2.0 * guess, SCAN_POINTS)
    spec = SweepSpec(sat, (("E2", [from_si("E2", g) for g in grid]),), periods=periods, model=model)
    th = np.array([_theta_ss(r) for r in map_points(spec, workers=workers)])
    runs = len(grid)
    edges = []
    for level in (+tol, -tol):
        # θ_ss decreases through the band: find the scan interval where it crosses the level
        # (a run that tumbles, NaN here, counts as below: past the band it turns over)
        above = np.nan_to_num(th, nan=-np.inf) > level
        idx = [i for i in range(len(grid) - 1) if above[i] and not above[i + 1]]
        if not idx:
            raise TuningError(f"no E2 in {grid[0]:.4g}..{grid[-1]:.4g} N gives a steady pitch of "
                               f"{level:+g} rad at E1 = {sat.E1:.4g} N; the stable band is outside "
                               f"the scan (steady pitches {np.round(th, 3).tolist()})")
        i = min(idx, key=lambda j: abs(grid[j] - guess))
        lo, hi = grid[i], grid[i + 1]
        while hi - lo > EDGE_RTOL * hi:
            mid = 0.5 * (lo + hi)
            v = _theta_ss(_run(sat, "E2", mid, periods, model))
            runs += 1
            if math.isfinite(v) and v > level:
                lo = mid
            else:
                hi = mid
        edges.append(0.5 * (lo + hi))
    return min(edges), max(edges), runs


def tune(sat: Satellite, E1: float | None = None, periods: float = 50.0, model: str = "derived",
         workers: int | None = None) -> TuneResult:
    """Tuned moduli and damping for ``sat`` (E1 [N], default the satellite's own).

    The thesis damper exerts a torque at rest (docs/torque-balance.md), so damping
    shifts the trim: the damping is chosen with the pitch trimmed within half the
    band (|θ_ss| <= tol/2), and E2 is then centred again at the chosen damping.
    """
    check_periods(periods)
    if E1 is not None:
        sat = sat.replace(E1=E1)
    lo, hi, runs = stable_band_E2(sat, periods, model, workers=workers)
    sat = sat.replace(E2=0.5 * (lo + hi))
    c1, c2 = (sat.c1, sat.c2) if sat.c1 + sat.c2 > 0 else (DEFAULT_DAMPING, DEFAULT_DAMPING)
    spec = SweepSpec(sat.replace(c1=c1, c2=c2), (("c1", [c1 * k for k in DAMPING_FACTORS]),
                                                  ("c2", [c2 * k for k in DAMPING_FACTORS])),
                     periods=periods, model=model)
    diagonal = [i * len(DAMPING_FACTORS) + i for i in range(len(DAMPING_FACTORS))]
    recs = map_points(spec, diagonal, workers=workers)
    runs += len(recs)
    scan = [(float(k), CLASSES[r["stability_class"]], r["settling_time"], r["steady_state_pitch"])
            for k, r in zip(DAMPING_FACTORS, recs)]
    ok = [(t, k) for k, name, t, th in scan
          if name == CLASSES[STABLE] and abs(th) <= 0.5 * SETTLING_TOL]
    if not ok:
        raise TuningError(f"no damping factor in {DAMPING_FACTORS[0]:g}..{DAMPING_FACTORS[-1]:g} "
                          f"x ({c1:g}, {c2:g}) N s/m settles stably: {scan}")
    _, k = min(ok)
    damped = sat.replace(c1=c1 * k, c2=c2 * k)
    lo, hi, more = stable_band_E2(damped, periods, model, workers=workers)
    tuned = damped.replace(E2=0.5 * (lo + hi))
    final = _run(tuned, "E2", tuned.E2, periods, model)
    if final["stability_class"] != STABLE:
        raise TuningError(f"the re-centred satellite (E2 = {tuned.E2:.6g} N, k = {k:.4g}) is "
                          f"{CLASSES[final['stability_class']]}, not stable")
    return TuneResult(tuned, (lo, hi), scan, float(k), runs + more + 1)
