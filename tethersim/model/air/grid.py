"""NRLMSISE-00 on a grid, interpolated in compiled code.

MSIS (pymsis, ``version=0``) is called once per run on a grid and the integrator
reads the density from :func:`msis_density_kernel`, a numba function of plain
floats and arrays.  Along a planar equatorial orbit (latitude 0) the density is a
function of altitude, local solar time and universal time, and only the first
two change quickly (a body sweeps all local times once an orbit).  The grid is
therefore laid out in

* altitude ``h`` -- uniform in ``x = ln(h - hc)`` (steps grow with altitude, fine
  across the lower thermosphere's kink at 120 km where MSIS joins its two
  temperature profiles), Catmull-Rom cubic in log density;
* local solar time ``lst = UT + lon/15`` (h, the argument pymsis itself derives
  from longitude and UT) -- uniform, periodic, Catmull-Rom cubic in log density;
* time -- UTC days of the run, each split into ``n_t`` uniform steps,
  Catmull-Rom cubic in log density, periodic within the day.  At fixed local
  time the density still changes with UT through MSIS's longitude and UT terms
  (longitude = 15 (lst - UT) sweeps the globe once a day).  MSIS takes the day
  of year as an integer and its UT terms are 24-h periodic, so within one UTC
  day the density is a periodic function of UT, and it steps at midnight (the
  day of year and the table's daily F10.7/Ap change).  Each day has its own
  nodes, evaluated with its own date and indices, so the steps at midnight are
  reproduced exactly as pymsis makes them.

The grid's shape is ``(n_days, n_t, n_lst, n_h)``.  The kernel reads one flat
float array, the *table*: the axes (:data:`AXES_FIELDS`) and then the grid in C
order (:func:`pack`), so that a compiled loop carries the whole atmosphere in
one borrowed array, at any offset.  Catmull-Rom is C¹, so an adaptive
integrator sees no kinks in ρ.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from tethersim.model.air.indices import DAY

#: the MSIS altitude range tethersim accepts [m]
H_MIN = 80e3
H_MAX = 1000e3
#: default grid (docs/air.md): altitude axis uniform in x = ln(h - HC) with step DX
#: (1.8 km at 120 km, 28 km at 1000 km), local-time nodes per 24 h, time steps per day
DX = 0.03
HC = 60e3
N_LST = 24
N_T = 8
#: order of the entries of ``axes``
AXES_FIELDS = ("x0", "dx", "n_h", "n_lst", "ut0", "dt", "n_t", "n_days", "h_min", "h_max", "hc")
N_AXES = len(AXES_FIELDS)


@njit(cache=True)
def _catmull_rom(u):
    """Catmull-Rom weights of the nodes i-1, i, i+1, i+2 at fraction u in [0, 1)."""
    u2 = u * u
    u3 = u2 * u
    return (0.5 * (-u3 + 2.0 * u2 - u),
            0.5 * (3.0 * u3 - 5.0 * u2 + 2.0),
            0.5 * (-3.0 * u3 + 4.0 * u2 + u),
            0.5 * (u3 - u2))


@njit(cache=True)
def _plane(table, base, j, wl0, wl1, wl2, wl3, i, wh0, wh1, wh2, wh3, n_lst, n_h):
    """Bicubic (local time x altitude) log density on one time node (its first entry at base)."""
    acc = 0.0
    for a in range(4):
        jj = (j - 1 + a) % n_lst
        wl = wl0 if a == 0 else (wl1 if a == 1 else (wl2 if a == 2 else wl3))
        r = base + jj * n_h + i
        row = (wh0 * table[r - 1] + wh1 * table[r] + wh2 * table[r + 1] + wh3 * table[r + 2])
        acc += wl * row
    return acc


@njit(cache=True)
def msis_density_kernel(h, lon, t, table, o):
    """NRLMSISE-00 mass density [kg/m^3] interpolated from a packed grid.

    Parameters
    ----------
    h : float
        Geodetic altitude [m] (equator: radius minus the WGS-84 equatorial radius).
    lon : float
        East longitude [rad], any branch.
    t : float
        Time since the grid's epoch [s].
    table : numpy.ndarray
        Flat float array holding the packed grid (:func:`pack`) from index ``o``.
    o : int
        Offset of the packed grid in ``table``.

    Returns
    -------
    float
        Density [kg/m^3]; NaN outside the altitude range or the grid's days.
    """
    x0 = table[o]
    dx = table[o + 1]
    n_h = int(table[o + 2])
    n_lst = int(table[o + 3])
    ut0 = table[o + 4]
    dt = table[o + 5]
    n_t = int(table[o + 6])
    n_days = int(table[o + 7])
    hc = table[o + 10]
    if not (h >= table[o + 8] and h <= table[o + 9]) or not (math.isfinite(lon)
                                                             and math.isfinite(t)):
        return np.nan
    s = ut0 + t  # seconds since 00:00 UTC of the epoch's day
    d = int(math.floor(s / DAY))
    if d < 0 or d >= n_days:
        return np.nan
    u = s - d * DAY
    k = min(int(u / dt), n_t - 1)
    ft = u / dt - k
    xh = (math.log(h - hc) - x0) / dx
    i = int(xh)
    wh0, wh1, wh2, wh3 = _catmull_rom(xh - i)
    lst = (u / 3600.0 + lon * (12.0 / math.pi)) % 24.0  # local solar time [h]
    xl = lst * n_lst / 24.0
    j = int(xl)
    wl0, wl1, wl2, wl3 = _catmull_rom(xl - j)
    if j >= n_lst:  # lst rounded up to 24.0
        j -= n_lst
    wt0, wt1, wt2, wt3 = _catmull_rom(ft)
    plane = n_lst * n_h
    first = o + N_AXES + d * n_t * plane
    out = 0.0
    for a in range(4):
        w_t = wt0 if a == 0 else (wt1 if a == 1 else (wt2 if a == 2 else wt3))
        kk = (k - 1 + a) % n_t  # periodic in UT within the day
        out += w_t * _plane(table, first + kk * plane, j, wl0, wl1, wl2, wl3,
                            i, wh0, wh1, wh2, wh3, n_lst, n_h)
    return math.exp(out)


def pack(grid: np.ndarray, axes: np.ndarray) -> np.ndarray:
    """The flat table :func:`msis_density_kernel` reads: ``axes``, then ``grid`` in C order."""
    grid = np.asarray(grid, float)
    if axes.size != N_AXES or grid.shape != tuple(int(axes[i]) for i in (7, 6, 3, 2)):
        raise ValueError(f"grid shape {grid.shape} does not match its axes")
    return np.concatenate([np.asarray(axes, float), grid.ravel()])


@njit(cache=True)
def longitude_of(angle, t, theta0, omega_earth):
    """East longitude [rad, -pi..pi) of an equatorial point at inertial polar angle ``angle``.

    Parameters
    ----------
    angle : float
        Polar angle of the point in the inertial equatorial plane [rad], from the
        x axis (the vernal equinox: the direction of Greenwich at sidereal angle 0).
    t : float
        Time since the epoch [s].
    theta0 : float
        Greenwich sidereal angle at the epoch [rad] (:func:`gmst`).
    omega_earth : float
        Earth's rotation rate [rad/s].
    """
    lam = angle - theta0 - omega_earth * t
    return (lam + math.pi) % (2.0 * math.pi) - math.pi


@njit(cache=True)
def longitude_kernel(x, y, t, theta0, omega_earth):
    """East longitude [rad, -pi..pi) of an equatorial point from its inertial position.

    Parameters
    ----------
    x, y : float
        Inertial position in the equatorial plane [m] (axes of :func:`longitude_of`).
    t, theta0, omega_earth : float
        As :func:`longitude_of`.
    """
    return longitude_of(math.atan2(y, x), t, theta0, omega_earth)


def gmst(epoch) -> float:
    """Greenwich mean sidereal angle [rad] at a UTC instant (IAU-82, Vallado Eq 3-45).

    UT1 is taken equal to UTC (|UT1 - UTC| < 0.9 s: < 4e-3 deg of longitude).
    """
    jd = (np.datetime64(epoch, "ms") - np.datetime64("2000-01-01T12:00", "ms")) / np.timedelta64(1, "D")
    tu = jd / 36525.0
    sec = (67310.54841 + (876600.0 * 3600.0 + 8640184.812866) * tu
           + 0.093104 * tu ** 2 - 6.2e-6 * tu ** 3)
    return float(np.deg2rad((sec % 86400.0) / 240.0))


def build_grid(epoch, n_days, daily_indices, dx=DX, n_lst=N_LST, n_t=N_T, hc=HC):
    """Evaluate NRLMSISE-00 (pymsis, version 0) on the interpolation grid.

    Parameters
    ----------
    epoch : numpy.datetime64
        UTC instant of t = 0.
    n_days : int
        UTC days the grid covers, from the epoch's day.
    daily_indices : callable
        ``daily_indices(first_day, n_days) -> array (n_days, 3)`` of f107, f107a, ap.
    dx : float
        Step of the altitude coordinate ``ln(h - hc)`` [-].
    n_lst : int
        Local-time nodes per 24 h.
    n_t : int
        Time steps per day.
    hc : float
        Offset of the altitude coordinate [m], below ``H_MIN``.

    Returns
    -------
    grid, axes : numpy.ndarray
        ``log(rho)`` on the nodes, shape (n_days, n_t, n_lst, n_h), and the
        axes in the order of :data:`AXES_FIELDS` (:func:`pack` joins them).
        The grid depends on the epoch's UTC day only (:func:`grid_values`), the
        axes on its time of day too (:func:`grid_axes`).
    """
    day0 = np.datetime64(epoch, "ms").astype("datetime64[D]")
    return (grid_values(day0, daily_indices(day0, n_days), dx, n_lst, n_t, hc),
            grid_axes(epoch, n_days, dx, n_lst, n_t, hc))


def _altitude_nodes(dx: float, hc: float) -> tuple:
    """(x0, n_h): the first node of ``ln(h - hc)`` and the node count (1 below, 2 above)."""
    x0 = math.log(H_MIN - hc) - dx
    return x0, int(math.ceil((math.log(H_MAX - hc) - x0) / dx)) + 3


def seconds_into_day(epoch) -> float:
    """Seconds from the start of ``epoch``'s UTC day to ``epoch`` [s]."""
    epoch = np.datetime64(epoch, "ms")
    return float((epoch - epoch.astype("datetime64[D]")) / np.timedelta64(1, "s"))


