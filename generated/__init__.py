"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model variant."""
import hashlib
import os
from pathlib import Path

import numba


def _source_keyed_cache_dir() -> str:
    """numba's on-disk cache folder, keyed on every kernel source file.

    numba revalidates a cached function against its own file only, so a loop in
    tethersim/ that inlines an edited generated kernel (or an edited tethersim
    helper) would keep running the old code.  Hashing all of generated/ and
    tethersim/ into the folder name makes any edit start a fresh cache.
    """
    here = Path(__file__).resolve().parent
    digest = hashlib.sha1()
    for folder in (here, here.parent / "tethersim"):
        for f in sorted(folder.rglob("*.py")):
            digest.update(f.read_bytes())
    base = os.environ.get("NUMBA_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"),
        "tethersim", "numba")
    return os.path.join(base, digest.hexdigest()[:16])


numba.config.CACHE_DIR = _source_keyed_cache_dir()
from . import layout  # noqa: E402
from . import derived  # noqa: E402
from . import printed  # noqa: E402
from . import exact_gravity  # noqa: E402
from . import objective_damper  # noqa: E402

MODELS = {
    'derived': derived,
    'printed': printed,
    'exact-gravity': exact_gravity,
    'objective-damper': objective_damper,
}

# 3-D models: their own state and parameter layout (generated/layout3d.py).
from . import three_d  # noqa: E402
from . import three_d_exact_gravity  # noqa: E402
from . import three_d_objective_damper  # noqa: E402

MODELS_3D = {
    '3d': three_d,
    '3d-exact-gravity': three_d_exact_gravity,
    '3d-objective-damper': three_d_objective_damper,
}
