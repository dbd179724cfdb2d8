"""NRLMSISE-00 averaged over an equatorial circular orbit, one profile per UTC day.

A lifetime of years cannot be integrated with the coupled attitude model; it is
integrated in the orbit-averaged circular decay (tethersim.analysis.deorbit), which
needs the density the orbit sees averaged over a revolution at each altitude, on each
day of the run.  Along an equatorial circular orbit the satellite sweeps every local
solar time (LST) once a revolution, and, the period not being a divisor of a day,
every universal time (UT) too: over a day its mean density at altitude h is the mean of
MSIS over the (LST, UT) torus at that day's date and indices.

The mean is taken on a 24-point rank-1 lattice of that torus, LST_k = k h and
UT_k = (5 k mod 24) h (longitude 15 (LST - UT) deg): such a rule averages exactly every
term cos(2π (m1 LST + m2 UT)/24) with m1 + 5 m2 not a multiple of 24, i.e. all the
diurnal, semi- and ter-diurnal LST terms of MSIS (|m1| <= 3) crossed with its UT and
longitude terms up to the second harmonic (|m2| <= 2), at the cost of 24 calls
(tests/model/test_air_orbit_mean.py compares it with a 24 x 24 grid of direct calls).

The profile is kept at :data:`NODES` altitudes (uniform in ln(h - 60 km), like the run
grid of docs/air.md: 4 km apart at 120 km, 60 km at 1000 km) for every day of the
history :data:`HISTORY_FIRST` .. the table's last observed day, each day with its own
F10.7 (previous day), F10.7a and Ap from the bundled table (tethersim.model.air.indices),
each held inside the range MSIS is fitted for (F10.7 60-400 sfu: a day of a radio burst,
such as 707.6 sfu on 2005-09-10, takes 400).
Built once (~35 s) and kept on disk under the tethersim cache folder, keyed on the
table's UPDATED lines and the nodes.

Past the last observed day the history repeats three solar cycles earlier
(:data:`WRAP_DAYS`: the cycle-22 minimum of September 1986 to the cycle-25 minimum of
December 2019), so a lifetime longer than what the table has observed sees the same
phase of the cycle it would have seen (docs/deorbit.md).
"""
from __future__ import annotations

import functools
import hashlib
import os

import numpy as np

from tethersim.model.air import indices as _indices
from tethersim.model.air.model import AP_RANGE, F107_RANGE

#: first day of the averaged history: the minimum that began solar cycle 22 (as mc's epochs)
HISTORY_FIRST = "1986-09-01"
#: three whole solar cycles: minimum of cycle 22 (1986-09) to minimum of cycle 25 (2019-12)
WRAP_FROM, WRAP_TO = "1986-09-01", "2019-12-01"
WRAP_DAYS = int((np.datetime64(WRAP_TO, "D") - np.datetime64(WRAP_FROM, "D")).astype(int))
#: altitude nodes [m]: uniform in ln(h - HC) from 100 to 1000 km
HC = 60e3
NODES = HC + np.exp(np.linspace(np.log(40e3), np.log(940e3), 48))
#: the (LST, UT) lattice [h]
LATTICE_N, LATTICE_G = 24, 5
CHUNK_DAYS = 400  # days per pymsis call (the call's output is 11 floats a point)
VERSION = 2  # of the cached table's recipe


def lattice() -> tuple:
    """(lst, ut) [h] of the 24-point rank-1 lattice over the (LST, UT) torus."""
    k = np.arange(LATTICE_N)
    return k * (24.0 / LATTICE_N), (LATTICE_G * k % LATTICE_N) * (24.0 / LATTICE_N)