def grid_axes(epoch, n_days, dx=DX, n_lst=N_LST, n_t=N_T, hc=HC) -> np.ndarray:
    """The axes of :func:`build_grid`'s grid for a run from ``epoch`` (:data:`AXES_FIELDS`)."""
    x0, n_h = _altitude_nodes(dx, hc)
    return np.array([x0, dx, n_h, n_lst, seconds_into_day(epoch), DAY / n_t, n_t, n_days,
                     H_MIN, H_MAX, hc], float)


def grid_values(day0, indices, dx=DX, n_lst=N_LST, n_t=N_T, hc=HC) -> np.ndarray:
    """``log(rho)`` of NRLMSISE-00 on the grid nodes from UTC day ``day0``.

    Parameters
    ----------
    day0 : numpy.datetime64
        The first UTC day.
    indices : numpy.ndarray
        (n_days, 3): f107, f107a, ap of each day.
    dx, n_lst, n_t, hc : as :func:`build_grid`.

    Returns
    -------
    numpy.ndarray
        Shape (n_days, n_t, n_lst, n_h): each day's :func:`day_values`.
    """
    day0 = np.datetime64(day0, "D")
    ind = np.asarray(indices, float)
    return np.stack([day_values(day0 + np.timedelta64(d, "D"), *ind[d], dx, n_lst, n_t, hc)
                     for d in range(ind.shape[0])])


def day_values(day, f107, f107a, ap, dx=DX, n_lst=N_LST, n_t=N_T, hc=HC) -> np.ndarray:
    """``log(rho)`` on the nodes of one UTC day with that day's indices, shape
    (n_t, n_lst, n_h): a day's nodes depend on nothing else (module docstring)."""
    import pymsis

    x0, n_h = _altitude_nodes(dx, hc)
    alts_km = (hc + np.exp(x0 + dx * np.arange(n_h))) / 1e3
    lst = 24.0 * np.arange(n_lst) / n_lst
    out = np.empty((n_t, n_lst, n_h))
    aps = np.full((1, 7), ap)
    for k in range(n_t):
        ut_h = 24.0 * k / n_t
        when = np.datetime64(day, "D").astype("datetime64[ms]") \
            + np.timedelta64(int(round(ut_h * 3.6e6)), "ms")
        lons = ((lst - ut_h) * 15.0) % 360.0
        rho = pymsis.calculate(when, lons, 0.0, alts_km, f107, f107a, aps, version=0)
        out[k] = np.log(rho[0, :, 0, :, 0].astype(float))  # (n_lst, n_h)
    return out
