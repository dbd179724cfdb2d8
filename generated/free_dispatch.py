"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/orbit_codegen.py.

Free-orbit models (state and parameter layout in each module's STATE, PARAMETERS).
"""
from numba import njit

from . import free
from . import free_exact_gravity
from . import free_objective_damper

MODEL_NAMES = ('free', 'free-exact-gravity', 'free-objective-damper')
STATE = free.STATE
PARAMETERS = free.PARAMETERS


@njit(cache=True)
def rhs(model, t, y, p, dydt):
    """rhs of free model MODEL_NAMES[model]."""
    if model == 0:
        free.rhs(t, y, p, dydt)
    elif model == 1:
        free_exact_gravity.rhs(t, y, p, dydt)
    elif model == 2:
        free_objective_damper.rhs(t, y, p, dydt)

@njit(cache=True)
def family_forces(model, y, p, out):
    """family_forces of free model MODEL_NAMES[model]."""
    if model == 0:
        free.family_forces(y, p, out)
    elif model == 1:
        free_exact_gravity.family_forces(y, p, out)
    elif model == 2:
        free_objective_damper.family_forces(y, p, out)

@njit(cache=True)
def jacobi(model, y, p):
    """jacobi of free model MODEL_NAMES[model]."""
    if model == 0:
        return free.jacobi(y, p)
    elif model == 1:
        return free_exact_gravity.jacobi(y, p)
    elif model == 2:
        return free_objective_damper.jacobi(y, p)
    return 0.0

@njit(cache=True)
def jacobian(model, t, y, p, J):
    """jacobian of free model MODEL_NAMES[model]."""
    if model == 0:
        free.jacobian(t, y, p, J)
    elif model == 1:
        free_exact_gravity.jacobian(t, y, p, J)
    elif model == 2:
        free_objective_damper.jacobian(t, y, p, J)
