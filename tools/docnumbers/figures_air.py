"""Figures of docs/air.md: a free orbit in NRLMSISE-00 air against the decay law (issue 12).

:func:`msis_decay` is also what tests/engine/test_orbit_runs.py bounds (0.5 %).
"""
from __future__ import annotations

from functools import cache

import numpy as np

from tethersim.engine.simulate import simulate
from tethersim.model.air.grid import gmst
from tethersim.model.constants import MU_EARTH, OMEGA_EARTH, R_EARTH
from tethersim.model.options import air_density
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

A = "docs/air.md"


@cache
def msis_decay() -> tuple:
    """(Δa of the run / Δa of the law − 1, largest / smallest ρ along the path).

    One orbit of SatI on a free orbit from 200 km, each body in NRLMSISE-00 air (F10.7 =
    F10.7a = 150, Ap 4, 2017-06-23 05:17 UTC); the law da/dt = −ρ B √(μa)(1 − ω_E/n)²
    with ρ from pymsis itself (no grid) at the COM's altitude, longitude and time of each
    of 2000 samples, a the osculating semi-major axis (vis-viva).
    """
    sat = load_preset("satI").replace(
        orbit="free", density_mode="per-body", reentry_altitude=170e3, atmosphere="nrlmsise00",
        epoch="2017-06-23T05:17:00", f107=150.0, f107a=150.0, ap=4.0)
    res = simulate(sat, periods=1, samples=2000, progress=False)
    r, rd, nd = res.series("r"), res.series("r_dot"), res.series("nu_dot")
    a = 1 / (2 / r - (rd**2 + r**2 * nd**2) / MU_EARTH)
    B = sat.CD * (sat.A1 + sat.A2 + sat.A3) / (sat.m1 + sat.m2 + sat.m3)
    X, Y = res.orbit[:, 0], res.orbit[:, 1]
    lon = np.arctan2(Y, X) - gmst(np.datetime64(sat.epoch)) - OMEGA_EARTH * res.t
    rho = np.array([air_density(sat, x - R_EARTH, t, g) for x, t, g in zip(r, res.t, lon)])
    rate = -rho * B * np.sqrt(MU_EARTH * a) * (1 - OMEGA_EARTH / np.sqrt(MU_EARTH / a**3)) ** 2
    from scipy.integrate import cumulative_trapezoid
    law = cumulative_trapezoid(rate, res.t, initial=0.0)
    return float((a[-1] - a[0]) / law[-1] - 1), float(rho.max() / rho.min())


QUANTITIES = {"air_msis_decay_error": lambda: abs(msis_decay()[0]),
              "air_msis_day_night": lambda: msis_decay()[1]}
# the run compiles the free-orbit kernels: the slow tier
FIGURES = [Figure(A, ("varies by a factor", "of ~"), "air_msis_day_night", slow=True),
           Figure(A, ("within 0.5 % (measured ",), "air_msis_decay_error", slow=True)]
