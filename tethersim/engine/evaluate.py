"""Jitted loops that evaluate generated functions along a trajectory."""
from __future__ import annotations

import numpy as np
from numba import njit

from tethersim.generated import dispatch

from tethersim.engine.dynamics import CFG_MODEL, CFG_PER_BODY, N_ATTITUDE, body_densities


@njit(cache=True, nogil=True)  # nogil: sweeps evaluate forces on threads
def family_forces_series(cfg, Y, p):
    """Q[i, f, k]: generalized force of family f on q_k at sample i."""
    n = Y.shape[0]
    out = np.zeros((n, 7, 3))
    pw = p.copy()
    for i in range(n):
        par = p
        if cfg[CFG_PER_BODY] == 1:
            body_densities(Y[i], p, pw)
            par = pw
        dispatch.family_forces(cfg[CFG_MODEL], Y[i, :N_ATTITUDE], par, out[i])
    return out


@njit(cache=True)
def jacobi_series(cfg, Y, p):
    """Jacobi integral (+ spring energy) [J] at each sample."""
    n = Y.shape[0]
    out = np.empty(n)
    for i in range(n):
        out[i] = dispatch.jacobi(cfg[CFG_MODEL], Y[i, :N_ATTITUDE], p)
    return out


@njit(cache=True, nogil=True)
def family_force_peaks(cfg, Y, p):
    """Largest |Q| of any single family on each coordinate over the samples (3,).

    What a sweep keeps of the force breakdown, without the (n, 7, 3) array and
    without holding the GIL (threads of a sweep run this side by side).
    """
    out = np.zeros(3)
    q = np.zeros((7, 3))
    pw = p.copy()
    for i in range(Y.shape[0]):
        par = p
        if cfg[CFG_PER_BODY] == 1:
            body_densities(Y[i], p, pw)
            par = pw
        dispatch.family_forces(cfg[CFG_MODEL], Y[i, :N_ATTITUDE], par, q)
        for f in range(7):
            for k in range(3):
                a = abs(q[f, k])
                if a > out[k]:
                    out[k] = a
    return out
