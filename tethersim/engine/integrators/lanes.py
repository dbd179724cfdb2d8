"""K points at once: the model's lane rhs and an RK4 step over structure-of-arrays lanes.

A sweep runs many points of one model; on a CPU with 4 (AVX2) or 8 (AVX-512) doubles
per vector register, K of them can advance together, lane k of every array holding
point k (heyoka's batch mode does the same).  Row i of the state, the parameters and
the stages sits at [i*LANES, i*LANES + K) of a flat array: the row stride LANES = 8 is
a compile-time constant, so LLVM sees every row at a constant offset and vectorises
(with a run-time stride its alias checks exceed their budget and it gives up); the
step is H[k].  The generated ``rhs_lanes`` (derive/lanes.py) is the scalar rhs inside
a loop over k: sin and cos are the generated polynomials (generated/trig.py), which
vectorise; libm's values (beyond trig.LIMIT, other calls) come from a first, scalar
loop over k.  :func:`rk4_lanes_step` is
``steps.rk4_step`` with the same loop over k innermost.  No fast-math anywhere: LLVM
vectorises across lanes without fusing or reordering an operation, so each lane's
numbers are those of the scalar step bit for bit (tests/engine/test_lanes.py).  Lanes
run the uniform air only (its densities are parameters; a per-body air vector runs
the scalar loops).
"""
from __future__ import annotations

import functools

import llvmlite.binding as llvm
from numba import njit
from numba.extending import overload

from tethersim.engine.dynamics import literal_index, model_size
from tethersim.engine.integrators.steps import RK4_C
from tethersim.model.registry import KERNELS

LANES = 8  # the lane arrays' row stride (derive/lanes.py): the most lanes, AVX-512


@functools.cache
def lane_count() -> int:
    """K: doubles per vector register of this CPU (8 with AVX-512, else 4: AVX2, and SSE2
    machines gain nothing from more)."""
    return 8 if "+avx512f" in llvm.get_host_cpu_features().flatten() else 4


def has_lanes(model: int) -> bool:
    """Whether model index ``model`` has a lane rhs (derive/lanes.py prints one when every
    libm call of its rhs reads only the state and the parameters)."""
    kernel = KERNELS[model]
    return hasattr(kernel, "rhs_lanes") and kernel.LANES == LANES


def model_rhs_lanes(model, t, y, p, dydt, s):
    """Generated lane rhs of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_rhs_lanes is only callable from compiled code")


def model_family_forces_lanes(model, K, y, p, out, s):
    """Generated lane family_forces of model ``model`` (compiled code, literal model only;
    a model without one: never called, see :func:`model_has_force_lanes`)."""
    raise NotImplementedError("model_family_forces_lanes is only callable from compiled code")


def model_has_force_lanes(model):
    """Whether model ``model`` has a lane family_forces, a compile-time constant."""
    raise NotImplementedError("model_has_force_lanes is only callable from compiled code")


def model_tether_margins_lanes(model, K, y, p, g, s):
    """Generated lane tether_margins of model ``model``: g[j*LANES + k] within a few ulps of
    lane k's λ_j − l_j0 (derive/lanes.py; compiled code, literal model only)."""
    raise NotImplementedError("model_tether_margins_lanes is only callable from compiled code")


def model_transcendentals(model):
    """Rows of the lane rhs's scratch (libm values from its first loop), a compile-time constant."""
    raise NotImplementedError("model_transcendentals is only callable from compiled code")


@overload(model_rhs_lanes, inline="always", prefer_literal=True)
def _model_rhs_lanes(model, t, y, p, dydt, s):
    if (k := literal_index(model)) is None:
        return None
    rhs = KERNELS[k].rhs_lanes

    def impl(model, t, y, p, dydt, s):
        rhs(t, y, p, dydt, s)
    return impl


