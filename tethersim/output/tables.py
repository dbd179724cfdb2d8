"""The one table writer: CSV with units in the headers and floats that round-trip.

Every CSV tethersim writes (time series, compare, force peaks, headlines,
sweeps, feasibility) goes through :func:`write_table`, so they share one rule:

* headers carry the unit in brackets (``settling time [h]``);
* floats are written with ``repr`` (shortest string that reads back to the
  same double), NaN and None as an empty cell, booleans as ``true``/``false``;
* rows are dicts; ``columns`` is an explicit tuple of (key, header) pairs.

The time series of a run also goes to NetCDF (:func:`write_netcdf`), with the
same names and units as attributes.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from tethersim.engine.dynamics import held_circle
from tethersim.engine.result import ORBIT_COLUMNS, ORBIT_UNITS, SimResult
from tethersim.model.plausibility import allowed_problems
from tethersim.output.files import replacing


def cell(value) -> str:
    """One CSV cell: repr for floats (round-trips), '' for NaN/None, true/false for bools."""
    if value is None:
        return ""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (float, np.floating)):
        v = float(value)
        return "" if math.isnan(v) else repr(v)
    if isinstance(value, (np.integer,)):
        return str(int(value))
    return str(value)


def write_table(path, rows, columns) -> Path:
    """Write ``rows`` (dicts) as CSV.

    Parameters
    ----------
    path : str or Path
        File to write.
    rows : iterable of dict
        One dict per row; every key of ``columns`` must be present.
    columns : sequence of (str, str)
        (key, header with unit) pairs, in column order.

    Returns
    -------
    Path
        The file written.

    Examples
    --------
    >>> import tempfile, tethersim as ts
    >>> path = ts.write_table(tempfile.mkdtemp() + "/t.csv", [{"h": 0.1, "ok": True}],
    ...                       (("h", "settling time [h]"), ("ok", "stable")))
    >>> path.read_text().splitlines()
    ['settling time [h],stable', '0.1,true']
    """
    path = Path(path)
    with replacing(path) as tmp, tmp.open("w", newline="") as fh:  # complete or absent
        w = csv.writer(fh)
        w.writerow([header for _, header in columns])
        for r in rows:
            w.writerow([cell(r[key]) for key, _ in columns])
    return path


def write_rows(path, rows) -> Path:
    """Write dict rows whose keys name their units (``settling_h``, ``step_s``).

    Columns are the union of the keys in first-seen order; private keys (a
    leading underscore: arrays kept for plots) are left out; a missing key is
    an empty cell.
    """
    rows = list(rows)
    keys = [k for k in dict.fromkeys(k for r in rows for k in r) if not k.startswith("_")]
    return write_table(path, ({k: r.get(k) for k in keys} for r in rows),
                       tuple((k, k) for k in keys))


def timeseries_columns(res: SimResult) -> tuple:
    """(name, unit) of every column of a run's time series, time first."""
    return tuple((n, u) for n, _, u in _columns(res))


def _columns(res: SimResult) -> list:
    """[(name, values, unit)] of a run's time series: t, the integrated state (and the
    COM orbit of a circular-orbit model, its closed form: SimResult.orbit), then, for a
    free orbit, the derived altitude, osculating elements and air densities
    (tethersim.analysis.free_orbit), then the tension of tethers 1 and 2."""
    from tethersim.analysis.free_orbit import free_orbit_series  # numba: only when writing one
    from tethersim.analysis.tethers import segment_tensions

    lay = res.layout
    cols = [("t", res.t, "s")] + [(n, res.states[:, i], u)
                                  for i, (n, u) in enumerate(zip(lay.state, lay.state_units))]
    if held_circle(lay.index):
        orbit = res.orbit
        cols += [(n, orbit[:, i], u) for i, (n, u) in enumerate(zip(ORBIT_COLUMNS, ORBIT_UNITS))]
    # the tethers' tensions, the model's own (SimResult.tether_tensions; zero while slack)
    tension = res.tether_tensions()
    # a bead chain's segments, boom end first (tethersim.analysis.tethers.segment_tensions)
    segments = segment_tensions(res)
    return (cols + free_orbit_series(res)
            + [(f"tension_{j + 1}", tension[:, j], "N") for j in range(2)]
            + [(f"tension_{j + 1}_{s + 1}", segments[:, j, s], "N") for j in range(2)
               for s in range(segments.shape[2])])


