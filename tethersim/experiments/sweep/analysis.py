"""What a finished sweep says: class counts, the stable band and its slope, map differences."""
from __future__ import annotations

import numpy as np
import xarray as xr

from tethersim.analysis.classify import CLASSES, STABLE
from tethersim.engine.result import STATUSES


def class_counts(ds: xr.Dataset) -> dict:
    """{class name: number of computed points}."""
    c = ds.stability_class.values[ds.done.values]
    return {name: int(np.sum(c == i)) for i, name in enumerate(CLASSES)}


def status_counts(ds: xr.Dataset) -> dict:
    """{engine status name: number of computed points} (tethersim.engine.result.STATUSES)."""
    from tethersim.experiments.sweep.store import status_names

    names = status_names(ds)
    return {s: int(np.sum(names == s)) for s in STATUSES}


def stable_band(ds: xr.Dataset) -> list:
    """[(x, y_low, y_high, y_centre)] per x value with stable points (2-D sweeps; edge units).

    The centre is the midpoint of the stable y values' extent; only stable
    points contiguous with the largest stable run of the column count, so an
    isolated point (thesis p. 5-19: "isolated data points") does not stretch it.
    """
    xname, yname = _axes(ds)
    y = ds[yname].values
    rows = []
    for i, x in enumerate(ds[xname].values):
        col = ds.stability_class.isel({xname: i}).values == STABLE
        if not col.any():
            continue
        lo, hi = _longest_run(col)
        rows.append((float(x), float(y[lo]), float(y[hi]), 0.5 * float(y[lo] + y[hi])))
    return rows


def band_slope(ds: xr.Dataset) -> float:
    """Least-squares slope through the origin of the band centre y against x (e.g. E2/E1)."""
    rows = [r for r in stable_band(ds) if r[0] != 0]
    if len(rows) < 2:
        return float("nan")
    x = np.array([r[0] for r in rows])
    yc = np.array([r[3] for r in rows])
    return float(np.dot(x, yc) / np.dot(x, x))


def differences(a: xr.Dataset, b: xr.Dataset) -> xr.DataArray:
    """Boolean map of points classified differently by two sweeps of the same grid."""
    if a.stability_class.shape != b.stability_class.shape:
        raise ValueError("the two sweeps have different grids")
    return (a.stability_class != b.stability_class) & a.done & b.done


def _axes(ds: xr.Dataset) -> tuple:
    dims = ds.stability_class.dims
    if len(dims) != 2:
        raise ValueError("needs a 2-D sweep")
    return dims[1], dims[0]  # (x, y): the store is (y, x)


def _longest_run(mask: np.ndarray) -> tuple:
    best, start, lo_hi = 0, None, (0, 0)
    for i, m in enumerate(np.append(mask, False)):
        if m and start is None:
            start = i
        elif not m and start is not None:
            if i - start > best:
                best, lo_hi = i - start, (start, i - 1)
            start = None
    return lo_hi
