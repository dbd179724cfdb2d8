"""``python -m derive [OUTDIR]``: regenerate generated/ (default) from the derivation."""
from __future__ import annotations

import sys
import time
from pathlib import Path

from . import codegen
from .kinematics import planar_kinematics
from .models import DEFINITIONS, FAMILY_ORDER
from .pipeline import derive
from .symbols import state_substitution


CACHE_PRELUDE = r'''import hashlib
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
'''.splitlines()


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else Path(__file__).resolve().parent.parent / "generated"
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    kin = planar_kinematics()
    sub = state_substitution()
    length_defs = {lam: d.subs(sub) for lam, d in kin.tether_length_defs.items()}
    names = []
    for defn in DEFINITIONS:
        model = derive(defn)
        fname = codegen.module_filename(defn.name)
        (out / fname).write_text(codegen.module_source(model, length_defs))
        names.append(fname[:-3])
        print(f"  {defn.name:<17} -> {out.name}/{fname}")
    (out / "layout.py").write_text(codegen.layout_source(FAMILY_ORDER))
    init = ['"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model variant."""',
            *CACHE_PRELUDE,
            "from . import layout  # noqa: E402", *(f"from . import {n}  # noqa: E402" for n in names), "",
            "MODELS = {", *(f"    {d.name!r}: {n}," for d, n in zip(DEFINITIONS, names)), "}", ""]
    (out / "__init__.py").write_text("\n".join(init))
    (out / "dispatch.py").write_text(codegen.dispatch_source(DEFINITIONS))
    print(f"derive: {len(names)} models in {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