def write_timeseries(res: SimResult, path) -> Path:
    """Write a run's samples as CSV (SI units in the headers).

    Parameters
    ----------
    res : SimResult
        The run.
    path : str or Path
        File to write.

    Returns
    -------
    Path
        The file: a column ``t [s]``, one per state of the model, and for a
        circular-orbit model the COM's X, Y [m], VX, VY [m/s]; for a free orbit
        the COM's altitude [m], osculating semi_major_axis [m] and eccentricity [1]
        and the air density at each body, rho_tip_mass, rho_bus, rho_balloon
        [kg/m^3] (tethersim.analysis.free_orbit); last the tethers' tensions
        tension_1, tension_2 [N] (the model's spring tension, zero while slack; a bead
        chain's most stretched segment's), and for a bead chain each segment's,
        tension_1_1 ... tension_2_{N+1} [N], boom end first (its bead positions
        x_1_1, y_1_1, ... are states).

    Examples
    --------
    >>> import tempfile, tethersim as ts
    >>> res = ts.simulate(ts.load_preset("satI"), periods=0.1, progress=False)
    >>> p = ts.write_timeseries(res, tempfile.mkdtemp() + "/run.csv")
    >>> p.read_text().splitlines()[0][:30]
    't [s],delta_x [m],delta_y [m],'
    """
    columns = _columns(res)
    data = np.column_stack([v for _, v, _ in columns])
    rows = ({n: v for (n, _, _), v in zip(columns, row)} for row in data)
    return write_table(path, rows, tuple((n, f"{n} [{u}]") for n, _, u in columns))


def _series(res: SimResult, attrs: dict | None = None) -> tuple:
    """(columns, global attributes) of a run's time series: [(name, values, units)] with
    ``t`` first, and the run's and satellite's metadata; what to_xarray and write_netcdf hold."""
    columns = _columns(res)
    found = allowed_problems(res.satellite, res.method)
    meta = {"satellite": res.satellite.name, "model": res.model, "method": res.method,
            "label": res.label, "status": res.status, "message": res.message,
            # the stopping limit that ended the run, and its located time (engine/events.py)
            **({"event": res.event, "event_time": res.event_time} if res.event else {}),
            **({"implausible_inputs": "; ".join(found)} if found else {}),
            "conventions": "docs/conventions.md: local frame rotating with omega z, "
                           "COM moves along -x, theta from +y towards +x"}
    for k, v in res.satellite.to_dict().items():
        if isinstance(v, (int, float, str)):
            meta[f"sat_{k}"] = v
        elif k in ("I1", "I2"):  # end-body moments [roll, pitch, yaw] kg m^2, where set
            meta[f"sat_{k}"] = np.asarray(v, dtype=float)
    # the density the run used, also when the orbit chose it (to_dict leaves it out then)
    meta["sat_density_mode"] = res.satellite.density_mode
    meta.update(attrs or {})
    return columns, meta


def to_xarray(res: SimResult, attrs: dict | None = None):
    """The run's time series as an xarray Dataset (units as attributes)."""
    import xarray as xr

    ((_, t, _), *columns), meta = _series(res, attrs)
    data = {n: ("t", v, {"units": u}) for n, v, u in columns}
    return xr.Dataset(data, coords={"t": ("t", t, {"units": "s"})}, attrs=meta)


def _nc3_attribute(value):
    """A netCDF-3 attribute as xarray encodes one: text as UTF-8, numbers as 1-D arrays
    of the classic types (int64 to int32, booleans to int8)."""
    if isinstance(value, str):
        return value.encode("utf-8")
    a = np.atleast_1d(np.asarray(value))
    if a.dtype == bool:
        return a.astype(np.int8)
    if a.dtype.kind in "iu":
        if np.any(a != a.astype(np.int32)):
            raise ValueError(f"attribute {value!r} does not fit netCDF-3's 32-bit integers")
        return a.astype(np.int32)
    return a  # floats keep their width, as in xarray


def write_netcdf(res: SimResult, path, attrs: dict | None = None) -> Path:
    """Write the time series as NetCDF-3 (64-bit offsets), readable by xarray and netCDF4.

    Parameters
    ----------
    res : SimResult
        The run; its status, message, model and satellite go into the attributes.
    path : str or Path
        File to write.
    attrs : dict, optional
        More global attributes.

    Returns
    -------
    Path
        The file written: what ``to_xarray(res, attrs).to_netcdf(path, engine="scipy")``
        writes, read back identically (tests/output/test_tables.py).

    Notes
    -----
    scipy's netCDF writer is called directly, the engine xarray itself would use:
    through xarray, the import and its backend discovery took ~0.5 s of a warm
    ``tethersim run`` for a 3 ms write.

    Examples
    --------
    >>> import tempfile, xarray, tethersim as ts
    >>> res = ts.simulate(ts.load_preset("satI"), periods=0.1, progress=False)
    >>> p = ts.write_netcdf(res, tempfile.mkdtemp() + "/run.nc")
    >>> xarray.open_dataset(p, engine="scipy").attrs["status"]
    'ok'
    """
    from scipy.io import netcdf_file

    path = Path(path)
    for k, v in (attrs or {}).items():  # what netCDF-3 attributes can hold, else scipy's KeyError
        if not (isinstance(k, str) and isinstance(v, (str, bool, int, float, np.number))):
            raise TypeError(f"attrs[{k!r}] = {v!r:.40}: a netCDF attribute is a str key with a "
                            f"str, int, float or bool value")
    columns, meta = _series(res, attrs)
    with replacing(path) as tmp, netcdf_file(tmp, "w", version=2) as f:
        f.createDimension("t", columns[0][1].size)
        for name, values, units in columns:
            var = f.createVariable(name, "d", ("t",))
            var[:] = values
            var.units = _nc3_attribute(units)
        for k, v in meta.items():
            setattr(f, k, _nc3_attribute(v))
    return path
