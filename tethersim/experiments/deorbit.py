"""``tethersim deorbit``: lifetime with and without the balloon over drawn epochs (docs/deorbit.md).

Per start altitude, n epochs are drawn as ``tethersim mc`` draws them (uniform in time
over the usable days of the bundled history from 1986-09-01 to its last observed day,
the stream of the input named "epoch" under the seed), and from each the orbit decays
day by day in the orbit-mean NRLMSISE-00 air of that day's own indices
(tethersim.analysis.deorbit.lifetimes); past the last observed day the history repeats
three solar cycles earlier (tethersim.model.air.orbit_mean).  The statistics are mc's:
inverted-CDF quantiles with distribution-free 95 % intervals, censored lives (+inf)
beyond the cap included.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis import deorbit as law
from tethersim.analysis.uncertainty import quantile_ci
from tethersim.experiments.mc.inputs import EPOCH_FIRST, Input, epoch_seconds, observed_days, stream
from tethersim.model.air import orbit_mean
from tethersim.model.air.grid import seconds_into_day

QUANTILES = (0.1, 0.5, 0.9)
MAX_EPOCHS = 10_000
#: the lifetime law needs the altitude inside the orbit-mean profile's nodes
ALTITUDE_MAX = float(orbit_mean.NODES[-1])


def check_altitudes(sat, low: float, high: float, n: int) -> np.ndarray:
    """The start altitudes [m] of ``--from LOW:HIGH:N``, or a one-line ValueError."""
    lo_ok = sat.reentry_altitude
    if not (isinstance(n, int) and 1 <= n <= 200):
        raise ValueError(f"from: N = {n!r} must be a whole number 1..200")
    if not (math.isfinite(low) and math.isfinite(high) and lo_ok < low <= high <= ALTITUDE_MAX):
        raise ValueError(f"from: {low / 1e3:g}:{high / 1e3:g} km must satisfy re-entry "
                         f"{lo_ok / 1e3:g} km < LOW <= HIGH <= {ALTITUDE_MAX / 1e3:g} km")
    if n == 1 and low != high:
        raise ValueError("from: N = 1 needs LOW = HIGH")
    return np.linspace(low, high, n)


def draw_epochs(n: int, seed: int) -> np.ndarray:
    """n epochs [s since 1970], drawn as mc draws them (its "epoch" stream and band)."""
    if not (isinstance(n, int) and 1 <= n <= MAX_EPOCHS):
        raise ValueError(f"n = {n!r}: epochs must be a whole number 1..{MAX_EPOCHS}")
    band = Input("epoch", "epoch", EPOCH_FIRST, observed_days()[1], "day", "start instant")
    return band.value(stream(seed, "epoch").random(n))


def log_q(sat) -> np.ndarray:
    """ln of ρ̄ √(μ a)(1 − ω_E/n)² on the history's days x nodes (analysis.deorbit)."""
    return np.log(orbit_mean.history()) + np.log(law.orbit_factor(sat, orbit_mean.NODES))[None, :]


def lives(sat, altitudes, epochs_s, balloon: bool, max_years: float, bar=None) -> np.ndarray:
    """Lifetimes [s] (+inf beyond ``max_years``), shape (altitudes, epochs); ``bar`` (a
    tqdm bar or None) advances by one per altitude."""
    e = np.asarray(epochs_s, float) - epoch_seconds(orbit_mean.HISTORY_FIRST)
    lq = log_q(sat)
    out = []
    for h in np.asarray(altitudes, float):
        out.append(law.lifetimes(lq, orbit_mean.NODES, orbit_mean.history_row,
                                 np.full(e.size, h), law.ballistic(sat, balloon), e,
                                 sat.reentry_altitude, max_years * law.YEAR))
        if bar is not None:
            bar.update()
    return np.array(out)


def _quantiles(values) -> dict:
    out = {}
    for p in QUANTILES:
        est, lo, hi = quantile_ci(values, p)
        out[f"p{round(100 * p)}"] = (est, lo, hi)
    return out


def trail_altitudes(sat, length: float) -> dict:
    """Altitude [m] where ε = 1 (trails below, hangs above) in the P10/P50/P90 day of the
    history's orbit-mean air (a thin day raises it less than a dense day lowers it)."""
    nodes = orbit_mean.NODES
    table = np.log(orbit_mean.history())
    out = {}
    for name, p in (("thin", 0.1), ("median", 0.5), ("dense", 0.9)):
        prof = np.quantile(table, p, axis=0)
        out[name] = law.trail_altitude(sat, length, lambda x, prof=prof: math.exp(np.interp(x, nodes, prof)),
                                       low=max(sat.reentry_altitude, 130e3), high=ALTITUDE_MAX)
    return out


