"""Stable band, its slope and map differences on synthetic sweeps with known answers."""
from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from tethersim.analysis.classify import OFFSET, STABLE, TUMBLING
from tethersim.experiments.sweep.analysis import band_slope, class_counts, differences, stable_band


def synthetic(slope=10.0, width=0.004, isolated=True):
    """Classes on E1 x E2 with the stable band |E2 - slope E1| <= width/2."""
    e1 = np.linspace(0.001, 0.02, 20)
    e2 = np.linspace(0.0, 0.24, 241)
    E1, E2 = np.meshgrid(e1, e2)
    cls = np.where(np.abs(E2 - slope * E1) <= width / 2 + 1e-12, STABLE,
                   np.where(E2 > slope * E1, TUMBLING, OFFSET)).astype("int8")
    if isolated:
        cls[5, 10] = STABLE  # an isolated point far from the band (thesis p. 5-19)
    return xr.Dataset({"stability_class": (("E2", "E1"), cls),
                       "done": (("E2", "E1"), np.ones_like(cls, bool))},
                      coords={"E1": e1, "E2": e2})


def test_band_slope_recovers_the_synthetic_slope_despite_an_isolated_point():
    assert band_slope(synthetic(slope=10.0)) == pytest.approx(10.0, rel=1e-3)
    assert band_slope(synthetic(slope=4.0)) == pytest.approx(4.0, rel=2e-3)


def test_stable_band_edges_bracket_the_band():
    ds = synthetic(slope=10.0, width=0.004, isolated=False)
    for x, lo, hi, _centre in stable_band(ds):
        assert lo <= 10 * x <= hi
        assert hi - lo == pytest.approx(0.004, abs=0.001 + 1e-12)  # grid step 0.001


def test_class_counts_and_differences():
    a = synthetic()
    b = a.copy(deep=True)
    b.stability_class[0, 0] = STABLE if a.stability_class[0, 0] != STABLE else OFFSET
    assert int(differences(a, b).sum()) == 1
    counts = class_counts(a)
    assert sum(counts.values()) == a.stability_class.size
    assert counts["stable"] == int((a.stability_class == STABLE).sum())


def test_band_slope_is_nan_without_a_band():
    ds = synthetic()
    ds["stability_class"][:] = OFFSET
    assert np.isnan(band_slope(ds))
