"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/three_d/."""
from numba import njit

from . import three_d
from . import three_d_exact_gravity
from . import three_d_objective_damper

MODEL_NAMES = ('3d', '3d-exact-gravity', '3d-objective-damper')


@njit(cache=True)
def rhs(model, t, y, p, dydt):
    """rhs of model MODEL_NAMES[model]."""
    if model == 0:
        three_d.rhs(t, y, p, dydt)
    elif model == 1:
        three_d_exact_gravity.rhs(t, y, p, dydt)
    elif model == 2:
        three_d_objective_damper.rhs(t, y, p, dydt)

@njit(cache=True)
def family_forces(model, y, p, out):
    """family_forces of model MODEL_NAMES[model]."""
    if model == 0:
        three_d.family_forces(y, p, out)
    elif model == 1:
        three_d_exact_gravity.family_forces(y, p, out)
    elif model == 2:
        three_d_objective_damper.family_forces(y, p, out)

@njit(cache=True)
def jacobi(model, y, p):
    """jacobi of model MODEL_NAMES[model]."""
    if model == 0:
        return three_d.jacobi(y, p)
    elif model == 1:
        return three_d_exact_gravity.jacobi(y, p)
    elif model == 2:
        return three_d_objective_damper.jacobi(y, p)
    return 0.0

@njit(cache=True)
def jacobian(model, t, y, p, J):
    """jacobian of model MODEL_NAMES[model]."""
    if model == 0:
        three_d.jacobian(t, y, p, J)
    elif model == 1:
        three_d_exact_gravity.jacobian(t, y, p, J)
    elif model == 2:
        three_d_objective_damper.jacobian(t, y, p, J)
