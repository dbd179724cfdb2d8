"""NRLMSISE-00 through tethersim equals pymsis's own output; record validation.

pymsis returns float32 densities; the wrapper only converts units (m -> km,
rad -> deg, seconds since the epoch -> UTC instant), so the tolerance is float32
round-off, 1e-6 relative.
"""
from __future__ import annotations

import numpy as np
import pymsis
import pytest

from tethersim.model import atmosphere
from tethersim.model.air import AirModel, air_density
from tethersim.model.air.model import msis_direct

FLOAT32_REL = 1e-6

CASES = [  # epoch, altitude [m], t [s], east longitude [rad], (f107, f107a, ap)
    ("2017-06-23T00:00:00", 200e3, 0.0, 0.0, (150.0, 150.0, 4.0)),
    ("2017-06-23T00:00:00", 200e3, 5400.0, 2.5, (70.0, 70.0, 4.0)),
    ("2003-10-29T12:30:00", 450e3, 7200.0, -1.2, (250.0, 200.0, 150.0)),
    ("2020-01-01T23:00:00", 120e3, 7200.0, 3.0, (68.0, 71.0, 2.0)),   # crosses midnight
    ("1995-03-21T06:00:00", 995e3, 100.0, -3.1, (90.0, 95.0, 20.0)),
]


@pytest.mark.parametrize("epoch, h, t, lon, idx", CASES)
def test_wrapper_equals_pymsis(epoch, h, t, lon, idx):
    f107, f107a, ap = idx
    air = AirModel("nrlmsise00", epoch, f107, f107a, ap)
    when = np.datetime64(epoch, "ms") + np.timedelta64(int(t * 1e3), "ms")
    ref = pymsis.calculate(when, np.rad2deg(lon), 0.0, h / 1e3, f107, f107a, [[ap] * 7],
                           version=0)[..., 0].item()
    assert air_density(air, h, t, lon) == pytest.approx(ref, rel=FLOAT32_REL)


def test_spaceweather_days_use_their_own_indices():
    """Across midnight the wrapper switches to the next day's table row, as pymsis does."""
    air = AirModel("nrlmsise00", "2003-10-28T22:00:00", indices="spaceweather")
    t = 4 * 3600.0  # 2003-10-29T02:00
    ref = pymsis.calculate(np.datetime64("2003-10-29T02:00"), 30.0, 0.0, 300.0,
                           # 10-28 F10.7 obs, 10-29 ctr81 obs, 10-29 Ap (SW-All.txt)
                           *_table("2003-10-29"), version=0)[..., 0].item()
    assert air_density(air, 300e3, t, np.deg2rad(30.0)) == pytest.approx(ref, rel=FLOAT32_REL)


def _table(day):
    from tethersim.model.air.indices import indices_for_day
    d = indices_for_day(day)
    return d.f107, d.f107a, [[d.ap] * 7]


def test_longitude_branch_does_not_matter():
    air = AirModel("nrlmsise00", "2017-06-23T00:00:00", 150.0, 150.0, 4.0)
    assert msis_direct(air, 300e3, 10.0, 1.0) == msis_direct(air, 300e3, 10.0, 1.0 - 2 * np.pi)


def test_vallado_kind_is_the_thesis_table():
    for h in (120e3, 200e3, 650e3):
        assert air_density(AirModel(), h) == atmosphere.density(h)


@pytest.mark.parametrize("fields, message", [
    (dict(kind="jacchia"), r"^kind = 'jacchia' is not one of vallado, nrlmsise00$"),
    (dict(f107=30.0), r"^f107 = 30 sfu is outside 60-400 sfu$"),
    (dict(f107a=500.0), r"^f107a = 500 sfu is outside 60-400 sfu$"),
    (dict(ap=-1.0), r"^ap = -1 is outside 0-400$"),
    (dict(ap="high"), r"^ap = 'high' is not a number"),
    (dict(epoch="next tuesday"), r"^epoch 'next tuesday' is not an ISO date-time"),
    (dict(indices="nasa"), r"^indices = 'nasa' is not one of fixed, spaceweather$"),
    (dict(f107=None), r"^f107 is missing"),
    (dict(indices="spaceweather"), r"^f107 = 150.0 differs from the spaceweather table"),
    (dict(indices="spaceweather", f107=None, f107a=None, ap=None, epoch="2050-01-01"),
     r"^epoch: day 2050-01-01 is outside the bundled space-weather table"),
])
def test_bad_records_give_one_line_errors(fields, message):
    base = dict(kind="nrlmsise00", epoch="2017-06-23T00:00:00", f107=150.0, f107a=150.0, ap=4.0)
    with pytest.raises(ValueError, match=message) as err:
        AirModel(**{**base, **fields})
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("kind, h", [("nrlmsise00", 79e3), ("nrlmsise00", 1001e3),
                                     ("vallado", -1.0), ("vallado", 1001e3)])
def test_altitude_outside_the_model_is_refused(kind, h):
    air = AirModel(kind, f107=150.0, f107a=150.0, ap=4.0)
    with pytest.raises(ValueError, match=r"^altitude = .* km is outside .* km \(" + kind):
        air_density(air, h)


def test_record_is_hashable_and_normalised():
    a = AirModel("nrlmsise00", "2017-06-23T00:00:00", 150, 150, 4)
    b = AirModel("nrlmsise00", np.datetime64("2017-06-23T00:00"), 150.0, 150.0, 4.0)
    assert a == b and hash(a) == hash(b)
    assert a.epoch.dtype == np.dtype("datetime64[s]") and isinstance(a.f107, float)


def test_replace_rereads_the_table_for_a_new_epoch():
    air = AirModel("nrlmsise00", "2017-06-23T00:00:00", indices="spaceweather")
    moved = air.replace(epoch="2003-10-29T00:00:00")
    assert moved.ap > 200 and moved.epoch == np.datetime64("2003-10-29T00:00:00")
    fixed = air.replace(indices="fixed", f107=200.0)
    assert (fixed.f107, fixed.f107a, fixed.ap) == (200.0, air.f107a, air.ap)
    back = fixed.replace(indices="spaceweather")
    assert back == air
