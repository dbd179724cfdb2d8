"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model variant."""
from . import layout
from . import derived
from . import printed
from . import exact_gravity
from . import objective_damper

MODELS = {
    'derived': derived,
    'printed': printed,
    'exact-gravity': exact_gravity,
    'objective-damper': objective_damper,
}

# 3-D models: their own state and parameter layout (generated/layout3d.py).
from . import three_d
from . import three_d_exact_gravity
from . import three_d_objective_damper

MODELS_3D = {
    '3d': three_d,
    '3d-exact-gravity': three_d_exact_gravity,
    '3d-objective-damper': three_d_objective_damper,
}