def daily_mean(first_day, n_days: int, altitudes=NODES, progress: bool | None = False) -> np.ndarray:
    """Orbit-mean NRLMSISE-00 density [kg/m^3] on each of ``n_days`` UTC days.

    Parameters
    ----------
    first_day : str or numpy.datetime64
        First UTC day (its indices must be in the bundled table, as every later day's).
    n_days : int
        Number of consecutive days.
    altitudes : array_like, optional
        Geodetic altitudes [m] on the equator (default :data:`NODES`).
    progress : bool or None, optional
        A progress bar (None: when slower than a second; False, the default: none).

    Returns
    -------
    numpy.ndarray
        Shape (n_days, len(altitudes)): the lattice mean of each day at each altitude.
    """
    import pymsis
    from tqdm.auto import tqdm

    h = np.asarray(altitudes, dtype=float)
    d0 = np.datetime64(first_day, "D")
    # a day's F10.7 above 400 sfu is a radio burst, not EUV (model.py's F107_RANGE): MSIS
    # returns NaN for 2005-09-10's 707.6 sfu, so each index is held inside its range
    ix = _indices.indices_for_days(d0, n_days)
    ix[:, :2] = np.clip(ix[:, :2], *F107_RANGE)
    ix[:, 2] = np.clip(ix[:, 2], *AP_RANGE)
    lst, ut = lattice()
    lon = (15.0 * (lst - ut)) % 360.0
    ut_ms = (ut * 3.6e6).astype(np.int64).astype("timedelta64[ms]")
    out = np.empty((n_days, h.size))
    for c in tqdm(range(0, n_days, CHUNK_DAYS), desc="orbit-mean air (once)", unit="chunk",
                  disable=progress is False, delay=0.0 if progress else 1.0, leave=False):
        m = min(CHUNK_DAYS, n_days - c)
        days = d0 + np.arange(c, c + m).astype("timedelta64[D]")
        when = days.astype("datetime64[ms]")[:, None, None] + ut_ms[None, :, None]
        shape = (m, LATTICE_N, h.size)
        when = np.broadcast_to(when, shape).ravel()
        lons = np.broadcast_to(lon[None, :, None], shape).ravel()
        hh = np.broadcast_to(h[None, None, :], shape).ravel()
        k = np.broadcast_to(np.arange(c, c + m)[:, None, None], shape).ravel()
        rho = pymsis.calculate(when, lons, np.zeros(hh.size), hh / 1e3, ix[k, 0], ix[k, 1],
                               np.repeat(ix[k, 2:3], 7, axis=1), version=0)[:, 0]
        out[c:c + m] = rho.reshape(shape).mean(axis=1)
    return out


def history_span() -> tuple:
    """(first, last) UTC day [datetime64[D]] of the averaged history."""
    t = _indices.bundled_table()
    return np.datetime64(HISTORY_FIRST, "D"), t["days"][~t["forecast"]][-1]


def _cache_path() -> str:
    from tethersim._jit import cache_base
    first, last = history_span()
    key = hashlib.sha256(repr((_indices.bundled_table()["updated"], NODES.tolist(), str(first),
                                str(last), LATTICE_N, LATTICE_G, VERSION)).encode()).hexdigest()[:16]
    return os.path.join(cache_base(), "deorbit", f"orbit-mean-{key}.npy")


def history(progress: bool | None = False) -> np.ndarray:
    """Orbit-mean densities of every day of the history, shape (days, len(NODES)).

    Row i is the day HISTORY_FIRST + i.  Read from the disk cache, or built and saved
    (about 35 s; ``progress`` as :func:`daily_mean`'s).
    """
    return _history(progress is not False)


@functools.lru_cache(maxsize=2)  # with and without a bar: the same table
def _history(bar: bool) -> np.ndarray:
    path = _cache_path()
    if os.path.exists(path):
        table = np.load(path)
    else:
        first, last = history_span()
        table = daily_mean(first, int((last - first).astype(int)) + 1,
                           progress=None if bar else False)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        tmp = f"{path}.{os.getpid()}.tmp.npy"
        np.save(tmp, table)
        os.replace(tmp, path)  # whole or absent, whichever process writes it
    table.setflags(write=False)
    return table


def history_row(day_index):
    """Row of :func:`history` for day ``day_index`` after HISTORY_FIRST (array accepted):
    the day itself while observed, else the day :data:`WRAP_DAYS` (or a multiple) earlier."""
    first, last = history_span()
    n = int((last - first).astype(int)) + 1
    i = np.asarray(day_index, dtype=np.int64)
    over = np.maximum(0, i - (n - 1))
    return i - WRAP_DAYS * ((over + WRAP_DAYS - 1) // WRAP_DAYS)
