"""Verify a sweep store on resume: every chunk readable, every done point intact.

A truncated chunk file used to give a decompression traceback on resume, and a
deleted one silently became a row of NaNs marked done (Zarr reads a missing
chunk as its fill value).  Each point's record now carries a checksum (a 64-bit
FNV-1a hash of its fields, written with the data and before ``done``); on
resume every chunk of every variable is read on its own, and a point counts as
done only if its chunk reads and its checksum matches its data.  Other points
are reset to the fill values and recomputed.
"""
from __future__ import annotations

import numpy as np

_OFFSET = np.uint64(0xCBF29CE484222325)  # FNV-1a 64-bit offset basis and prime
_PRIME = np.uint64(0x100000001B3)


class StoreDamaged(ValueError):
    """The store's metadata cannot be read: only ``--restart`` can recover it."""


def checksums(arrays: dict, names, index=slice(None)) -> np.ndarray:
    """Per-point checksums (int64) of the record fields ``names`` at flat ``index``.

    Parameters
    ----------
    arrays : dict of numpy.ndarray
        Flat arrays of the store, one per field.
    names : sequence of str
        The record's fields, in a fixed order.
    index : slice or array of int
        The points to hash.

    Returns
    -------
    numpy.ndarray
        int64 checksums; NaNs hash alike whatever their bit pattern, so a
        NaN that is really there equals the NaN a missing chunk reads as.
    """
    h = None
    for name in names:
        v = np.atleast_1d(np.asarray(arrays[name][index]))
        if v.dtype.kind == "f":
            bits = np.where(np.isnan(v), np.nan, v).astype(np.float64).view(np.uint64)
        else:
            bits = v.astype(np.int64).view(np.uint64)
        if h is None:
            h = np.full(bits.shape, _OFFSET, dtype=np.uint64)
        # array arithmetic wraps modulo 2^64 silently, as the hash wants
        h = (h ^ bits) * _PRIME
    return h.view(np.int64)


def read_verified(group, shape, fields: dict, fill: dict, names) -> tuple:
    """Read a store's flat arrays chunk by chunk; reset points that fail verification.

    Parameters
    ----------
    group : zarr.Group
        The open store.
    shape : tuple of int
        Grid shape; chunks are rows of the last axis (or the whole 1-D grid).
    fields : dict
        {variable name: numpy dtype} of every array to read, ``done`` and
        ``checksum`` included.
    fill : dict
        {variable name: fill value} written into reset points.
    names : sequence of str
        The record fields the checksum covers.

    Returns
    -------
    (dict of numpy.ndarray, int)
        Flat arrays and the number of points that were marked done but failed
        (unreadable chunk or checksum mismatch) and are now pending again.

    Raises
    ------
    StoreDamaged
        If a variable's metadata cannot be opened, or its dtype or shape is not
        the one tethersim writes (an edited store).
    """
    rows, row = (shape[0], shape[1]) if len(shape) == 2 else (1, shape[0])
    arrays, bad_rows = {}, set()
    for name, dtype in fields.items():
        try:
            arr = group[name]
        except Exception as exc:  # noqa: BLE001 - any failure here is damaged metadata
            raise StoreDamaged(f"variable {name!r} cannot be opened ({type(exc).__name__}: "
                               f"{' '.join(str(exc).split())})") from None
        # an edited dtype or shape is not a damaged chunk: rewriting the rows into it
        # would "repair" the store into one that every reader then fails on
        if arr.dtype != np.dtype(dtype):
            raise StoreDamaged(f"variable {name!r} is stored as {arr.dtype}, tethersim "
                               f"writes {np.dtype(dtype)} (an edited store)")
        if tuple(arr.shape) != tuple(shape):
            raise StoreDamaged(f"variable {name!r} has shape {tuple(arr.shape)}, the grid is "
                               f"{tuple(shape)} (an edited store)")
        flat = np.empty(rows * row, dtype=dtype)
        for r in range(rows):
            try:
                block = arr[r, :] if len(shape) == 2 else arr[:]
                flat[r * row:(r + 1) * row] = np.asarray(block).astype(dtype)
            except Exception:  # noqa: BLE001 - truncated/corrupt chunk: recompute its row
                flat[r * row:(r + 1) * row] = fill[name]
                bad_rows.add(r)
        arrays[name] = flat
    done = arrays["done"]
    ok = np.ones(done.size, dtype=bool)
    for r in bad_rows:
        ok[r * row:(r + 1) * row] = False
    was_done = np.flatnonzero(done)
    ok[was_done] &= checksums(arrays, names, was_done) == arrays["checksum"][was_done]
    reset = done & ~ok
    for name, a in arrays.items():
        a[reset] = fill[name]
    return arrays, int(reset.sum())
