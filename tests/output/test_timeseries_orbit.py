"""The time series of a circular run carries the COM orbit, computed (issue 22): the
circle r0 (cos ωt, sin ωt) of Table 4.3's start, right after the model's integrated states."""
from __future__ import annotations

import numpy as np

import tethersim as ts


def test_the_timeseries_orbit_columns_are_the_circle_of_the_satellite(tmp_path):
    sat = ts.load_preset("satII")
    res = ts.simulate(sat, periods=0.4, steps=120, method="rk4", check=False, progress=False)
    path = ts.write_timeseries(res, tmp_path / "run.csv")
    header = path.read_text().splitlines()[0].split(",")
    n = res.layout.n_state
    assert header[1:n + 1] == [f"{s} [{u}]" for s, u in zip(res.layout.state,
                                                            res.layout.state_units)]
    assert header[n + 1:n + 5] == ["X [m]", "Y [m]", "VX [m/s]", "VY [m/s]"]
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    t, r0, w = data[:, 0], sat.r0, sat.omega
    circle = np.column_stack([r0 * np.cos(w * t), r0 * np.sin(w * t),
                              -r0 * w * np.sin(w * t), r0 * w * np.cos(w * t)])
    assert np.max(np.abs(data[:, n + 1:n + 3] - circle[:, :2])) <= 1e-15 * r0 * 4
    assert np.max(np.abs(data[:, n + 3:n + 5] - circle[:, 2:])) <= 1e-15 * r0 * w * 4
    # the start of Table 4.3: on +X, moving along +Y at the circular speed
    assert np.array_equal(data[0, n + 1:n + 5], [r0, 0.0, 0.0, r0 * w])
