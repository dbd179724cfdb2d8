"""∂(dy/dt)/∂y of every model: generated where the analysis needs it, else central differences.

`make derive` writes an analytic ``jacobian`` kernel only for the models whose
analysis needs one to the last digits (the thesis's planar models: the torque
balance, the equilibrium's eigenvalues, the pitch prediction).  Every other
model (3-D, free orbit) gets its Jacobian here, by central differences of its
generated ``rhs`` in one compiled loop per model (literal model index, as in
tethersim.engine.dynamics): the RK4 step warning (tethersim.engine.linearise),
the 3-D equilibrium's Newton steps and the roll modes (tethersim.analysis.roll),
and the implicit scheme of the real-tether issue.

Step and error: column c is (f(y + h_c e_c) − f(y − h_c e_c)) / (2 h_c) with
h_c = ε^(1/3) max(|y_c|, 1) (ε = 2.2e-16, so ε^(1/3) = 6.1e-6; lengths in m,
angles in rad, rates in their SI units, so "1" is a metre, a radian, a m/s or a
rad/s), rounded so that y_c ± h_c is exact.  The truncation error is
h_c² |∂³f/∂y_c³| / 6 and the rounding error about ε |f| / h_c, both of relative
size ε^(2/3) ≈ 4e-11 for a component that varies on the scale of max(|y_c|, 1).
Where f carries terms much larger than its change the rounding grows with them:
the drag of the rate columns holds the ~7.3 km/s air speed (entries good to ~1e-9
of their row's largest), and a free orbit's accelerations the ~9 m/s² central
gravity that cancels against the centrifugal term (δ columns good to ~1e-4 of the
O(ω²) entries: ample for the RK4 step warning, the free models' only use).  A
column whose step crosses a tether's taut/slack switch (λ_j = l_j0 within h_c)
averages the two sides.  tests/engine/test_jacobian.py checks it against the
generated planar Jacobians; tests/derive/test_contract_symbolic.py against the
40-digit difference quotient of every model's derivation, and
tests/derive/test_3d_modes.py its modes against closed forms.
"""
from __future__ import annotations

import numpy as np
from numba import literally, njit
from numba.extending import overload

from tethersim.engine.dynamics import literal_index, model_rhs
from tethersim.engine.integrators.select import call
from tethersim.model.registry import MODELS, kernels_of, record

STEP = float(np.finfo(float).eps ** (1 / 3))  # relative step of the central differences


def analytic(model: int) -> bool:
    """True when `make derive` generated model ``model``'s Jacobian (module ``jacobian``)."""
    return hasattr(kernels_of(model), "jacobian")


def model_jacobian(model, t, y, p, J):
    """J = ∂(dy/dt)/∂y of model ``model`` (compiled code, literal model only)."""
    raise NotImplementedError("model_jacobian is only callable from compiled code")


@njit(cache=True, inline="always")
def _central_differences(model, t, y, p, J, yh, f):
    """J by central differences of model_rhs (module docstring); yh, f: scratch of len(y)."""
    n = y.shape[0]
    for c in range(n):
        yh[c] = y[c]
    for k in range(2 * n):  # one call site of the (inlined) rhs: columns c, sides +, −
        c = k // 2
        yc = y[c]
        h = STEP * max(abs(yc), 1.0)
        yh[c] = yc + h if k % 2 == 0 else yc - h
        model_rhs(model, t, yh, p, f)
        yh[c] = yc
        if k % 2 == 0:
            for i in range(n):
                J[i, c] = f[i]
        else:
            # the steps actually taken (y_c ± h rounded), so rounding of y_c ± h is no error
            width = (yc + h) - (yc - h)
            for i in range(n):
                J[i, c] = (J[i, c] - f[i]) / width


@overload(model_jacobian, prefer_literal=True)
def _model_jacobian(model, t, y, p, J):
    if (k := literal_index(model)) is None:
        return None
    if analytic(k):
        jac = kernels_of(k).jacobian

        def impl(model, t, y, p, J):
            jac(t, y, p, J)
        return impl

    def impl(model, t, y, p, J):
        n = y.shape[0]
        _central_differences(model, t, y, p, J, np.empty(n), np.empty(n))
    return impl


@njit(cache=True)
def _jacobian(model, t, y, p, J):
    literally(model)
    model_jacobian(model, t, y, p, J)


@njit(cache=True)
def _differences(model, t, y, p, J):
    literally(model)
    n = y.shape[0]
    _central_differences(model, t, y, p, J, np.empty(n), np.empty(n))


def _check(model: int, y, J) -> None:
    n = MODELS[model].n_state if model < len(MODELS) else y.shape[0]  # a chain: any N
    if y.shape != (n,) or J.shape != (n, n):
        raise ValueError(f"y has shape {y.shape} and J {J.shape}: model "
                         f"{record(model).name!r} needs ({n},) and ({n}, {n})")


def central_differences(model: int, t: float, y, p, J) -> None:
    """Write the central-difference Jacobian of model ``model``'s rhs into ``J``.

    What :func:`jacobian` gives for a model with no generated Jacobian; callable
    for every model (the tests compare it with the generated ones).  Arguments
    as :func:`jacobian`.
    """
    _check(model, y, J)
    call(_differences, model, float(t), y, p, J)


def jacobian(model: int, t: float, y, p, J) -> None:
    """Write ∂(dy/dt)/∂y of model index ``model`` at (t, y) into ``J`` (from Python).

    Parameters
    ----------
    model : int
        Index in :data:`tethersim.model.registry.MODELS`.
    t : float
        Time [s].
    y : numpy.ndarray
        The model's own state (its ``STATE`` order, C-contiguous float64).
    p : numpy.ndarray
        Its parameter vector.
    J : numpy.ndarray
        (n, n) output, n = ``MODELS[model].n_state``: J[i, j] = ∂(dy_i/dt)/∂y_j (SI per SI).

    Notes
    -----
    A generated Jacobian is called as it is (no compile of a loop around it); the
    others go through the compiled central differences of the model's rhs.
    """
    _check(model, y, J)
    if analytic(model):
        kernels_of(model).jacobian(t, y, p, J)
    else:
        call(_jacobian, model, float(t), y, p, J)
