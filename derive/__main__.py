"""``python -m derive [OUTDIR]``: regenerate generated/ (default) from the derivation."""
from __future__ import annotations

import sys
import time
from pathlib import Path

from . import codegen, orbit_codegen
from .kinematics import planar_kinematics
from .models import DEFINITIONS, FAMILY_ORDER
from .pipeline import derive
from .symbols import state_substitution


CACHE_PRELUDE = r'''import hashlib
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
    free = orbit_codegen.write_free_models(out)  # free orbit (issue 12), own layout
    for fname in free:
        print(f"  {fname[:-3].replace('_', '-'):<17} -> {out.name}/{fname}")
    print(f"derive: {len(names) + len(free)} models in {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
