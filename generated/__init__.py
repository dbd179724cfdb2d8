"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model, by name.

Each module carries its own layout (STATE, STATE_UNITS, PARAMETERS,
PARAMETER_UNITS, FAMILIES), what it models (DESCRIPTION, GEOMETRY, ORBIT)
and the kernels rhs, family_forces, jacobi, jacobian, tether_margins and
body_radii.  tethersim.model.registry reads this table; nothing else lists
the models."""
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
