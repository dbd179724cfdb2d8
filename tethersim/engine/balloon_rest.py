"""The balloon at rest for a boom held at pitch θ: a compiled 2-state Newton solve.

For a thesis model (state δx, δy, θ, δẋ, δẏ, θ̇) held at pitch θ with every rate zero,
:func:`balloon_rest` solves δẍ = δÿ = 0 (Eqs 3.48-3.49 as derived) for (δx, δy) by
Newton's method on the generated Jacobian's 2 × 2 balloon block, from ``trail``.  It is
the inner solve of tethersim.analysis.torque_balance.PitchTorque, which the predicted
stability maps call about sixty times a grid point: compiled together with the model's rhs and
Jacobian, rather than a Python loop over two kernel calls an iteration.

Units: SI.
"""
from __future__ import annotations

import math

from numba import literally, njit

from tethersim.engine.dynamics import model_rhs
from tethersim.engine.jacobian import model_jacobian


@njit(cache=True)
def balloon_rest(model, theta, trail, y, p, d, J, max_iter, step_tol, residual_tol):
    """Newton's method for the balloon's rest position at pitch θ.

    Parameters
    ----------
    model : int
        Model index (a compile-time literal): a thesis model, state (δx, δy, θ, δẋ, δẏ, θ̇).
    theta : float
        The boom's pitch [rad], held.
    trail : ndarray
        (2,) the start (δx, δy) [m]; overwritten with the solution when one is found.
    y, d : ndarray
        (6,) scratch: the state, and on success the rhs there (d[5] = θ̈ [rad/s²]).
    p : ndarray
        The model's parameter vector.
    J : ndarray
        (6, 6) scratch: the Jacobian.
    max_iter : int
        Newton iterations allowed.
    step_tol : float
        Converged when |Δδx| + |Δδy| [m] is at most this...
    residual_tol : float
        ...and then max(|δẍ|, |δÿ|) [m/s²] is at most this.

    Returns
    -------
    bool
        True when converged (``trail`` and ``d`` then hold the answer); False when a
        Jacobian block is singular or not finite, the iterate leaves the finite
        numbers, the residual test fails, or the iterations run out.
    """
    literally(model)
    for i in range(y.shape[0]):
        y[i] = 0.0
    y[0], y[1], y[2] = trail[0], trail[1], theta
    converged = False
    for it in range(max_iter + 1):
        # one call site of the (inlined) rhs: the residual of each iterate, and of the last
        model_rhs(model, 0.0, y, p, d)
        if converged:
            # written so that a NaN residual fails
            if abs(d[3]) <= residual_tol and abs(d[4]) <= residual_tol:
                trail[0], trail[1] = y[0], y[1]
                return True
            return False
        if it == max_iter:
            return False
        model_jacobian(model, 0.0, y, p, J)
        a11, a12, a21, a22 = J[3, 0], J[3, 1], J[4, 0], J[4, 1]
        det = a11 * a22 - a12 * a21
        if not (math.isfinite(det) and det != 0.0):
            return False
        sx = (a22 * d[3] - a12 * d[4]) / det
        sy = (a11 * d[4] - a21 * d[3]) / det
        y[0] -= sx
        y[1] -= sy
        converged = abs(sx) + abs(sy) <= step_tol
        if not converged and not (math.isfinite(y[0]) and math.isfinite(y[1])):
            return False
    return False