def _force_lanes(k: int) -> bool:
    # a bead chain's loop index lies past KERNELS: its forces run one sample at a time
    return k < len(KERNELS) and has_lanes(k) and hasattr(KERNELS[k], "family_forces_lanes")


@overload(model_family_forces_lanes, inline="always", prefer_literal=True)
def _model_family_forces_lanes(model, K, y, p, out, s):
    if (k := literal_index(model)) is None:
        return None
    forces = KERNELS[k].family_forces_lanes if _force_lanes(k) else None

    def impl(model, K, y, p, out, s):
        forces(K, y, p, out, s)

    def absent(model, K, y, p, out, s):
        pass
    return impl if forces is not None else absent


@overload(model_tether_margins_lanes, inline="always", prefer_literal=True)
def _model_tether_margins_lanes(model, K, y, p, g, s):
    if (k := literal_index(model)) is None:
        return None
    margins = KERNELS[k].tether_margins_lanes

    def impl(model, K, y, p, g, s):
        margins(K, y, p, g, s)
    return impl


@overload(model_has_force_lanes, inline="always", prefer_literal=True)
def _model_has_force_lanes(model):
    if (k := literal_index(model)) is None:
        return None
    present = _force_lanes(k)

    def impl(model):
        return present
    return impl


@overload(model_transcendentals, inline="always", prefer_literal=True)
def _model_transcendentals(model):
    if (k := literal_index(model)) is None:
        return None
    n = KERNELS[k].N_TRANSCENDENTAL if has_lanes(k) else 1

    def impl(model):
        return n
    return impl


# error_model="numpy": a float division by zero gives inf (IEEE) instead of a branch
# that raises ZeroDivisionError, which would keep LLVM from vectorising the lane loop
@njit(cache=True, error_model="numpy")
def rk4_lanes_step(model, T, Y, H, P, k1, k2, k3, k4, ys, ts, Y_new, S):
    """One RK4 step of every lane: lane k from (T[k], Y[i*LANES + k]) by H[k] into Y_new.

    The arithmetic of each lane is ``steps.rk4_step``'s, operation for operation.  Lane
    arrays hold row i of a quantity at [i*LANES, i*LANES + K) (derive/lanes.py).

    Parameters
    ----------
    model : int literal
        Model index (a model with a lane rhs, :func:`has_lanes`).
    T, H : ndarray
        (K,) start times and steps; K <= LANES.
    Y, P : ndarray
        (state*LANES,) start states, (parameters*LANES,) parameter vectors.
    k1, k2, k3, k4, ys : ndarray
        (state*LANES,) scratch: the four stages and a stage state.
    ts : ndarray
        (K,) scratch: the stage times.
    Y_new : ndarray
        (state*LANES,) output.
    S : ndarray
        (model_transcendentals(model)*LANES,) scratch of the lane rhs.
    """
    n = model_size(model, Y)
    K = T.shape[0]
    for s in range(4):
        # one rhs call site (steps.py); each stage its own array, not a row of one: LLVM
        # then checks the arrays' overlap at run time and vectorises (rows of one array at
        # a run-time distance it does not)
        dst = k1 if s == 0 else k2 if s == 1 else k3 if s == 2 else k4
        if s == 0:
            for k in range(K):
                ts[k] = T[k]
            for i in range(n):
                for k in range(K):
                    ys[i * LANES + k] = Y[i * LANES + k]
        else:
            for k in range(K):
                ts[k] = T[k] + RK4_C[s] * H[k]
            ws = k1 if s == 1 else k2 if s == 2 else k3
            for i in range(n):
                for k in range(K):
                    r = i * LANES + k
                    ys[r] = Y[r] + RK4_C[s] * H[k] * ws[r]
        model_rhs_lanes(model, ts, ys, P, dst, S)
    for i in range(n):
        for k in range(K):
            r = i * LANES + k
            Y_new[r] = Y[r] + H[k] / 6.0 * (k1[r] + 2.0 * k2[r] + 2.0 * k3[r] + k4[r])
