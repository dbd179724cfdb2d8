"""``python -m derive [OUTDIR]``: regenerate generated/ (default) from the derivation."""
from __future__ import annotations

import sys
import time
from pathlib import Path

from . import codegen
from .kinematics import planar_kinematics
from .models import DEFINITIONS, FAMILY_ORDER
from .pipeline import derive
from .symbols import STATE_SYMBOLS, state_substitution


def clear_numba_cache(root: Path) -> int:
    """Delete numba's on-disk caches under root.

    numba's cache=True revalidates a function against its own source file only:
    tethersim/dynamics.py, which inlines generated kernels, would keep running
    the old equations after a regeneration.
    """
    n = 0
    for pattern in ("*.nbi", "*.nbc"):
        for f in root.glob(f"**/__pycache__/{pattern}"):
            if ".venv" not in f.parts:
                f.unlink()
                n += 1
    return n


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    repo = Path(__file__).resolve().parent.parent
    out = Path(argv[0]) if argv else repo / "generated"
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
            "from . import layout", *(f"from . import {n}" for n in names), "",
            "MODELS = {", *(f"    {d.name!r}: {n}," for d, n in zip(DEFINITIONS, names)), "}", ""]
    (out / "__init__.py").write_text("\n".join(init))
    (out / "dispatch.py").write_text(codegen.dispatch_source(DEFINITIONS))
    cleared = clear_numba_cache(repo) if out.resolve() == repo / "generated" else 0
    print(f"derive: {len(names)} models in {time.perf_counter() - t0:.1f} s; "
          f"cleared {cleared} numba cache files")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
