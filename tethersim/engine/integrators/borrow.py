"""Borrowed (non-owning) arrays for the inside of compiled time loops.

Every numba array carries a pointer to its reference-counted memory block
(``meminfo``).  Each time an array or a view of it crosses a non-inlined call,
is rebound or goes out of scope, numba emits a call to ``NRT_incref`` or
``NRT_decref`` on that pointer: an atomic, lock-prefixed increment (~10 ns on
some Xeons) about 23 times per right-hand-side evaluation, and even on a NULL
pointer a call that returns at once (about 14 per evaluation of the derivative,
7 % of a DOP853 run on an AMD EPYC).

A *borrowed* array has its own numba type, :class:`BorrowedArray`: the same
layout, operations and views as a numba array, but its data model declares the
first field a plain pointer rather than a reference-counted one, so numba emits
no reference counting at all for it, and the field is NULL.  Every view of a
borrowed array is borrowed too.

Contract: a borrowed array does not keep its memory alive.  A run function
borrows its arguments at its entry (the caller holds them for the duration
of the call) and a thin wrapper allocates the scratch arrays, passes them
down and keeps them alive until the loop returns.  A borrowed array must never
be returned, stored or outlive the call that borrowed it.
"""
from __future__ import annotations

from numba.core import cgutils, errors, types
from numba.extending import intrinsic, models, overload_classmethod, register_model


class BorrowedArray(types.Array):
    """A numba array type whose values own no memory (no reference counting)."""

    def __init__(self, dtype, ndim, layout, readonly=False, aligned=True):
        name = (f"borrowed {'readonly ' if readonly else ''}array({dtype}, {ndim}d, {layout})"
                f"{'' if aligned else ' unaligned'}")
        super().__init__(dtype, ndim, layout, readonly=readonly, name=name, aligned=aligned)

    @classmethod
    def of(cls, arr: types.Array) -> BorrowedArray:
        """The borrowed twin of the array type ``arr`` (same dtype, shape, layout, flags)."""
        return cls(arr.dtype, arr.ndim, arr.layout, readonly=not arr.mutable,
                   aligned=arr.aligned)

    def copy(self, dtype=None, ndim=None, layout=None, readonly=None):
        # views, slices and reshapes of a borrowed array are borrowed
        return BorrowedArray.of(super().copy(dtype=dtype, ndim=ndim, layout=layout,
                                             readonly=readonly))

    def unify(self, typingctx, other):
        # p or pw (dynamics.derivative): two borrowed arrays unify to a borrowed one
        base = super().unify(typingctx, other)
        if base is not None and isinstance(other, BorrowedArray):
            return BorrowedArray.of(base)
        return base


@register_model(BorrowedArray)
class BorrowedArrayModel(models.StructModel):
    """numba's array layout with an untracked first field (numba's ArrayModel has a
    reference-counted ``meminfo`` there): the same LLVM struct, no reference counting."""

    def __init__(self, dmm, fe_type):
        members = [
            ("meminfo", types.voidptr),
            ("parent", types.pyobject),
            ("nitems", types.intp),
            ("itemsize", types.intp),
            ("data", types.CPointer(fe_type.dtype)),
            ("shape", types.UniTuple(types.intp, fe_type.ndim)),
            ("strides", types.UniTuple(types.intp, fe_type.ndim)),
        ]
        super().__init__(dmm, fe_type, members)


@overload_classmethod(BorrowedArray, "_allocate")
def _refuse_allocation(cls, allocsize, align):
    # numba allocates a new array (a copy, np.empty_like, arithmetic) of its template's
    # type: one typed borrowed would own memory that nothing frees
    raise errors.TypingError("a borrowed array (tethersim.engine.integrators.borrow) cannot "
                             "be the template of a new array: allocate with np.empty and "
                             "copy into it")


@intrinsic
def borrow(typingctx, arr):
    """Return ``arr`` as a :class:`BorrowedArray`: the same data, shape and strides.

    Parameters
    ----------
    arr : numba array
        Any array; the caller must keep the owner alive while the result is used.

    Returns
    -------
    BorrowedArray
        The same array, of a type for which numba emits no reference counting,
        its meminfo pointer NULL.
    """
    if not isinstance(arr, types.Array):
        return None
    result = arr if isinstance(arr, BorrowedArray) else BorrowedArray.of(arr)

    def codegen(context, builder, signature, args):
        src = context.make_array(signature.args[0])(context, builder, value=args[0])
        out = context.make_array(signature.return_type)(context, builder)
        for field in ("parent", "nitems", "itemsize", "data", "shape", "strides"):
            setattr(out, field, getattr(src, field))
        out.meminfo = cgutils.get_null_value(out.meminfo.type)
        # a new struct owning nothing: returning it needs no incref
        return out._getvalue()

    return result(arr), codegen
