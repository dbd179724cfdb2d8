"""Figures of docs/deorbit.md: SatI's ballistic coefficients and trail/hang altitude, the
history's wrap, and the published flights (InflateSail, NanoSail-D2) by the lifetime law."""
from __future__ import annotations

import functools

from tools.docnumbers.check import Figure

DOC = "docs/deorbit.md"
DAY = 86400.0
#: the published flights' inputs (docs/deorbit.md gives the sources)
INFLATESAIL = {"mass": 3.2, "area": 10.0, "altitude": 505e3, "epoch": "2017-06-23",
               "flown_days": 72.0}
NANOSAIL = {"mass": 4.0, "area": 10.0, "altitude": 650e3, "epoch": "2011-01-20"}
CD = 2.2


def _sat():
    import tethersim as ts
    return ts.load_preset("satI")


def _b(balloon: bool) -> float:
    from tethersim.analysis.deorbit import ballistic
    return ballistic(_sat(), balloon)


@functools.cache
def _trail() -> dict:
    from tethersim.experiments.deorbit import trail_altitudes
    return trail_altitudes(_sat(), 29.0)


def _flight_days(f: dict, area_fraction: float = 1.0) -> float:
    from tethersim.experiments.deorbit import flight_life
    return flight_life(CD * f["area"] * area_fraction / f["mass"], f["altitude"], f["epoch"]) / DAY


@functools.cache
def _inflatesail_fraction() -> float:
    """The share of the 10 m^2 whose C_D 2.2 makes the law last InflateSail's 72 days."""
    from scipy.optimize import brentq
    return brentq(lambda x: _flight_days(INFLATESAIL, x) - INFLATESAIL["flown_days"], 0.05, 1.0,
                  xtol=1e-4)


def _towed_stretch_pct() -> float:
    """The towed line's stretch [%] under the tide of SatI's balloon 100 m out at 500 km."""
    from tethersim.experiments.deorbit_runs import TOWED_MODULUS
    s = _sat().replace(altitude=500e3)
    return 100 * 3 * s.omega ** 2 * s.m3 * 100.0 / TOWED_MODULUS


def _towed_ea() -> float:
    from tethersim.experiments.deorbit_runs import TOWED_MODULUS
    return TOWED_MODULUS


def _wrap_years() -> float:
    from tethersim.model.air.orbit_mean import WRAP_DAYS
    return WRAP_DAYS / 365.25


QUANTITIES = {
    "deorbit_b_with": lambda: _b(True),
    "deorbit_b_without": lambda: _b(False),
    "deorbit_b_ratio": lambda: _b(True) / _b(False),
    "deorbit_wrap_years": _wrap_years,
    "deorbit_towed_ea": _towed_ea,
    "deorbit_towed_stretch_pct": _towed_stretch_pct,
    "deorbit_trail_median_km": lambda: _trail()["median"] / 1e3,
    "deorbit_trail_thin_km": lambda: _trail()["thin"] / 1e3,
    "deorbit_trail_dense_km": lambda: _trail()["dense"] / 1e3,
    "deorbit_inflatesail_b": lambda: CD * INFLATESAIL["area"] / INFLATESAIL["mass"],
    "deorbit_inflatesail_days": lambda: _flight_days(INFLATESAIL),
    "deorbit_inflatesail_fraction_pct": lambda: 100 * _inflatesail_fraction(),
    "deorbit_nanosail_days": lambda: _flight_days(NANOSAIL),
}
# the history's orbit-mean air is built once (~35 s) where the cache lacks it: slow tier
FIGURES = [
    Figure(DOC, ("with the balloon B = ",), "deorbit_b_with"),
    Figure(DOC, ("the host alone ",), "deorbit_b_without"),
    Figure(DOC, ("a ratio of ",), "deorbit_b_ratio"),
    Figure(DOC, ("three solar cycles, ",), "deorbit_wrap_years"),
    Figure(DOC, ("in the median day's air at ",), "deorbit_trail_median_km", slow=True),
    Figure(DOC, ("on a thin day (P10 density) ",), "deorbit_trail_thin_km", slow=True),
    Figure(DOC, ("on a dense day (P90) ",), "deorbit_trail_dense_km", slow=True),
    Figure(DOC, ("nearly inextensible (EA ",), "deorbit_towed_ea"),
    Figure(DOC, ("a stretch of ",), "deorbit_towed_stretch_pct"),
    Figure(DOC, ("InflateSail's B = ",), "deorbit_inflatesail_b"),
    Figure(DOC, ("the law gives ",), "deorbit_inflatesail_days", slow=True),
    Figure(DOC, ("last 72 days with ",), "deorbit_inflatesail_fraction_pct", slow=True),
    Figure(DOC, ("NanoSail-D2 ", "the law gives "), "deorbit_nanosail_days", slow=True),
]
