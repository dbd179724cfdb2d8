"""tethersim/output/tables.py: the run's NetCDF attributes carry the satellite it was run for."""
from __future__ import annotations

import numpy as np
import pytest
import xarray

import tethersim as ts
from tethersim.output.tables import to_xarray


def test_netcdf_attributes_carry_the_end_body_moments_only_where_set(tmp_path):
    sat = ts.load_preset("satI")
    res = ts.simulate(sat.replace(I2=(20.0, 22.0, 5.0)), periods=0.02, progress=False)
    attrs = xarray.open_dataset(ts.write_netcdf(res, tmp_path / "a.nc"), engine="scipy").attrs
    np.testing.assert_array_equal(attrs["sat_I2"], [20.0, 22.0, 5.0])
    assert "sat_I1" not in attrs and "sat_inertia" not in attrs  # defaults: absent
    plain = ts.simulate(sat, periods=0.02, progress=False)
    attrs = xarray.open_dataset(ts.write_netcdf(plain, tmp_path / "b.nc"), engine="scipy").attrs
    assert not {"sat_I1", "sat_I2", "sat_inertia"} & set(attrs)


@pytest.mark.parametrize("how", ["thesis", "implausible-with-moments"])
def test_netcdf_reads_back_as_xarray_would_have_written_it(tmp_path, how):
    """write_netcdf calls scipy's netCDF-3 writer itself (no xarray import at run time):
    the file must read back identical, attributes included, to xarray's own file."""
    sat = ts.load_preset("satI")
    if how == "thesis":
        res = ts.simulate(sat, periods=0.02, progress=False)
    else:  # an array attribute (I2) and an implausible input (already compiled kernels:
        # a 16-state model here cost 11 s of cold compile in the fast tier)
        odd = sat.replace(I2=(20.0, 22.0, 5.0), allow_implausible=True, m3=2e5)
        res = ts.simulate(odd, periods=0.02, progress=False)
        assert res.satellite.implausible
    extra = {"note": "θ, δx: ±0.05 rad", "count": 3, "flag": True}  # unicode, int, bool
    ours = xarray.open_dataset(ts.write_netcdf(res, tmp_path / "ours.nc", extra), engine="scipy")
    to_xarray(res, extra).to_netcdf(tmp_path / "xr.nc", engine="scipy")
    theirs = xarray.open_dataset(tmp_path / "xr.nc", engine="scipy")
    xarray.testing.assert_identical(ours.load(), theirs.load())
    assert ours.attrs["note"] == extra["note"]
    for k, v in theirs.attrs.items():  # same attribute types, not only equal values
        assert type(ours.attrs[k]) is type(v), k
