"""Choosing the compiled loop of one model, once per run, from Python.

The run functions (rk4_run, dop853_run) take the model index as a compile-time
literal (``numba.literally``), so each model has its own specialised loop.
Called from Python with a plain int, numba's dispatcher cannot match a
literal signature on its fast path and goes through its type-inference slow
path on every call (about a millisecond).  ``specialised`` picks the loop's
compiled entry point once — compiling it, or loading it from the disk cache,
the first time — and the caller then calls it directly.
"""
from __future__ import annotations

from numba import types
from numba.core.dispatcher import Dispatcher


def specialised(dispatcher, model: int, args: tuple):
    """Compiled entry point of ``dispatcher`` for a literal model index.

    Parameters
    ----------
    dispatcher : numba Dispatcher
        A run function whose first argument is the model index.
    model : int
        Model index (generated.dispatch.MODEL_NAMES).
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
    sig = (types.literal(int(model)),) + tuple(dispatcher.typeof_pyval(a) for a in args)
    if sig not in dispatcher.overloads:
        dispatcher.compile(sig)
    return dispatcher.get_overload(sig)
