"""The sweep store's layout: chunks of whole grid rows, a store Zarr writes directly that
xarray reads as its own, flushes of whole chunks from memory."""
from __future__ import annotations

import pytest
import xarray as xr
import zarr

from tests.experiments.test_sweep import paced
from tethersim import load_preset
from tethersim.experiments.sweep import SweepInterrupted, SweepSpec, run_sweep
from tethersim.experiments.sweep import store as store_module
from tethersim.experiments.sweep.store import SweepStore, _empty_dataset, chunk_rows_for

AXES = (("E1", [0.0038, 0.0042]), ("E2", [0.041, 0.043, 0.045]))  # 3 rows of 2 points


def _spec():
    return SweepSpec(load_preset("satI"), AXES, periods=0.2)


def test_chunks_are_whole_rows_of_about_chunk_points():
    n = store_module.CHUNK_POINTS
    assert chunk_rows_for((12, 12)) == 12  # a small sweep: one chunk per variable
    assert chunk_rows_for((1000, 100)) == n // 100
    assert chunk_rows_for((10, 2 * n)) == 1  # rows longer than a chunk: one row each
    assert chunk_rows_for((7,)) == 1  # a 1-D sweep is one chunk


def test_a_new_store_reads_back_as_xarray_would_have_written_it(tmp_path):
    spec = _spec()
    store = SweepStore(tmp_path / "direct.zarr", spec)
    store.close()  # waits for the files
    ds = _empty_dataset(spec)
    ds.to_zarr(tmp_path / "xr.zarr", mode="w", consolidated=True, zarr_format=2)
    with xr.open_zarr(tmp_path / "direct.zarr", consolidated=True) as a, \
            xr.open_zarr(tmp_path / "xr.zarr", consolidated=True) as b:
        xr.testing.assert_identical(a.load(), b.load())
        for name in ds.variables:
            assert a[name].dtype == b[name].dtype, name
    assert zarr.open_group(str(tmp_path / "direct.zarr"), mode="r")["done"].chunks == (3, 2)


def test_flushes_of_multi_row_chunks_resume_to_the_uninterrupted_data(tmp_path, monkeypatch):
    monkeypatch.setattr(store_module, "CHUNK_POINTS", 4)  # chunks of 2 rows: (0, 1) and (2,)
    whole = run_sweep(_spec(), tmp_path / "whole.zarr", workers=1, progress=False).dataset()
    out = tmp_path / "cut.zarr"
    paced(monkeypatch)
    with pytest.raises(SweepInterrupted):  # stops after 3 points (the one running finishes)
        run_sweep(_spec(), out, workers=1, block=1, progress=False, stop_after=3)
    assert 3 <= int(xr.open_zarr(out).done.sum()) < 6
    assert zarr.open_group(str(out), mode="r")["done"].chunks == (2, 2)
    monkeypatch.setattr(store_module, "CHUNK_POINTS", 1)  # a resume keeps the store's chunks
    resumed = run_sweep(_spec(), out, workers=1, progress=False).dataset()
    xr.testing.assert_identical(resumed, whole)
    assert zarr.open_group(str(out), mode="r")["done"].chunks == (2, 2)
