"""tethersim report: one HTML page whose figures exist and whose facts table covers the thesis."""
from __future__ import annotations

import re

import pytest

from tethersim.report import MAPS, build_report


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    return build_report(out, grid=3, periods=2.0, progress=False, log=lambda *a: None)


def test_report_links_only_figures_that_exist(report):
    text = report.read_text()
    srcs = re.findall(r'<img src="([^"]+)"', text)
    assert len(srcs) >= len(MAPS) + 3
    for s in srcs:
        assert (report.parent / s).is_file(), s


def test_report_sets_thesis_statements_beside_ours_with_a_verdict(report):
    text = report.read_text()
    rows = re.findall(r'<tr class="(yes|no|partly)">', text)
    assert len(rows) >= 15
    for needle in ("3.18", "two days", "28 m", "E2/E1", "26.55"):
        assert needle in text, needle
    assert "no" in rows, "the report must say where we disagree with the thesis"


def test_report_map_table_shows_the_classes_its_stores_hold(report):
    """The numbers on the page are those of the stored sweeps, not written-in text."""
    from tethersim.sweep import open_dataset
    from tethersim.sweep.analysis import class_counts
    text = report.read_text()
    stores = sorted((report.parent / "sweeps").glob("*_adaptive_*.zarr"))
    assert stores
    for store in stores:
        counts = class_counts(open_dataset(store))
        shown = ", ".join(f"{k} {v}" for k, v in counts.items() if v)
        assert f"<td>{shown}</td>" in text, (store.name, shown)


def test_report_sweeps_are_stored_and_resumable(report):
    entries = sorted(p.name for p in (report.parent / "sweeps").iterdir())
    stores = [s for s in entries if s.endswith(".zarr")]
    assert len(stores) == 2 * len(MAPS)  # converged + faithful per map
    # beside each store only its writer lock and the holder's name (tethersim.sweep.lock)
    assert set(entries) - set(stores) <= {s + e for s in stores for e in (".lock", ".lock.json")}
    assert all(s.endswith("_3x3_2orbits.zarr") for s in stores)


def test_report_refuses_a_bad_grid(tmp_path):
    with pytest.raises(ValueError, match="grid"):
        build_report(tmp_path, grid=1)
