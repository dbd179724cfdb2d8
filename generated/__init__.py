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
