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
            "from . import layout", *(f"from . import {n}" for n in names), "",
            "MODELS = {", *(f"    {d.name!r}: {n}," for d, n in zip(DEFINITIONS, names)), "}", ""]
    (out / "__init__.py").write_text("\n".join(init))
    (out / "dispatch.py").write_text(codegen.dispatch_source(DEFINITIONS))
    print(f"derive: {len(names)} models in {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
