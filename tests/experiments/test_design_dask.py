"""The design search on a local Dask cluster (two worker processes, one cluster for the whole
search) finds what the threads find: the same evaluations, front and re-verification."""
from __future__ import annotations

import pytest

from tests.experiments.test_design import SMALL, _front, _spec
from tethersim.experiments.design_search import search


@pytest.mark.slow  # starts worker processes, each loading the kernels
def test_a_local_dask_cluster_gives_the_threads_search(tmp_path):
    spec = _spec(**{**SMALL, "budget": 6, "population": 6, "verify": 1})
    threads = search(spec, tmp_path / "threads", workers=1, progress=False)
    dask = search(spec, tmp_path / "dask", dask_workers=2, progress=False)
    assert _front(dask) == _front(threads)
    assert [r["F"] for r in dask["evaluations"]] == [r["F"] for r in threads["evaluations"]]
