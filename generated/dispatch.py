"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/codegen.py."""
from numba import njit

from . import derived
from . import printed
from . import exact_gravity
from . import objective_damper
from . import three_d
from . import three_d_exact_gravity
from . import three_d_objective_damper
from . import free
from . import free_exact_gravity
from . import free_objective_damper
from . import three_d_free
from . import three_d_free_objective_damper

MODEL_NAMES = ('derived', 'printed', 'exact-gravity', 'objective-damper', '3d', '3d-exact-gravity', '3d-objective-damper', 'free', 'free-exact-gravity', 'free-objective-damper', '3d-free', '3d-free-objective-damper')


@njit(cache=True)
def rhs(model, t, y, p, dydt):
    """rhs of model MODEL_NAMES[model]."""
    if model == 0:
        derived.rhs(t, y, p, dydt)
    elif model == 1:
        printed.rhs(t, y, p, dydt)
    elif model == 2:
        exact_gravity.rhs(t, y, p, dydt)
    elif model == 3:
        objective_damper.rhs(t, y, p, dydt)
    elif model == 4:
        three_d.rhs(t, y, p, dydt)
    elif model == 5:
        three_d_exact_gravity.rhs(t, y, p, dydt)
    elif model == 6:
        three_d_objective_damper.rhs(t, y, p, dydt)
    elif model == 7:
        free.rhs(t, y, p, dydt)
    elif model == 8:
        free_exact_gravity.rhs(t, y, p, dydt)
    elif model == 9:
        free_objective_damper.rhs(t, y, p, dydt)
    elif model == 10:
        three_d_free.rhs(t, y, p, dydt)
    elif model == 11:
        three_d_free_objective_damper.rhs(t, y, p, dydt)

@njit(cache=True)
def family_forces(model, y, p, out):
    """family_forces of model MODEL_NAMES[model]."""
    if model == 0:
        derived.family_forces(y, p, out)
    elif model == 1:
        printed.family_forces(y, p, out)
    elif model == 2:
        exact_gravity.family_forces(y, p, out)
    elif model == 3:
        objective_damper.family_forces(y, p, out)
    elif model == 4:
        three_d.family_forces(y, p, out)
    elif model == 5:
        three_d_exact_gravity.family_forces(y, p, out)
    elif model == 6:
        three_d_objective_damper.family_forces(y, p, out)
    elif model == 7:
        free.family_forces(y, p, out)
    elif model == 8:
        free_exact_gravity.family_forces(y, p, out)
    elif model == 9:
        free_objective_damper.family_forces(y, p, out)
    elif model == 10:
        three_d_free.family_forces(y, p, out)
    elif model == 11:
        three_d_free_objective_damper.family_forces(y, p, out)

@njit(cache=True)
def jacobi(model, y, p):
    """jacobi of model MODEL_NAMES[model]."""
    if model == 0:
        return derived.jacobi(y, p)
    elif model == 1:
        return printed.jacobi(y, p)
    elif model == 2:
        return exact_gravity.jacobi(y, p)
    elif model == 3:
        return objective_damper.jacobi(y, p)
    elif model == 4:
        return three_d.jacobi(y, p)
    elif model == 5:
        return three_d_exact_gravity.jacobi(y, p)
    elif model == 6:
        return three_d_objective_damper.jacobi(y, p)
    elif model == 7:
        return free.jacobi(y, p)
    elif model == 8:
        return free_exact_gravity.jacobi(y, p)
    elif model == 9:
        return free_objective_damper.jacobi(y, p)
    elif model == 10:
        return three_d_free.jacobi(y, p)
    elif model == 11:
        return three_d_free_objective_damper.jacobi(y, p)
    return 0.0

@njit(cache=True)
def jacobian(model, t, y, p, J):
    """jacobian of model MODEL_NAMES[model]."""
    if model == 0:
        derived.jacobian(t, y, p, J)
    elif model == 1:
        printed.jacobian(t, y, p, J)
    elif model == 2:
        exact_gravity.jacobian(t, y, p, J)
    elif model == 3:
        objective_damper.jacobian(t, y, p, J)
    elif model == 4:
        three_d.jacobian(t, y, p, J)
    elif model == 5:
        three_d_exact_gravity.jacobian(t, y, p, J)
    elif model == 6:
        three_d_objective_damper.jacobian(t, y, p, J)
    elif model == 7:
        free.jacobian(t, y, p, J)
    elif model == 8:
        free_exact_gravity.jacobian(t, y, p, J)
    elif model == 9:
        free_objective_damper.jacobian(t, y, p, J)
    elif model == 10:
        three_d_free.jacobian(t, y, p, J)
    elif model == 11:
        three_d_free_objective_damper.jacobian(t, y, p, J)
