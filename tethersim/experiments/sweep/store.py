"""The on-disk, labelled, resumable store of a sweep: an xarray data set in Zarr.

Layout: one variable per record field (tethersim.experiments.sweep.point.VARIABLES) on the
grid dimensions (second axis, first axis) — or (first axis,) for a 1-D
sweep — with coordinates in edge units, a ``done`` mask, and the spec as JSON
in the attributes.  Chunks are whole grid rows, about ``CHUNK_POINTS`` points
each, and a flush rewrites whole chunks that gained points from the copy in
memory (never a read-modify-write).  A sweep of up to ``CHUNK_POINTS`` points is
one chunk per variable: with one chunk per row, a 12 x 12 sweep spent 0.2 s
creating and 0.18 s flushing its 16 x 12 chunk files, as long as its 144
five-orbit runs took on two cores.

Crash safety: within a flush every data variable is written before ``done``,
and Zarr writes each chunk to a temporary file that it then renames, so a
kill at any instant leaves ``done`` true only where the data are on disk.
A kill loses at most the points finished since the last flush (every
``FLUSH_SECONDS``); Ctrl-C loses nothing (the runner flushes first).

One writer at a time (tethersim.experiments.sweep.lock), and a resume verifies the store
(tethersim.experiments.sweep.verify): unreadable chunks and points whose ``checksum``
does not match their data are recomputed, with a StoreRepaired warning.
"""
from __future__ import annotations

import json
import os
import shutil
import threading
import warnings
from pathlib import Path

import numpy as np
import xarray as xr
import zarr

from tethersim._jit import CACHE_KEY
from tethersim._version import __version__
from tethersim.analysis.classify import flag_attrs
from tethersim.engine.result import STATUSES
from tethersim.experiments.sweep.lock import StoreLock
from tethersim.experiments.sweep.point import VARIABLES
from tethersim.experiments.sweep.spec import SweepSpec
from tethersim.experiments.sweep.verify import StoreDamaged, checksums, read_verified
from tethersim.model import params

FILL = {"float64": np.nan, "int8": -1, "int64": -1}
CHUNK_POINTS = 4096  # points per chunk, in whole grid rows (module docstring)


def code_id() -> str:
    """tethersim's version and the hash of every jitted source (the numba cache key): a
    store resumes only with the code that began it, so a data set never mixes two models."""
    return f"{__version__}+{CACHE_KEY[:12]}"


class StoreMismatch(ValueError):
    """The store on disk holds a different sweep."""


class StoreRepaired(UserWarning):
    """Damaged points of a resumed store were found and will be recomputed."""


def _empty_dataset(spec: SweepSpec) -> xr.Dataset:
    dims = tuple(reversed(spec.names))
    coords = {name: (name, np.asarray(values),
                     {"units": params.unit(name), "long_name": f"{name} (edge units)"})
              for name, values in spec.axes}
    data = {}
    for name, dtype, units, long_name in VARIABLES:
        attrs = {"units": units, "long_name": long_name}
        if name == "stability_class":
            attrs.update(flag_attrs())
        if name == "status":  # a failed point says why: its status, not a bare NaN row
            attrs.update(status_attrs())
        data[name] = (dims, np.full(spec.shape, FILL[dtype], dtype=dtype), attrs)
    data["checksum"] = (dims, np.full(spec.shape, -1, dtype=np.int64),
                        {"long_name": "FNV-1a hash of the point's record "
                                      "(tethersim.experiments.sweep.verify)"})
    data["done"] = (dims, np.zeros(spec.shape, dtype=bool), {"long_name": "point computed"})
    attrs = {"title": f"tethersim sweep of {spec.satellite.name} over {' x '.join(spec.names)}",
             "spec": spec.to_json(), "tethersim_version": __version__, "code": code_id(),
             "conventions": "docs/conventions.md; metrics and classes: docs/metrics.md"}
    return xr.Dataset(data, coords=coords, attrs=attrs)


