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


CACHE_KEY = cache_key()  # of the sources this process loaded (read once: ~6 ms)
CACHE_DIR = os.path.join(cache_base(), CACHE_KEY)
numba.config.CACHE_DIR = CACHE_DIR