def deorbit(sat, altitudes, n: int = 100, seed: int = 0, max_years: float = 200.0,
            line_length: float | None = None, progress: bool | None = None) -> dict:
    """Lifetimes with and without the balloon, their ratio and verdicts, at each altitude.

    Parameters
    ----------
    sat : Satellite
        The design (masses, areas, C_D, re-entry altitude).
    altitudes : array_like
        Start altitudes [m].
    n, seed : int
        Epochs drawn and their seed.
    max_years : float
        Cap on a life [years]; a longer one is censored (+inf).
    line_length : float, optional
        The balloon's distance from the centre of mass [m] for trail or hang (default
        the design's start offset).
    progress : bool or None, optional
        Progress bars (None: when slower than a second; False: none).

    Returns
    -------
    dict
        ``rows`` (one dict per altitude: quantiles with 95 % intervals [s], median ratio,
        verdicts), ``epochs`` [s since 1970], ``life`` {"with", "without"} arrays (altitude,
        epoch) [s], ``trail`` (ε = 1 altitudes [m]), ``line_length`` [m].
    """
    if not (math.isfinite(max_years) and 0 < max_years <= 1000):
        raise ValueError(f"max_years = {max_years!r}: must be in (0, 1000] years")
    h = np.asarray(altitudes, float)
    epochs = draw_epochs(n, seed)
    orbit_mean.history(progress)  # built once, then read from the cache
    from tqdm.auto import tqdm
    with tqdm(total=2 * h.size, desc="lifetimes", unit="altitude", disable=progress is False,
              delay=0.0 if progress else 1.0, leave=False) as bar:
        life = {"with": lives(sat, h, epochs, True, max_years, bar),
                "without": lives(sat, h, epochs, False, max_years, bar)}
    ell = math.hypot(sat.initial[0], sat.initial[1]) if line_length is None else line_length
    if not (math.isfinite(ell) and ell > 0):
        raise ValueError(f"line_length = {ell!r} m: must be > 0 (the balloon's distance "
                         f"from the centre of mass)")
    rows = []
    for i, hi in enumerate(h):
        w, wo = life["with"][i], life["without"][i]
        with np.errstate(invalid="ignore"):
            ratio = np.where(np.isinf(w), np.nan, wo / w)
        q = {k: _quantiles(v) for k, v in (("with", w), ("without", wo))}
        row = {"altitude": float(hi), **{f"{k}_{p}": q[k][p] for k in q for p in q[k]},
               "ratio_p50": (_quantiles(ratio[~np.isnan(ratio)])["p50"]
                             if np.any(~np.isnan(ratio)) else (math.nan,) * 3)}
        for k in q:
            for years in law.RULES_YEARS:
                row[f"{k}_{years:g}y"] = law.verdict(q[k]["p10"][0], q[k]["p90"][0], years)
        rows.append(row)
    return {"rows": rows, "epochs": epochs, "life": life, "line_length": ell,
            "trail": trail_altitudes(sat, ell), "max_years": max_years}


def flight_life(bc: float, altitude: float, epoch: str, reentry_altitude: float = 120e3,
                max_years: float = 50.0) -> float:
    """Lifetime [s] of one flight from ``altitude`` [m] at ``epoch`` (ISO UTC) with ballistic
    coefficient ``bc`` = C_D A / M [m^2/kg], by the same law (a published flight's inputs).

    The orbit factor √(μ a)(1 − ω_E/n)² does not depend on the design, so SatI's
    record carries it here.
    """
    from tethersim.model.presets import load_preset
    if not (math.isfinite(bc) and bc > 0):
        raise ValueError(f"bc = {bc!r} m^2/kg: must be > 0")
    check_altitudes(load_preset("satI").replace(reentry_altitude=reentry_altitude),
                    altitude, altitude, 1)
    sat = load_preset("satI")
    start = (epoch_seconds(str(np.datetime64(epoch, "D")))
             + seconds_into_day(np.datetime64(epoch, "s")))
    return float(law.lifetimes(log_q(sat), orbit_mean.NODES, orbit_mean.history_row,
                               [altitude], bc, [start - epoch_seconds(orbit_mean.HISTORY_FIRST)],
                               reentry_altitude, max_years * law.YEAR)[0])
