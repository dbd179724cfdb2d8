"""The generated kernels of a bead chain's base model, picked by a compile-time literal.

tethersim/model/beads.py calls the base model's ``rhs``, ``jacobi`` and ``family_forces``
for the boom, the balloon and each bead; the base (an index into
tethersim.model.bead_layout.BASES) is a literal, so each chain kernel compiles against
its base's generated functions, as tethersim/engine/dynamics.py picks a model's.
"""
from __future__ import annotations

from numba import types
from numba.extending import overload

import tethersim.generated as generated
from tethersim.model.bead_layout import BASES

GENERATED = {name: generated.MODELS[name] for name in BASES}


def _base_rhs(kind, t, y, p, dydt):
    """The generated rhs of base ``BASES[kind]`` (compiled code, literal ``kind`` only)."""
    raise NotImplementedError("_base_rhs is only callable from compiled code")


def _base_jacobi(kind, y, p):
    """The generated jacobi of base ``BASES[kind]`` (compiled code, literal ``kind`` only)."""
    raise NotImplementedError("_base_jacobi is only callable from compiled code")


def _base_family_forces(kind, y, p, out):
    """The generated family_forces of base ``BASES[kind]`` (compiled code, literal only)."""
    raise NotImplementedError("_base_family_forces is only callable from compiled code")


@overload(_base_family_forces, prefer_literal=True)
def _base_family_forces_overload(kind, y, p, out):
    if not isinstance(kind, types.IntegerLiteral):
        return None
    f = GENERATED[BASES[kind.literal_value]].family_forces

    def impl(kind, y, p, out):
        f(y, p, out)
    return impl


@overload(_base_rhs, prefer_literal=True)
def _base_rhs_overload(kind, t, y, p, dydt):
    if not isinstance(kind, types.IntegerLiteral):
        return None
    f = GENERATED[BASES[kind.literal_value]].rhs

    def impl(kind, t, y, p, dydt):
        f(t, y, p, dydt)
    return impl


@overload(_base_jacobi, prefer_literal=True)
def _base_jacobi_overload(kind, y, p):
    if not isinstance(kind, types.IntegerLiteral):
        return None
    f = GENERATED[BASES[kind.literal_value]].jacobi

    def impl(kind, y, p):
        return f(y, p)
    return impl
