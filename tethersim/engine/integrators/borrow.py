"""Borrowed (non-owning) views of arrays for the inside of compiled time loops.

Every numba array carries a pointer to its reference-counted memory block
(``meminfo``).  Each time an array or a view of it crosses a non-inlined call,
is rebound or goes out of scope, numba emits ``NRT_incref``/``NRT_decref`` on
that pointer: an atomic, lock-prefixed increment (~10 ns on some Xeons) about
23 times per right-hand-side evaluation.  numba's runtime returns from both at
once when the pointer is NULL, so an array struct whose ``meminfo`` is NULL
(a *borrowed* array) costs a predictable branch instead.

Contract: a borrowed array does not keep its memory alive.  A run function
borrows its arguments at its entry (the caller holds them for the duration
of the call) and a thin wrapper allocates the scratch arrays, passes them
down and keeps them alive until the loop returns.  A borrowed array must never
be returned, stored or outlive the call that borrowed it.
"""
from __future__ import annotations

from numba.core import cgutils, types
from numba.extending import intrinsic


@intrinsic
def borrow(typingctx, arr):
    """Return ``arr`` with its reference-count pointer (meminfo) set to NULL.

    Parameters
    ----------
    arr : numba array
        Any array; the caller must keep the owner alive while the result is used.

    Returns
    -------
    numba array
        The same data, shape and strides, of the same type, whose incref and
        decref are no-ops.
    """
    if not isinstance(arr, types.Array):
        return None

    def codegen(context, builder, signature, args):
        ary = context.make_array(signature.args[0])(context, builder, value=args[0])
        ary.meminfo = cgutils.get_null_value(ary.meminfo.type)
        # a new struct owning nothing: returning it needs no incref
        return ary._getvalue()

    return arr(arr), codegen
