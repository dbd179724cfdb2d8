"""Jitted loops that evaluate a model's generated kernels along a trajectory.

Each takes the model index as a literal (one specialised loop per model, like
the integrators), the air vector, the samples Y (n, integrated state) and the
parameter vector; the model's own layout (number of coordinates, families)
comes from its generated module.

The public functions are called from Python with a plain int model index: they
pick the compiled loop of that literal once and call it directly
(integrators.select.call).  Called through numba's dispatcher instead, a literal
argument sends every call down its type-inference slow path (~1-20 ms a call,
more than a 5-orbit run; it made every sweep point's outcome cost that).
"""
from __future__ import annotations

import numpy as np
from numba import literally, njit
from numba.extending import overload

from tethersim.engine.dynamics import literal_index, model_densities, model_tether_margins
from tethersim.engine.integrators.borrow import borrow
from tethersim.engine.integrators.lanes import (
    LANES,
    model_family_forces_lanes,
    model_has_force_lanes,
    model_transcendentals,
)
from tethersim.engine.integrators.select import call
from tethersim.engine.integrators.steps import copy_into
from tethersim.model.air.vector import UNIFORM
from tethersim.model.beads import N_FAMILIES
from tethersim.model.registry import KERNELS, MODELS, bead_index, kernels_of


def model_family_forces(model, y, p, out):
    """Generated family_forces of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_family_forces is only callable from compiled code")


def model_jacobi(model, y, p):
    """Generated jacobi of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_jacobi is only callable from compiled code")


def model_power(model, y, p, fam):
    """A bead chain's power of drag and dampers [W] (compiled code, literal chain only)."""
    raise NotImplementedError("model_power is only callable from compiled code")


def model_shape(model):
    """(families, coordinates) of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_shape is only callable from compiled code")


@overload(model_family_forces, inline="always", prefer_literal=True)
def _model_family_forces(model, y, p, out):
    if (k := literal_index(model)) is None:
        return None
    f = KERNELS[k].family_forces

    def impl(model, y, p, out):
        f(y, p, out)
    return impl


@overload(model_jacobi, inline="always", prefer_literal=True)
def _model_jacobi(model, y, p):
    if (k := literal_index(model)) is None:
        return None
    f = kernels_of(k).jacobi

    def impl(model, y, p):
        return f(y, p)
    return impl


@overload(model_power, inline="always", prefer_literal=True)
def _model_power(model, y, p, fam):
    if (k := literal_index(model)) is None or not bead_index(k):
        return None
    f = kernels_of(k).power

    def impl(model, y, p, fam):
        return f(y, p, fam)
    return impl


@overload(model_shape, inline="always", prefer_literal=True)
def _model_shape(model):
    if (k := literal_index(model)) is None:
        return None
    shape = (len(MODELS[k].families), MODELS[k].n_coordinates)

    def impl(model):
        return shape
    return impl


@njit(cache=True, nogil=True)
def _forces_loop(model, air, T, Y, p, pw, out, q, peaks):
    # the caller holds every array for the call: all are borrowed here (module docstring)
    air, T, Y, p, pw = borrow(air), borrow(T), borrow(Y), borrow(p), borrow(pw)
    out, q, peaks = borrow(out), borrow(q), borrow(peaks)
    nf, nq = model_shape(model)
    for i in range(Y.shape[0]):
        # pw equals p in uniform air; per-body air writes the bodies' densities into it
        if air[0] != UNIFORM:
            model_densities(model, T[i], Y[i], p, pw, air)
        if out.shape[0] == 0:  # peaks only
            model_family_forces(model, Y[i], pw, q)
            for f in range(nf):
                for k in range(nq):
                    a = abs(q[f, k])
                    if a > peaks[k]:
                        peaks[k] = a
        else:
            model_family_forces(model, Y[i], pw, out[i])


@njit(cache=True, nogil=True)  # nogil: sweeps evaluate forces on threads
def _family_forces_series(model, air, T, Y, p):
    """Q[i, f, k]: generalized force of family f on coordinate k at sample (T[i], Y[i]) (SI).

    ``air`` is the run's air vector (dynamics.derivative).
    """
    literally(model)
    nf, nq = model_shape(model)
    out = np.zeros((Y.shape[0], nf, nq))
    # the arguments borrowed, the scratch plain: the types _family_force_peaks passes
    # (a sweep's blocks and outcome() call it on borrowed views), so one compiled
    # _forces_loop serves both; the scratch arrays live as arguments of the call
    _forces_loop(model, borrow(air), borrow(T), borrow(Y), borrow(p), p.copy(), out,
                 np.empty((nf, nq)), np.empty(0))
    return out


@njit(cache=True)
def _jacobi_series(model, Y, p):
    """Jacobi integral (+ spring energy) [J] at each sample."""
    literally(model)
    n = Y.shape[0]
    out = np.empty(n)
    Y, p, o = borrow(Y), borrow(p), borrow(out)  # ``out`` lives to the return
    for i in range(n):
        o[i] = model_jacobi(model, Y[i], p)
    return out


@njit(cache=True, nogil=True)
def _family_force_peaks(model, air, T, Y, p):
    """Largest |Q| of any single family on each coordinate over the samples.

    What a sweep keeps of the force breakdown, without the (n, families,
    coordinates) array and without holding the GIL (threads of a sweep run this
    side by side).
    """
    literally(model)
    nf, nq = model_shape(model)
    peaks = np.zeros(nq)
    if model_has_force_lanes(model) and air[0] == UNIFORM:
        _peaks_lanes(model, Y, p, peaks)
        return peaks
    pw = np.empty(p.shape[0])  # not p.copy(): p may be borrowed (borrow.py)
    copy_into(borrow(pw), p)  # borrowed as every other caller's: one compiled copy_into
    _forces_loop(model, air, T, Y, p, pw, np.empty((0, nf, nq)), np.empty((nf, nq)), peaks)
    return peaks


# error_model="numpy": a division by zero gives inf (IEEE), not a branch that raises,
# which would keep LLVM from vectorising the lane loop (integrators/lanes.py)
@njit(cache=True, nogil=True, error_model="numpy")
def _peaks_lanes(model, Y, p, peaks):
    """``_forces_loop``'s peaks (into ``peaks``) in uniform air, LANES samples at a time through the lane
    family_forces (derive/lanes.py: each lane's forces equal the scalar kernel's bit for
    bit, and a largest |Q| does not depend on the order the samples come in).  Measured
    on an AVX-512 EPYC, SatI: 21 ns a sample against 52 ns one at a time."""
    Y, p, peaks = borrow(Y), borrow(p), borrow(peaks)
    nf, nq = model_shape(model)
    ns, n = Y.shape[1], Y.shape[0]
    YL, PL = np.zeros(ns * LANES), np.zeros(p.shape[0] * LANES)
    out, S = np.zeros(nf * nq * LANES), np.zeros(model_transcendentals(model) * LANES)
    PK = np.zeros(nq * LANES)  # each lane's peaks
    for i in range(p.shape[0]):
        for k in range(LANES):
            PL[i * LANES + k] = p[i]
    for i0 in range(0, n, LANES):
        K = min(LANES, n - i0)
        for i in range(ns):
            for k in range(K):
                YL[i * LANES + k] = Y[i0 + k, i]
        model_family_forces_lanes(model, K, YL, PL, out, S)
        # every lane, K or not: a lane past K holds forces already counted (or zeros)
        for f in range(nf):
            for q in range(nq):
                for k in range(LANES):
                    a = abs(out[(f * nq + q) * LANES + k])
                    m = PK[q * LANES + k]
                    PK[q * LANES + k] = a if a > m else m
    for q in range(nq):
        for k in range(LANES):
            a = PK[q * LANES + k]
            if a > peaks[q]:
                peaks[q] = a


@njit(cache=True)
def _chain_power_series(model, air, T, Y, p):
    """A bead chain's power of drag and dampers [W] at each sample (T[i], Y[i])."""
    literally(model)
    n = Y.shape[0]
    out = np.empty(n)
    pw = p.copy()
    fam = np.empty((N_FAMILIES, 3))
    for i in range(n):
        par = p
        if air[0] != UNIFORM:
            model_densities(model, T[i], Y[i], p, pw, air)
            par = pw
        out[i] = model_power(model, Y[i], par, fam)
    return out


