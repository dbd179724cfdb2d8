"""The first compile of any model's kernels is announced (issue 19: the first 3-D and 3-D
free-orbit compiles sat silent for 36-44 s, because the notice asked only whether the loop
function had a cache file at all, and the planar model's compile had made one).

Fast tests use a small cached function in a temporary cache; the end-to-end one compiles
the planar kernels cold in a subprocess (slow).
"""
from __future__ import annotations

import contextlib
import importlib.util
import io
import os
import subprocess
import sys
from pathlib import Path

import numba
import pytest
from numba import types

from tethersim.engine.integrators import select
from tethersim.model.registry import BEAD_INDEX, BY_NAME

ROOT = Path(__file__).parents[2]
KERNEL = '''
from numba import njit


@njit(cache=True)
def kernel(model, x):
    return x + model
'''


@pytest.fixture
def cached_kernel(tmp_path, monkeypatch):
    """A ``cache=True`` function whose disk cache lives under tmp_path."""
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "cache" / "key"))
    (tmp_path / "notice_kernel.py").write_text(KERNEL)
    spec = importlib.util.spec_from_file_location("notice_kernel", tmp_path / "notice_kernel.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.kernel


def _sig(model: int):
    return (types.literal(model), types.float64)


def test_the_cache_check_tells_one_models_specialisation_from_anothers(cached_kernel):
    assert not select._in_cache(cached_kernel, _sig(0))
    cached_kernel.compile(_sig(0))  # writes the function's cache index and model 0's entry
    assert select._in_cache(cached_kernel, _sig(0))
    # the same function, another model: not compiled, so a first compile is still ahead
    assert not select._in_cache(cached_kernel, _sig(4))


class _FakeDispatcher:
    """Stands in for a numba dispatcher: compiling it records the call and takes no time."""

    def __init__(self):
        self.compiled = []

    def compile(self, sig):
        self.compiled.append(sig)


@pytest.mark.parametrize("name", ["3d", "3d-free", "free", "derived"])
def test_a_models_first_uncached_compile_is_announced_once_with_its_estimate(
        name, tmp_path, monkeypatch):
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "key"))
    monkeypatch.setattr(select, "_compiling", {})
    monkeypatch.setattr(select, "_in_cache", lambda dispatcher, sig: False)
    model = BY_NAME[name]
    fake, err = _FakeDispatcher(), io.StringIO()
    with contextlib.redirect_stderr(err):
        select._compile(fake, _sig(model.index), model.index)
        select._compile(fake, _sig(model.index), model.index)  # its second kernel: no notice
    lines = err.getvalue().splitlines()
    assert len(lines) == 1 and fake.compiled == [_sig(model.index)] * 2
    rough = select.COLD_COMPILE_S[(model.geometry, model.orbit)]
    assert f"compiling numerical kernels once for the {name} model (~{rough} s)" in lines[0]
    # the 3-D estimates are the slow ones the issue timed (36-44 s), not the planar 20 s
    assert (rough > select.COLD_COMPILE_S[("planar", "circular")]) == (name != "derived")


@pytest.mark.parametrize("name, words", [
    ("derived+beads4", "the derived+beads model (4 beads per line; any N reuses these kernels)"),
    ("objective-damper+beads0", "the objective-damper+beads model (0 beads per line; any N"),
    (None, "the exact-gravity+beads model (any number of beads per line)"),
])
def test_a_chains_first_compile_names_its_base_and_the_runs_beads_not_beads0(
        name, words, tmp_path, monkeypatch):
    # one chain loop per base serves every N (the state size says N): the notice named
    # every chain "derived+beads0", whatever N the run had
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "key"))
    monkeypatch.setattr(select, "_compiling", {})
    monkeypatch.setattr(select, "_in_cache", lambda dispatcher, sig: False)
    base = name.partition("+")[0] if name else "exact-gravity"
    index = BEAD_INDEX[base]
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        select._compile(_FakeDispatcher(), _sig(index), index, name=name)
    line = err.getvalue().strip()
    assert f"compiling numerical kernels once for {words}" in line
    assert "beads0 " not in line and f"(~{select.CHAIN_COLD_COMPILE_S} s)" in line
    assert select._timing_path(index).name.endswith(f"-{base}+beads")  # one file per loop


def test_a_series_kernels_first_compile_says_nothing_but_counts_for_an_announced_model(
        tmp_path, monkeypatch):
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "key"))
    monkeypatch.setattr(select, "_compiling", {})
    monkeypatch.setattr(select, "_in_cache", lambda dispatcher, sig: False)
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        select._compile(_FakeDispatcher(), _sig(4), 4, loud=False)  # short: a series kernel
        assert err.getvalue() == "" and select._compiling == {}
        select._compile(_FakeDispatcher(), _sig(4), 4)  # the run loop: announced
        select._compile(_FakeDispatcher(), _sig(4), 4, loud=False)
    assert err.getvalue().count("compiling") == 1 and list(select._compiling) == [4]


def test_a_cached_models_compile_says_nothing(tmp_path, monkeypatch):
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "key"))
    monkeypatch.setattr(select, "_compiling", {})
    monkeypatch.setattr(select, "_in_cache", lambda dispatcher, sig: True)
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        select._compile(_FakeDispatcher(), _sig(4), 4)
    assert err.getvalue() == ""


def test_the_estimate_is_the_models_last_timed_compile(tmp_path, monkeypatch):
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "key"))
    three_d = BY_NAME["3d"].index
    select._timing_path(three_d).write_text("37.5\n")
    assert select.estimate(three_d) == 37.5
    assert select.estimate(BY_NAME["derived"].index) == 20  # another model keeps its own


@pytest.mark.slow
def test_a_cold_cache_announces_the_planar_compile_once_and_a_warm_one_not(tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(TETHERSIM_CACHE_DIR=str(tmp_path), PYTHONPATH=str(ROOT))
    argv = [sys.executable, "-m", "tethersim", "run", "satI", "--periods", "0.05", "--quiet",
            "--no-plots", "--no-check", "--out", str(tmp_path / "out"), "--force"]
    cold = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=900)
    assert cold.returncode == 0, cold.stderr[-2000:]
    assert cold.stderr.count("compiling numerical kernels once for the derived model") == 1
    warm = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=900)
    assert warm.returncode == 0 and "compiling" not in warm.stderr, warm.stderr
