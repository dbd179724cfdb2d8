"""Locating taut/slack switches of the tethers inside a step.

A tether is taut when its margin g = λ − l0 > 0 (Eqs 3.35-3.36).  When a step
from y to y_new changes the tautness of a tether, the step size τ that lands
on the switch is found by Illinois (modified regula falsi) iteration on
φ(τ) = g(step(y, τ)), using the integrator's own step so that the landing
point is as accurate as a normal step.  The returned τ is the bracket end
just *past* the switch, so the next step starts on the new side and its
right-hand side is smooth.
"""
from __future__ import annotations

from numba import njit

from tethersim.engine.dynamics import model_tether_margins
from tethersim.engine.integrators.steps import copy_into, dop853_step, rk4_step

RTOL_TAU = 1e-12  # bracket width, relative to the step, at which the search stops
MAX_ITER = 60


@njit(cache=True)
def crossed(g0, g1):
    """Index of a tether whose tautness differs between g0 and g1, else -1."""
    for j in range(g0.shape[0]):
        if (g0[j] > 0.0) != (g1[j] > 0.0):
            return j
    return -1


@njit(cache=True)
def _trial(method, model, air, t, y, f, tau, p, pw, work, y_new, g):
    if method == 0:
        rk4_step(model, air, t, y, tau, p, pw, work, y_new)
    else:
        dop853_step(model, air, t, y, f, tau, p, pw, work[:16], work[16], y_new)
    model_tether_margins(model, y_new, p, g)


# Out of line on purpose: switches are rare, and keeping this search (with its
# own copies of the step functions) out of the time loops keeps them small.
@njit(cache=True)
def locate(method, model, air, t, y, f, h, p, pw, work, y_new, g0, g1, g):
    """Step size τ in (0, h] landing just past the earliest switch.

    method 0: RK4 (work is (5, n)); method 1: DOP853 (work is (17, n): stages
    then a stage state; f = f(t, y)).  model, air: dynamics.derivative.
    g is a scratch vector like g1.  On return y_new holds step(y, τ).
    """
    tau_best = h
    copy_into(g, g1)
    for j in range(g0.shape[0]):
        if (g0[j] > 0.0) == (g1[j] > 0.0):
            continue
        lo, hi = 0.0, tau_best
        f_lo = g0[j]
        _trial(method, model, air, t, y, f, hi, p, pw, work, y_new, g)
        f_hi = g[j]
        if (f_hi > 0.0) == (f_lo > 0.0):
            continue  # no switch of this tether before an earlier one
        side = 0
        for _ in range(MAX_ITER):
            if hi - lo <= RTOL_TAU * h:
                break
            mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
            if not (lo < mid < hi):
                mid = 0.5 * (lo + hi)
            _trial(method, model, air, t, y, f, mid, p, pw, work, y_new, g)
            f_mid = g[j]
            if (f_mid > 0.0) == (f_lo > 0.0):
                lo, f_lo = mid, f_mid
                if side == -1:
                    f_hi *= 0.5
                side = -1
            else:
                hi, f_hi = mid, f_mid
                if side == 1:
                    f_lo *= 0.5
                side = 1
        tau_best = hi
    _trial(method, model, air, t, y, f, tau_best, p, pw, work, y_new, g1)
    return tau_best
