"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model, by name.

Each module carries its own layout (STATE, STATE_UNITS, PARAMETERS,
PARAMETER_UNITS, FAMILIES), what it models (DESCRIPTION, GEOMETRY, ORBIT)
and the kernels rhs, family_forces, jacobi, tether_margins and body_radii;
the thesis's planar models also jacobian (tethersim/engine/jacobian.py
differentiates the others' rhs).  tethersim.model.registry reads this table;
nothing else lists the models."""
from . import (
    derived,
    exact_gravity,
    free,
    free_exact_gravity,
    free_objective_damper,
    objective_damper,
    printed,
    three_d,
    three_d_exact_gravity,
    three_d_free,
    three_d_free_objective_damper,
    three_d_objective_damper,
)

MODELS = {
    'derived': derived,
    'printed': printed,
    'exact-gravity': exact_gravity,
    'objective-damper': objective_damper,
    '3d': three_d,
    '3d-exact-gravity': three_d_exact_gravity,
    '3d-objective-damper': three_d_objective_damper,
    'free': free,
    'free-exact-gravity': free_exact_gravity,
    'free-objective-damper': free_objective_damper,
    '3d-free': three_d_free,
    '3d-free-objective-damper': three_d_free_objective_damper,
}
