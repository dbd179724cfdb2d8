"""Choosing the compiled loop of one model, once per run, from Python.

The run functions (rk4_run, dop853_run) take the model index as a compile-time
literal (``numba.literally``), so each model has its own specialised loop.
Called from Python with a plain int, numba's dispatcher cannot match a
literal signature on its fast path and goes through its type-inference slow
path on every call (about a millisecond).  ``specialised`` picks the loop's
compiled entry point once — compiling it, or loading it from the disk cache,
the first time — and the caller then calls it directly.

A first run after installing (or after editing a kernel source) compiles for
tens of seconds; ``specialised`` says so on stderr, once per process, with
the time the last cold compile took on this machine.
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

COLD_COMPILE_S = 20  # estimate before any compile was timed here (2 cores: 14 s for one loop)
ANNOUNCE_AFTER_S = 2.0  # compiles shorter than this are not worth recording
_TIMING_FILE = "last-cold-compile-seconds"
_announced = False
_lock = threading.Lock()
_entries = {}  # (dispatcher, model, argument type keys) -> compiled entry point


def _in_cache(dispatcher) -> bool:
    # numba names a function's cache index <module file>.<qualname>-<line>.pyXY.nbi;
    # this only decides whether to print a notice, never what runs
    fn = dispatcher.py_func
    stem = fn.__module__.rsplit(".", 1)[-1]
    return any(Path(numba.config.CACHE_DIR).glob(f"*/{stem}.{fn.__qualname__}-*.nbi"))


def _timing_path() -> Path:
    # one level above the source-keyed folder: survives a change of the key
    return Path(numba.config.CACHE_DIR).parent / _TIMING_FILE


def _estimate() -> float:
    try:
        return float(_timing_path().read_text())
    except (OSError, ValueError):
        return COLD_COMPILE_S


def _compile(dispatcher, sig) -> None:
    global _announced
    notice = False
    with _lock:
        if not _announced and not _in_cache(dispatcher):
            _announced = notice = True
            print(f"tethersim: compiling numerical kernels once (~{_estimate():.0f} s); "
                  f"later runs load them from {os.path.dirname(numba.config.CACHE_DIR)}",
                  file=sys.stderr, flush=True)
    t0 = time.perf_counter()
    dispatcher.compile(sig)
    dt = time.perf_counter() - t0
    if notice and dt > ANNOUNCE_AFTER_S:
        try:
            _timing_path().write_text(f"{dt:.1f}\n")
        except OSError:
            pass  # the estimate is a courtesy, a read-only cache folder is fine


def specialised(dispatcher, model: int, args: tuple):
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
            _compile(dispatcher, sig)
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
    return specialised(dispatcher, model, args)(model, *args)
