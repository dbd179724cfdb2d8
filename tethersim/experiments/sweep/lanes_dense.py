"""The adaptive sweep lanes' dense output: steps wait in a queue for their interpolant.

DOP853's interpolant needs three more stages of a step in which an output falls.
With 200 outputs an orbit and about 800 steps, 1-2 of a pass's lanes need them, so
computing them on every lane of the pass (sweep/lanes853.py) left three quarters of
that work idle.  Instead such a step (its start and end, stages 0-12, parameters,
step and output rows) is copied into one of LANES slots in the lane layout
(:func:`enqueue`), and a full queue, or one whose lane is about to be measured,
computes the three stages and the coefficients on all slots at once
(``dop853_lanes_dense``, each slot's numbers those of the scalar ``dop853_dense``)
and writes each slot's outputs (:func:`flush`).  The bench's 64-point sweep went
from 107.7-108.0 to 99.6-101.0 ms on one thread (AMD EPYC Zen 4, 2026-12-05), the
same records.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from tethersim.engine.integrators.dop853_lanes import (
    dop853_lanes_dense,
    dop853_lanes_interpolate,
)
from tethersim.engine.integrators.lanes import LANES
from tethersim.engine.integrators.steps import N_K


@njit(cache=True)
def queue(m, npar):
    """The queue's arrays for states of m = n*LANES rows and npar parameters: QY, QYn,
    QH, QP, QK, QHR (the slots in the lane layout; a slot never read holds zeros, not
    uninitialised data), QT (each slot's start time and step) and QI (its lane, point
    and output rows r0, r1)."""
    return (np.zeros(m), np.zeros(m), np.zeros(LANES), np.zeros(npar * LANES),
            np.zeros(N_K * m), np.zeros(m), np.zeros((LANES, 2)),
            np.zeros((LANES, 4), dtype=np.int64))


@njit(cache=True, nogil=True)
def flush(model, out_y, T, QY, QYn, QH, QP, QK, QHR, QT, QI, YS, Fd, S, queued):
    """The interpolant of every queued step (one ``dop853_lanes_dense`` over the slots of
    the :func:`queue`, the scalar ``dop853_dense``'s numbers slot by slot) and their
    outputs; returns 0, the queue's new length."""
    if queued == 0:
        return 0
    ns = out_y.shape[2]
    dop853_lanes_dense(model, QY, QYn, QH, QP, QK, YS, Fd, S, QHR)
    for q in range(queued):
        k, j, r0, r1 = QI[q, 0], QI[q, 1], QI[q, 2], QI[q, 3]
        t, h = QT[q, 0], QT[q, 1]
        for i_out in range(r0, r1):
            dop853_lanes_interpolate(ns, q, Fd, QY, (T[j, i_out] - t) / h, out_y[k, i_out])
    return 0


# inlined, and unsigned indices (dop853_lanes.U2 says why): a call that passes twenty
# arrays, 64,000 times in the bench's 64-point sweep, took 3-4 of its 104 ms
@njit(cache=True, nogil=True, inline="always")
def enqueue(k, j, i_out, t, h, npar, T, Y, Y_new, PL, Ks, QY, QYn, QH, QP, QK, QHR, QT, QI,
            queued):
    """Lane k's accepted step from t by h (point j, its next output row i_out), in which
    an output falls, into queue slot ``queued`` (its outputs written at the next
    :func:`flush`); returns the queue's new length and the point's next output row."""
    ns = Y.shape[0] // LANES
    m = ns * LANES
    q = queued
    rows = T.shape[1]
    uk, uq, ul = np.uint64(k), np.uint64(q), np.uint64(LANES)
    for i in range(ns):
        a, b = np.uint64(i) * ul + uk, np.uint64(i) * ul + uq
        QY[b] = Y[a]
        QYn[b] = Y_new[a]
        QHR[b] = h
    for s in range(N_K - 3):  # the step's stages 0..12 (the dense ones are computed)
        for i in range(ns):
            o = np.uint64(s * m + i * LANES)
            QK[o + uq] = Ks[o + uk]
    for i in range(npar):
        QP[np.uint64(i) * ul + uq] = PL[np.uint64(i) * ul + uk]
    QH[q] = h
    QT[q, 0], QT[q, 1] = t, h
    r0 = i_out
    while i_out < rows and T[j, i_out] <= t + h:
        i_out += 1
    QI[q, 0], QI[q, 1], QI[q, 2], QI[q, 3] = k, j, r0, i_out
    return queued + 1, i_out