@njit(cache=True)
def _tether_margin_series(model, Y, p):
    """g[i, j] = λ_j − l_j0 [m] of tether j at sample i (taut when positive)."""
    literally(model)
    n = Y.shape[0]
    out = np.empty((n, 2))
    Y, p, o = borrow(Y), borrow(p), borrow(out)  # ``out`` lives to the return
    for i in range(n):
        model_tether_margins(model, Y[i], p, o[i])
    return out


def family_forces_series(model: int, air, T, Y, p) -> np.ndarray:
    """Q[i, f, k]: generalized force of family f on coordinate k at sample (T[i], Y[i]) (SI).

    ``model``: the model index; ``air``: the run's air vector (dynamics.derivative).
    """
    return call(_family_forces_series, model, air, T, Y, p)


def jacobi_series(model: int, Y, p) -> np.ndarray:
    """Jacobi integral (+ spring energy) [J] at each sample (model index ``model``)."""
    return call(_jacobi_series, model, Y, p)


def chain_power_series(model: int, air, T, Y, p) -> np.ndarray:
    """A bead chain's power of drag and dampers [W] at each sample (chain model index
    ``model``, air vector ``air``): the rate of its Jacobi integral (beads.chain_power)."""
    return call(_chain_power_series, model, air, T, Y, p)


@njit(cache=True, nogil=True)
def _family_force_peaks_of(model, air, T, Y, p):
    # on borrowed views: the types a sweep's compiled blocks pass _family_force_peaks
    # (experiments/sweep/kernel.py _measure), so one compiled loop serves both
    literally(model)
    return _family_force_peaks(model, borrow(air), borrow(T), borrow(Y), borrow(p))


def family_force_peaks(model: int, air, T, Y, p) -> np.ndarray:
    """Largest |Q| of any single family on each coordinate over the samples (model index
    ``model``, air vector ``air``; C-contiguous float arrays); the loop releases the GIL."""
    return call(_family_force_peaks_of, model, air, T, Y, p)


def tether_margin_series(model: int, Y, p) -> np.ndarray:
    """g[i, j] = λ_j − l_j0 [m] of tether j at sample i (taut when positive; model index ``model``)."""
    return call(_tether_margin_series, model, Y, p)
