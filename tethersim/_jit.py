"""Where numba keeps compiled kernels, and one message when it has to compile.

numba revalidates a cached function against its own source file only, so a
loop that inlines an edited kernel from another file would keep running stale
machine code.  The cache folder is therefore keyed on a hash of every source
file that holds compiled code (the generated kernels, and any tethersim module
with a numba decorator: ``@njit``, ``@intrinsic``, ``@overload``) plus the
modules whose constants compiled code bakes in (:data:`BAKED`): editing one of
them starts a fresh folder, editing anything else (the CLI, plots, docs)
reuses the compiled kernels.

This module is imported first by ``tethersim/__init__.py``: numba reads
``numba.config.CACHE_DIR`` when a ``cache=True`` function is decorated, so it
must be set before any kernel module is imported.

Folder: ``$TETHERSIM_CACHE_DIR`` if set, else ``$NUMBA_CACHE_DIR``, else
``~/.cache/tethersim/numba`` (``$XDG_CACHE_HOME`` honoured), then ``/<hash>``.

It also sets the vector width, before any kernel is compiled: on a CPU with AVX-512,
LLVM's tuning for Intel's server cores (Skylake-X to Emerald Rapids) prefers 256-bit
vectors (its ``prefer-256-bit`` feature), so the SIMD lanes of a sweep
(engine/integrators/lanes.py, 8 points) ran as two 4-wide halves.  :func:`vector_features`
turns that preference off: the same IEEE operations in the same order, so the same bits
(the lanes' and the reference runs' tests), in 512-bit registers.  Measured on an Intel
Xeon (Emerald Rapids, 2 cores), the bench's 64-point 5-orbit sweep on one thread: 95.5 ms
with 256-bit vectors, 82.3 ms with 512.  A ``NUMBA_CPU_FEATURES`` or ``NUMBA_CPU_NAME``
of the user's own is kept as it is (numba's cache keys on the CPU and its features, so
each setting has its own kernels).
"""
from __future__ import annotations

import hashlib
import os
import re
from pathlib import Path

import numba

PACKAGE = Path(__file__).resolve().parent
# modules without a numba decorator whose values compiled code captures as constants
BAKED = ("model/constants.py", "engine/integrators/dop853_tableau.py")
DECORATOR = re.compile(r"@(njit|intrinsic|overload|jit)\b")


def _generated_folder() -> Path:
    # the generated kernels are installed as tethersim.generated; in a source
    # checkout that package is the top-level folder generated/ (pyproject package-dir)
    from importlib.util import find_spec
    spec = find_spec("tethersim.generated")
    return Path(next(iter(spec.submodule_search_locations)))


def jitted_sources() -> list:
    """Source files holding jitted code, in a fixed order (the cache key's input)."""
    files = sorted(_generated_folder().glob("*.py"))
    for f in sorted(PACKAGE.rglob("*.py")):
        rel = f.relative_to(PACKAGE).as_posix()
        if rel in BAKED or DECORATOR.search(f.read_text(encoding="utf-8")):
            files.append(f)
    return files


def cache_key() -> str:
    """16 hex digits of the SHA-1 of every jitted source file."""
    digest = hashlib.sha1()
    for f in jitted_sources():
        digest.update(f.name.encode())
        digest.update(f.read_bytes())
    return digest.hexdigest()[:16]


def cache_base() -> str:
    """The folder under which the keyed cache folders live."""
    base = os.environ.get("TETHERSIM_CACHE_DIR") or os.environ.get("NUMBA_CACHE_DIR")
    if base:
        return base
    home = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(home, "tethersim", "numba")


def vector_features() -> str | None:
    """numba's CPU features with 512-bit vectors preferred, where the host has AVX-512 and
    the user set none of ``NUMBA_CPU_FEATURES``, ``NUMBA_CPU_NAME`` (``make test-generic``)
    and ``NUMBA_ENABLE_AVX=0``; else None (numba's own choice stands)."""
    config = numba.config
    if config.CPU_FEATURES is not None or config.CPU_NAME is not None or not config.ENABLE_AVX:
        return None
    import llvmlite.binding as ll
    try:
        features = ll.get_host_cpu_features()
    except RuntimeError:  # a host LLVM cannot describe: numba's default
        return None
    if not features.get("avx512f"):
        return None
    return features.flatten() + ",-prefer-256-bit"


if (_features := vector_features()) is not None:
    numba.config.CPU_FEATURES = _features

CACHE_KEY = cache_key()  # of the sources this process loaded (read once: ~6 ms)
CACHE_DIR = os.path.join(cache_base(), CACHE_KEY)
numba.config.CACHE_DIR = CACHE_DIR
