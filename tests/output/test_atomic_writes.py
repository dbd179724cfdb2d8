"""Ctrl-C while a file is written leaves the previous file intact, or no file: never a
truncated one, never a temporary one (issue 19: a truncated ``timeseries.csv``).

Each writer is interrupted part-way by a KeyboardInterrupt raised from inside it (a
monkeypatched step of its own work), after it has already written some bytes.
"""
from __future__ import annotations

import csv

import matplotlib
import pytest

import tethersim as ts
from tests.cli.conftest import call
from tethersim.output import files, tables
from tethersim.output.files import TEMPORARY_MARK, replacing, save_figure, write_text

matplotlib.use("Agg")


@pytest.fixture(scope="module")
def res():
    return ts.simulate(ts.load_preset("satI"), periods=0.05, progress=False, check=False)


def _leftovers(folder) -> list:
    return sorted(p.name for p in folder.iterdir() if TEMPORARY_MARK in p.name)


def _interrupt_after(monkeypatch, module, name, calls: int):
    """Make ``module.name`` raise KeyboardInterrupt on its ``calls``-th call."""
    real, count = getattr(module, name), [0]

    def wrapped(*args, **kwargs):
        count[0] += 1
        if count[0] == calls:
            raise KeyboardInterrupt
        return real(*args, **kwargs)
    monkeypatch.setattr(module, name, wrapped)


def test_replacing_keeps_the_old_file_when_the_writer_is_interrupted(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("old, complete")
    with pytest.raises(KeyboardInterrupt), replacing(target) as tmp:
        tmp.write_text("new, half")
        assert tmp.parent == tmp_path and tmp.suffix == ".txt"
        raise KeyboardInterrupt
    assert target.read_text() == "old, complete"
    assert _leftovers(tmp_path) == []
    assert write_text(target, "new") == target and target.read_text() == "new"


def test_an_interrupted_time_series_leaves_the_previous_csv_whole(res, tmp_path, monkeypatch):
    path = tables.write_timeseries(res, tmp_path / "timeseries.csv")
    before = path.read_bytes()
    # the writer has written rows (a cell is formatted per value) when Ctrl-C comes
    _interrupt_after(monkeypatch, tables, "cell", calls=res.t.size * 5)
    with pytest.raises(KeyboardInterrupt):
        tables.write_timeseries(res, path)
    assert path.read_bytes() == before
    assert _leftovers(tmp_path) == []


def test_an_interrupted_first_write_leaves_no_file(res, tmp_path, monkeypatch):
    _interrupt_after(monkeypatch, tables, "cell", calls=50)
    with pytest.raises(KeyboardInterrupt):
        tables.write_timeseries(res, tmp_path / "timeseries.csv")
    assert list(tmp_path.iterdir()) == []


def test_an_interrupted_netcdf_leaves_the_previous_file_whole(res, tmp_path, monkeypatch):
    path = tables.write_netcdf(res, tmp_path / "timeseries.nc")
    before = path.read_bytes()
    # attributes are set after the variables' data: the file is half written by then
    _interrupt_after(monkeypatch, tables, "_nc3_attribute", calls=len(tables.timeseries_columns(
        res)) + 3)
    with pytest.raises(KeyboardInterrupt):
        tables.write_netcdf(res, path)
    assert path.read_bytes() == before
    assert _leftovers(tmp_path) == []


def test_an_interrupted_plot_leaves_complete_pngs_or_none(res, tmp_path, monkeypatch):
    from matplotlib.figure import Figure

    from tethersim.output.plots.run import plot_result

    real = Figure.savefig
    count = [0]

    def half_then_interrupt(self, fname, *args, **kwargs):
        count[0] += 1
        if count[0] == 2:  # the second figure: some bytes on disk, then Ctrl-C
            with open(fname, "wb") as fh:
                fh.write(b"\x89PNG\r\n\x1a\n half")
            raise KeyboardInterrupt
        return real(self, fname, *args, **kwargs)
    monkeypatch.setattr(Figure, "savefig", half_then_interrupt)
    with pytest.raises(KeyboardInterrupt):
        plot_result(res, tmp_path)
    pngs = sorted(tmp_path.glob("*.png"))
    assert [p.name for p in pngs] == ["theta.png"]  # the first, whole; the second absent
    from PIL import Image
    with Image.open(pngs[0]) as im:
        im.verify()
    assert _leftovers(tmp_path) == []


def test_save_figure_writes_the_format_of_the_files_suffix(tmp_path):
    import matplotlib.pyplot as plt
    fig = plt.figure()
    path = save_figure(fig, tmp_path / "f.png")
    plt.close(fig)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_ctrl_c_while_run_writes_keeps_the_previous_runs_files_whole(tmp_path, monkeypatch):
    out = tmp_path / "o"
    argv = ["run", "satI", "--periods", "0.05", "--quiet", "--no-plots", "--no-check",
            "--out", str(out)]
    assert call(argv)[0] == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    n = len((out / "timeseries.csv").read_text().splitlines())
    _interrupt_after(monkeypatch, tables, "cell", calls=n * 3)  # mid timeseries.csv
    code, _, err = call(argv)
    assert code == 130 and err.startswith("tethersim: interrupted"), err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    with (out / "timeseries.csv").open() as fh:
        assert len(list(csv.reader(fh))) == n


def test_the_temporary_name_is_hidden_beside_the_file_with_its_suffix(tmp_path):
    tmp = files.temporary_name(tmp_path / "overview.png")
    assert tmp.parent == tmp_path and tmp.name.startswith(".") and tmp.suffix == ".png"
