"""tethersim/output/tables.py: the run's NetCDF attributes carry the satellite it was run for."""
from __future__ import annotations

import numpy as np
import xarray

import tethersim as ts


def test_netcdf_attributes_carry_the_end_body_moments_only_where_set(tmp_path):
    sat = ts.load_preset("satI")
    res = ts.simulate(sat.replace(I2=(20.0, 22.0, 5.0)), periods=0.02, progress=False)
    attrs = xarray.open_dataset(ts.write_netcdf(res, tmp_path / "a.nc"), engine="scipy").attrs
    np.testing.assert_array_equal(attrs["sat_I2"], [20.0, 22.0, 5.0])
    assert "sat_I1" not in attrs and "sat_inertia" not in attrs  # defaults: absent
    plain = ts.simulate(sat, periods=0.02, progress=False)
    attrs = xarray.open_dataset(ts.write_netcdf(plain, tmp_path / "b.nc"), engine="scipy").attrs
    assert not {"sat_I1", "sat_I2", "sat_inertia"} & set(attrs)
