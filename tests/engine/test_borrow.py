"""The borrowed array type (tethersim/engine/integrators/borrow.py): views stay borrowed
and read the owner's memory, and a borrowed array never becomes the owner of new memory."""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit
from numba.core.errors import TypingError

from tethersim.engine.integrators.borrow import BorrowedArray, borrow


@njit(cache=False)
def _row_sum(a, out):
    b = borrow(a)
    row = b[1]  # a view of a borrowed array
    s = 0.0
    for i in range(row.shape[0]):
        s += row[i]
    out[0] = s


def test_views_of_a_borrowed_array_are_borrowed_and_read_the_owners_memory():
    a = np.arange(6.0).reshape(2, 3)
    out = np.zeros(1)
    _row_sum(a, out)
    assert out[0] == 3.0 + 4.0 + 5.0
    types = _row_sum.overloads[_row_sum.signatures[0]].type_annotation.typemap
    assert not isinstance(types["a"], BorrowedArray)  # the caller's array owns its memory
    assert isinstance(types["b"], BorrowedArray) and types["b"].ndim == 2
    assert isinstance(types["row"], BorrowedArray) and types["row"].ndim == 1


def test_a_borrowed_array_cannot_be_the_template_of_a_new_array():
    @njit(cache=False)
    def copy_of_borrowed(a):
        return borrow(a).copy()

    with pytest.raises(TypingError, match="cannot be the template of a new array"):
        copy_of_borrowed(np.zeros(3))
