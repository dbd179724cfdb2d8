"""The run summary and the NetCDF attributes name the stopping event and its located time."""
from __future__ import annotations

import xarray

import tethersim as ts
from tethersim.output.tables import to_xarray, write_netcdf


def test_a_run_stopped_by_a_limit_says_which_and_when_in_its_files(tmp_path):
    blown = ts.load_preset("satI").replace(altitude=115e3, allow_implausible=True)
    res = ts.simulate(blown, periods=0.05, progress=False)
    assert res.status == "left-domain" and res.event is not None
    summary = ts.run_summary(res)
    assert summary["event"] == res.event and summary["event time [s]"] == res.event_time
    attrs = to_xarray(res).attrs
    assert attrs["event"] == res.event and attrs["event_time"] == res.event_time
    with xarray.open_dataset(write_netcdf(res, tmp_path / "run.nc"), engine="scipy") as ds:
        assert ds.attrs["event"] == res.event and ds.attrs["event_time"] == res.event_time


def test_a_run_without_an_event_has_no_event_entries():
    res = ts.simulate(ts.load_preset("satI"), periods=0.05, progress=False)
    assert res.event is None and res.event_time is None
    assert "event" not in ts.run_summary(res) and "event" not in to_xarray(res).attrs