class SweepStore:
    """In-memory copy of a sweep's arrays, flushed row by row to a Zarr store."""

    def __init__(self, path, spec: SweepSpec, restart: bool = False):
        self.path = Path(path)
        self.spec = spec
        self.zarrays = None  # name -> the open Zarr array (_open_arrays)
        self._creating, self._create_error = None, None
        self.lock = StoreLock(self.path).acquire()  # before looking: no second writer
        try:
            self._open(restart)
        except BaseException:
            self.lock.release()
            raise

    def close(self) -> None:
        """Release the writer lock (the data stay readable), once a new store is written."""
        try:
            if self._creating is not None:
                self._creating.join()
        finally:
            self.lock.release()

    def _open(self, restart: bool) -> None:
        spec = self.spec
        exists = (self.path / "zarr.json").exists() or (self.path / ".zgroup").exists()
        if exists and not restart:
            try:  # consolidated: the store always has it, so its absence is damage too
                on_disk = xr.open_zarr(self.path, consolidated=True)
            except Exception as exc:  # noqa: BLE001 - unreadable metadata, whatever the cause
                raise StoreDamaged(f"{self.path}: the store's metadata is damaged "
                                   f"({type(exc).__name__}: {' '.join(str(exc).split())}); "
                                   f"run again with --restart to discard it") from None
            if on_disk.attrs.get("spec") != spec.to_json():
                raise StoreMismatch(
                    f"{self.path} holds a different sweep ({_differences(on_disk.attrs.get('spec'), spec)}); "
                    f"use another --out, or --restart to discard it")
            if on_disk.attrs.get("code") != code_id():
                raise StoreMismatch(
                    f"{self.path} was begun by another tethersim build "
                    f"({on_disk.attrs.get('code')}, this is {code_id()}): its points would not "
                    f"match new ones; use another --out, or --restart to discard it")
            _check_status_codes(on_disk, self.path)
            if "checksum" not in on_disk:
                raise StoreMismatch(f"{self.path} has no per-point checksums (an older tethersim): "
                                    f"use --restart to discard it")
            chunk_rows = on_disk["done"].encoding["chunks"][0] if len(spec.shape) == 2 else 1
            on_disk.close()
            self.arrays = self._read_verified()
        else:
            damaged = (self.path / ".zmetadata").exists()  # a store that lost its .zgroup
            if self.path.exists() and any(self.path.iterdir()) and not exists and not (
                    restart and damaged):
                if damaged:
                    raise StoreDamaged(f"{self.path}: the store's metadata is damaged (no "
                                       f".zgroup); run again with --restart to discard it")
                raise StoreMismatch(f"{self.path} exists and is not a sweep store; choose another --out")
            chunk_rows = chunk_rows_for(spec.shape)
            ds = _empty_dataset(spec)
            self.arrays = {v: ds[v].values.reshape(-1).copy() for v in _stored()}
            # written on a thread: the first points compute (without the GIL) while Zarr
            # writes the empty store, a serial ~0.2 s that bounded short sweeps; every
            # flush, the lock's release and dataset() wait for it (_created)
            self._creating = threading.Thread(target=self._create, args=(ds, chunk_rows),
                                              name="tethersim-store-create")
            self._creating.start()
        self.row = spec.shape[-1]  # points per grid row
        self.chunk_rows = chunk_rows
        self.dirty = set()  # chunks (chunk_rows grid rows each) that gained points

    def _create(self, ds: xr.Dataset, chunk_rows: int) -> None:
        # Zarr's own API, not xarray's to_zarr (xarray reads the store back identical,
        # tests/experiments/test_store.py), and Zarr encodes it into a dict (its
        # MemoryStore's store_dict) that is then written out file by file: a fifth of
        # the CPU of Zarr writing to disk itself (17 against 81 ms for 18 arrays), which
        # a short sweep's threads would otherwise share with it.  Zarr format 2, where
        # consolidated metadata is in the spec; xarray's dimension names attribute.
        try:
            shape = self.spec.shape
            files = {}
            group = zarr.open_group(zarr.storage.MemoryStore(store_dict=files), mode="w",
                                    zarr_format=2, attributes=dict(ds.attrs))
            for name, v in ds.variables.items():
                chunks = ((chunk_rows, shape[1]) if len(shape) == 2 else shape) \
                    if name in ds.data_vars else v.shape
                floats = v.dtype.kind == "f"
                arr = group.create_array(
                    name, shape=v.shape, dtype=v.dtype, chunks=chunks,
                    fill_value=np.nan if floats else None,
                    attributes={**v.attrs, "_ARRAY_DIMENSIONS": list(v.dims)})
                if not (floats and np.isnan(v.values).all()):  # NaN: the fill, not written
                    arr[...] = v.values
            # metadata never changes after creation (flushes write chunks only)
            zarr.consolidate_metadata(group.store, zarr_format=2)
            if self.path.exists():  # replaced, as Zarr's own mode="w" does
                shutil.rmtree(self.path)
            # the group's metadata first and the consolidated metadata last: a kill in
            # between leaves a store that asks for --restart (_open)
            _write_files(self.path, files,
                         sorted(files, key=lambda k: (k != ".zgroup", k == ".zmetadata")))
            self.zarrays = _open_arrays(self.path)  # here too, not in the first flush
        except BaseException as exc:  # noqa: BLE001 - re-raised by _created in the caller
            self._create_error = exc

    def _created(self) -> None:
        """Wait for a new store's files (written on a thread); raise what writing them raised."""
        if self._creating is not None:
            self._creating.join()
            self._creating = None
            if self._create_error is not None:
                raise self._create_error
        if self.zarrays is None:
            self.zarrays = _open_arrays(self.path)

    def _read_verified(self) -> dict:
        try:
            group = zarr.open_group(str(self.path), mode="r")
        except Exception as exc:  # noqa: BLE001
            raise StoreDamaged(f"{self.path}: the store's metadata is damaged ({exc}); run "
                               f"again with --restart to discard it") from None
        fields = {name: dtype for name, dtype, *_ in VARIABLES}
        fields.update(checksum="int64", done="bool")
        fill = {name: FILL[dtype] for name, dtype, *_ in VARIABLES}
        fill.update(checksum=-1, done=False)
        try:
            arrays, n_bad = read_verified(group, self.spec.shape, fields, fill, _names())
        except StoreDamaged as exc:
            raise StoreDamaged(f"{self.path}: {exc}; run again with --restart to discard "
                               f"it") from None
        if n_bad:
            warnings.warn(StoreRepaired(
                f"{self.path}: {n_bad} point(s) had damaged or missing data (unreadable chunk "
                f"or checksum mismatch) and will be recomputed"), stacklevel=4)
        # reset points are pending: recomputing them rewrites their rows, damaged chunks included
        return arrays

    @property
    def done(self) -> np.ndarray:
        return self.arrays["done"]

    def pending(self) -> list:
        return [int(k) for k in np.flatnonzero(~self.done)]

    def put(self, records: list) -> None:
        """Keep finished points: ``records`` is a list of (flat index, record dict).

        A block's points at once: their checksums in one array operation (per point,
        hashing held the GIL 0.07 ms, a tenth of a five-orbit run, against the threads).
        """
        ks = np.fromiter((k for k, _ in records), dtype=np.int64, count=len(records))
        for name in _names():
            column = self.arrays[name]
            for k, rec in records:
                column[k] = rec[name]
        self.arrays["checksum"][ks] = checksums(self.arrays, _names(), ks)
        self.done[ks] = True
        self.dirty.update((ks // (self.row * self.chunk_rows)).tolist())

    def flush(self) -> None:
        """Write the chunks that gained points: data and checksums first, then the done mask."""
        self._created()
        if not self.dirty:
            return
        rows = len(self.done) // self.row
        # one write per run of adjacent chunks, each chunk whole: Zarr writes them together
        runs = [(c0 * self.chunk_rows, min(c1 * self.chunk_rows, rows))
                for c0, c1 in _runs(sorted(self.dirty))]
        for name in _stored():
            arr = self.zarrays[name]
            for r0, r1 in runs:
                block = self.arrays[name][r0 * self.row:r1 * self.row]
                if arr.ndim == 2:
                    arr[r0:r1, :] = block.reshape(r1 - r0, self.row)
                else:
                    arr[:] = block
        self.dirty.clear()

    def dataset(self) -> xr.Dataset:
        """The whole data set, loaded from disk."""
        self._created()
        return open_dataset(self.path)


def _open_arrays(root: Path) -> dict:
    """Every stored array of the store ``root``, open for writing.

    Through the consolidated metadata (one read; the metadata never changes after
    creation), not one read per array: 3 against 7.5 ms of CPU for a flush's 18 arrays.
    """
    group = zarr.open_group(str(root), mode="r+", use_consolidated=True)
    return {name: group[name] for name in _stored()}


def _write_files(root: Path, files: dict, keys: list) -> None:
    """Write ``files[key]`` (a Zarr buffer) to ``root/key`` for each key, in that order.

    Each file goes to a temporary name and is renamed into place, as Zarr's LocalStore
    writes: a kill leaves every file whole, old or new.
    """
    for folder in dict.fromkeys((root / key).parent for key in keys):  # each folder once
        folder.mkdir(parents=True, exist_ok=True)
    for key in keys:
        path = root / key
        partial = path.with_name(path.name + ".partial")
        partial.write_bytes(files[key].to_bytes())
        os.replace(partial, path)


def chunk_rows_for(shape: tuple) -> int:
    """Grid rows per chunk of a new store of grid ``shape``: about CHUNK_POINTS points."""
    return max(1, min(shape[0], CHUNK_POINTS // shape[1])) if len(shape) == 2 else 1


def _runs(rows: list) -> list:
    """[(first, end)] of the runs of consecutive integers in the sorted list ``rows``."""
    runs = []
    for r in rows:
        if runs and runs[-1][1] == r:
            runs[-1][1] = r + 1
        else:
            runs.append([r, r + 1])
    return [tuple(x) for x in runs]


def _names():
    return tuple(v[0] for v in VARIABLES)


def _stored():
    """Every array of the store, in flush order: the done mask last."""
    return (*_names(), "checksum", "done")


def _differences(old_json, spec: SweepSpec) -> str:
    try:
        old = json.loads(old_json)
    except (TypeError, ValueError):
        return "no readable spec"
    new = json.loads(spec.to_json())
    keys = sorted(k for k in set(old) | set(new) if old.get(k) != new.get(k))
    return "differs in " + ", ".join(keys) if keys else "same spec"


def status_attrs() -> dict:
    """CF flag attributes of the status variable: the engine's names, coded by index."""
    return {"flag_values": list(range(len(STATUSES))), "flag_meanings": " ".join(STATUSES)}


def _check_status_codes(ds: xr.Dataset, path) -> None:
    """Refuse, in one line, a store whose status codes are not this tethersim's."""
    meanings = ds["status"].attrs.get("flag_meanings") if "status" in ds else None
    if meanings != status_attrs()["flag_meanings"]:
        raise StoreMismatch(f"{path}: its status codes ({meanings!r}) are an older "
                            f"tethersim's, which recorded a run that left the domain as "
                            f"failed; run the sweep again with --restart")


def _check_dtypes(ds: xr.Dataset, path) -> None:
    """Refuse, in one line, a store whose arrays do not have the dtypes tethersim writes."""
    expected = {name: dtype for name, dtype, *_ in VARIABLES}
    expected.update(checksum="int64", done="bool")
    for name, dtype in expected.items():
        if name in ds and ds[name].dtype != np.dtype(dtype):
            raise StoreDamaged(f"{path}: variable {name!r} is stored as {ds[name].dtype}, "
                               f"tethersim writes {dtype} (an edited store); run the sweep "
                               f"again with --restart to discard it")


def status_names(ds: xr.Dataset) -> np.ndarray:
    """The status of each grid point by the engine's name ("" where not computed)."""
    codes = ds["status"].values
    names = np.array(STATUSES + ("",), dtype=object)
    return np.where(ds["done"].values, names[np.clip(codes, 0, len(STATUSES))], "")


def open_dataset(path) -> xr.Dataset:
    """A finished (or partial) sweep store as a loaded xarray Dataset.

    Raises
    ------
    FileNotFoundError
        Not a sweep store.
    StoreMismatch
        A store of an older tethersim whose status codes differ.
    StoreDamaged
        A store whose arrays' dtypes were edited.
    """
    path = Path(path)
    if not ((path / "zarr.json").exists() or (path / ".zgroup").exists()):
        raise FileNotFoundError(f"{path}: not a sweep store (no zarr.json)")
    with xr.open_zarr(path) as ds:
        _check_dtypes(ds, path)
        _check_status_codes(ds, path)
        # the checksum is the store's own bookkeeping (tethersim.experiments.sweep.verify)
        return ds.drop_vars("checksum", errors="ignore").load()
