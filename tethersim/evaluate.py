"""Jitted loops that evaluate generated functions along a trajectory."""
from __future__ import annotations

import numpy as np
from numba import njit

from generated import dispatch

from .dynamics import CFG_MODEL, CFG_PER_BODY, N_ATTITUDE, body_densities


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
