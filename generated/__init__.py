"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model variant."""
import hashlib
import os
from pathlib import Path

import numba

# Every file holding jitted code, or constants that jitted code bakes in,
# relative to the repository root.  Only these key the cache: editing any other
# file (the CLI, plotting, docs) reuses the compiled kernels.  Moving a kernel
# module means editing this list in derive/__main__.py and `make derive`;
# tests/test_engine_cache.py fails if a jitted module is missing here.
KERNEL_SOURCES = (
    "generated/*.py",
    "tethersim/atmosphere.py",
    "tethersim/constants.py",
    "tethersim/dynamics.py",
    "tethersim/evaluate.py",
    "tethersim/integrators/*.py",
)


def kernel_source_files() -> list:
    """The files of KERNEL_SOURCES that exist, in a fixed order."""
    root = Path(__file__).resolve().parent.parent
    return [f for pattern in KERNEL_SOURCES for f in sorted(root.glob(pattern))]


def cache_base_dir() -> str:
    """TETHERSIM_CACHE_DIR, else NUMBA_CACHE_DIR, else ~/.cache/tethersim/numba."""
    return (os.environ.get("TETHERSIM_CACHE_DIR") or os.environ.get("NUMBA_CACHE_DIR")
            or os.path.join(os.environ.get("XDG_CACHE_HOME")
                            or os.path.join(os.path.expanduser("~"), ".cache"),
                            "tethersim", "numba"))


def _source_keyed_cache_dir() -> str:
    """numba's on-disk cache folder, keyed on the jitted source files.

    numba revalidates a cached function against its own file only, so a loop
    that inlines an edited generated kernel (or an edited engine helper) would
    keep running the old code.  Hashing every kernel source (KERNEL_SOURCES)
    into the folder name makes any edit of them start a fresh cache.
    """
    root = Path(__file__).resolve().parent.parent
    digest = hashlib.sha1()
    for f in kernel_source_files():
        digest.update(f.relative_to(root).as_posix().encode())
        digest.update(f.read_bytes())
    return os.path.join(cache_base_dir(), digest.hexdigest()[:16])


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
