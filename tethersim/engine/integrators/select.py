"""Choosing the compiled loop of one model, once per run, from Python.

The run functions (rk4_run, dop853_run) take the model index as a compile-time
literal (``numba.literally``), so each model has its own specialised loop.
Called from Python with a plain int, numba's dispatcher cannot match a
literal signature on its fast path and goes through its type-inference slow
path on every call (about a millisecond).  ``specialised`` picks the loop's
compiled entry point once — compiling it, or loading it from the disk cache,
the first time — and the caller then calls it directly.

A first run after installing (or after editing a kernel source) compiles for
tens of seconds; ``specialised`` says so on stderr, once per model and process
when that model's kernels are not in the disk cache, with the time that model's
last cold compile took on this machine (else a rough figure per kind of model).
"""
from __future__ import annotations

import os
import sys
import threading
import time
from pathlib import Path

import numba
import numpy as np
from numba import types
from numba.core.dispatcher import Dispatcher

# rough cold-compile time of one model's kernels before any was timed here (2 cores: 14 s for
# one planar loop; issue 19 timed 36-44 s for the first 3-D and 3-D free-orbit compiles)
COLD_COMPILE_S = {("planar", "circular"): 20, ("planar", "free"): 30, ("3d", "circular"): 40,
                  ("3d", "free"): 45}
# a bead chain's loop (tethersim.model.beads): 20-54 s cold on 2 cores, its base model's
# generated kernels inlined once per segment and node
CHAIN_COLD_COMPILE_S = 45
ANNOUNCE_AFTER_S = 2.0  # compiles shorter than this are not worth recording
_TIMING_FILE = "last-cold-compile-seconds"
_lock = threading.Lock()
_entries = {}  # (dispatcher, model, argument type keys) -> compiled entry point
_compiling = {}  # model index -> seconds its announced compiles took so far in this process


def _in_cache(dispatcher, sig) -> bool:
    """Whether numba's disk cache holds ``dispatcher`` compiled for ``sig`` (this model).

    Asks the cache's own index, as numba's load does: one function's index holds every
    model's specialisation, so a file-exists check said "cached" for a 3-D model whose
    planar twin was compiled.  This only decides whether to print a notice, never what
    runs; numba's private API moving falls back to that per-function check.
    """
    try:
        cache = dispatcher._cache
        key = cache._index_key(sig, dispatcher.targetctx.codegen())
        return key in cache._cache_file._load_index()
    except Exception:  # noqa: BLE001 - a courtesy; any failure means "do not know"
        # numba names a function's cache index <module file>.<qualname>-<line>.pyXY.nbi
        fn = dispatcher.py_func
        stem = fn.__module__.rsplit(".", 1)[-1]
        return any(Path(numba.config.CACHE_DIR).glob(f"*/{stem}.{fn.__qualname__}-*.nbi"))


def _model(model: int):
    from tethersim.model.registry import record
    return record(model)


def _loop_name(model: int) -> str:
    """The name of loop ``model``'s kernels: the model's, or for a bead chain its base's
    with the tag (``derived+beads``): one loop serves every N, read from the state size."""
    from tethersim.model.registry import bead_index, bead_split
    name = _model(model).name
    return f"{bead_split(name)[0]}+beads" if bead_index(model) else name


def _timing_path(model: int) -> Path:
    # one level above the source-keyed folder: survives a change of the key
    return Path(numba.config.CACHE_DIR).parent / f"{_TIMING_FILE}-{_loop_name(model)}"


def estimate(model: int) -> float:
    """Seconds the model's first compile took last time here, else a rough figure."""
    from tethersim.model.registry import bead_index
    try:
        return float(_timing_path(model).read_text())
    except (OSError, ValueError):
        if bead_index(model):
            return CHAIN_COLD_COMPILE_S
        m = _model(model)
        return COLD_COMPILE_S.get((m.geometry, m.orbit), max(COLD_COMPILE_S.values()))


def announce(model: int, name: str | None = None) -> None:
    """Say on stderr, once per model and process, that its kernels compile now.

    ``name`` is the run's model (a chain's says its N: ``derived+beads4``); a chain's
    notice names the loop, which serves every N, and the run's N when given.
    """
    from tethersim.model.registry import bead_index, bead_split
    what = f"the {_loop_name(model)} model"
    if bead_index(model):
        chain = bead_split(name) if name else None
        what += (f" ({chain[1]} beads per line; any N reuses these kernels)" if chain
                 else " (any number of beads per line)")
    print(f"tethersim: compiling numerical kernels once for {what} "
          f"(~{estimate(model):.0f} s); later runs load them from "
          f"{os.path.dirname(numba.config.CACHE_DIR)}", file=sys.stderr, flush=True)


def _compile(dispatcher, sig, model: int, loud: bool = True, name: str | None = None) -> None:
    with _lock:
        timed = model in _compiling
        if loud and not timed and not _in_cache(dispatcher, sig):
            _compiling[model] = 0.0
            timed = True
            announce(model, name)
    t0 = time.perf_counter()
    dispatcher.compile(sig)
    dt = time.perf_counter() - t0
    if timed:  # every compile of an announced model counts: the next estimate is the total
        with _lock:
            _compiling[model] += dt
            total = _compiling[model]
        if total > ANNOUNCE_AFTER_S:
            try:
                _timing_path(model).write_text(f"{total:.1f}\n")
            except OSError:
                pass  # the estimate is a courtesy, a read-only cache folder is fine


def specialised(dispatcher, model: int, args: tuple, loud: bool = True,
                name: str | None = None):
    """Compiled entry point of ``dispatcher`` for a literal model index.

    Parameters
    ----------
    dispatcher : numba Dispatcher
        A run function whose first argument is the model index.
    model : int
        Model index (tethersim.model.registry order).
    args : tuple
        The remaining arguments as they will be passed (their types select
        the signature).
    loud : bool
        Announce a first compile of this model (the run loops, tens of seconds);
        False for the short series kernels, which only add to an announced
        model's timing.
    name : str, optional
        The run's model name, for the notice (a bead chain's carries its N).

    Returns
    -------
    callable
        ``f(model, *args)``, the compiled function for this model and these
        argument types; it releases the GIL when the run function is nogil.
    """
    if not isinstance(dispatcher, Dispatcher):
        return dispatcher  # a Python wrapper (or a test double) is called as it is
    # numba's typeof of every argument costs ~0.1 ms a call: a cheap key first
    key = (dispatcher, int(model), tuple(map(_type_key, args)))
    entry = _entries.get(key)
    if entry is None:
        sig = (types.literal(int(model)),) + tuple(dispatcher.typeof_pyval(a) for a in args)
        if sig not in dispatcher.overloads:
            _compile(dispatcher, sig, int(model), loud, name)
        entry = _entries[key] = dispatcher.get_overload(sig)
    return entry


def _type_key(a):
    # what numba's typeof of the run functions' arguments depends on
    if isinstance(a, np.ndarray):
        f = a.flags
        return a.dtype.str, a.ndim, f.c_contiguous, f.f_contiguous, f.writeable, f.aligned
    return type(a)


def call(dispatcher, model: int, *args):
    """``dispatcher(model, *args)`` from Python through its compiled entry for a literal model.

    What every Python caller of a literal-model kernel uses (the series of
    tethersim.engine.evaluate, dynamics.parameters_at): a plain call would go
    through numba's type inference on every call (~10 ms for a series kernel).
    """
    return specialised(dispatcher, model, args, loud=False)(model, *args)
