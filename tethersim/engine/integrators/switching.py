"""Locating events inside a step: tether switches and the stopping limits.

The events are the slots of engine/events.py's vector g(y), positive inside:
slots 0, 1 are the tethers' taut/slack margins λ_j − l_j0 (Eqs 3.35-3.36; the run
continues across them), the others the stopping limits (re-entry, roll, balloon
reach, tether stretch).  When a step from y to y_new changes the sign of a slot
that is watched, the step size τ that lands on the earliest crossing is found by
Illinois (modified regula falsi) iteration on φ(τ) = g_j(step(y, τ)), slot by
slot, each search bracketed by the best τ so far; the integrator's own step is
the trial, so that the landing point is as accurate as a normal step.  The
returned τ is the bracket end just *past* the crossing: after a switch the next
step starts on the new side and its right-hand side is smooth; after a stopping
limit the run ends just outside, |g_j| within the bracket's width times |ġ_j|.
"""
from __future__ import annotations

from numba import njit

from tethersim.engine.dynamics import model_size
from tethersim.engine.events import N_EVENTS, N_SWITCH, model_events
from tethersim.engine.integrators.steps import copy_into, dop853_step, rk4_step

RTOL_TAU = 1e-12  # bracket width, relative to the step, at which the search stops
MAX_ITER = 60


@njit(cache=True, inline="always")
def _crosses(j, a, b):
    """Whether slot j crosses from value a to b: a switch either way, a stopping limit
    from inside (> 0) to outside (<= 0; NaN is no crossing)."""
    if j < N_SWITCH or j >= N_EVENTS:  # a switch (events.is_switch)
        return (a > 0.0) != (b > 0.0)
    return a > 0.0 and b <= 0.0


@njit(cache=True)
def fired(g0, g1, switches):
    """Whether a watched slot changed sign from g0 to g1.

    The switch slots (both directions) only when ``switches``; a stopping limit
    whenever it goes from inside (> 0) to outside (<= 0; a NaN is no crossing:
    the loops report a non-finite state as such).
    """
    first, last = (0, g0.shape[0]) if switches else (N_SWITCH, N_EVENTS)
    for j in range(first, last):
        if _crosses(j, g0[j], g1[j]):
            return True
    return False


@njit(cache=True)
def _trial(method, model, air, t, y, f, tau, p, pw, ev, work, y_new, g, switches):
    if method == 0:
        rk4_step(model, air, t, y, tau, p, pw, work, y_new)
    elif method == 2:
        # Radau (integrators/radau.py): the step's collocation cubic, work[k] the
        # coefficient of τ^(k+1); the loop then retakes the step to land there
        for i in range(model_size(model, y)):
            y_new[i] = y[i] + tau * (work[0, i] + tau * (work[1, i] + tau * work[2, i]))
    else:
        dop853_step(model, air, t, y, f, tau, p, pw, work[:16], work[16], y_new)
    model_events(model, y_new, p, ev, g, switches)


# Out of line on purpose: events are rare, and keeping this search (with its own
# copies of the step functions) out of the time loops keeps them small.
@njit(cache=True)
def locate(method, model, air, t, y, f, h, p, pw, ev, work, y_new, g0, g1, g, switches):
    """(τ in (0, h] landing just past the earliest crossing, its slot).

    method 0: RK4 (work is (5, n)); method 1: DOP853 (work is (17, n): stages
    then a stage state; f = f(t, y)); method 2: Radau's dense output (work is
    (3, n), the cubic's coefficients per power of τ).  model, air: dynamics.derivative.
    g0, g1: the events at y and at step(y, h); g is a scratch vector like them.
    switches: whether the switch slots are watched (``fired``).  On return
    y_new holds step(y, τ) and g1 the events there.
    """
    tau_best = h
    j_best = -1
    copy_into(g, g1)
    first, last = (0, g0.shape[0]) if switches else (N_SWITCH, N_EVENTS)
    for j in range(first, last):
        if not _crosses(j, g0[j], g1[j]):
            continue
        lo, hi = 0.0, tau_best
        f_lo = g0[j]
        _trial(method, model, air, t, y, f, hi, p, pw, ev, work, y_new, g, switches)
        f_hi = g[j]
        if not _crosses(j, f_lo, f_hi):
            continue  # no crossing of this slot before an earlier one
        side = 0
        for _ in range(MAX_ITER):
            if hi - lo <= RTOL_TAU * h:
                break
            mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
            if not (lo < mid < hi):
                mid = 0.5 * (lo + hi)
            _trial(method, model, air, t, y, f, mid, p, pw, ev, work, y_new, g, switches)
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
        j_best = j
    _trial(method, model, air, t, y, f, tau_best, p, pw, ev, work, y_new, g1, switches)
    return tau_best, j_best
