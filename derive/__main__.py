"""``python -m derive [OUTDIR]``: regenerate generated/ (default) from the derivation."""
from __future__ import annotations

import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from . import codegen
from .coordinates import ALL
from .emit import module_source
from .model import derive
from .models import DEFINITIONS, FAMILY_ORDER
from .printer import module_filename
from .trig import trig_source


def _group(index: int, out: Path) -> list:
    """Derive and print every model on the coordinates ALL[index]; lines to print.

    One process per set of coordinates: variants that differ in forces only
    share their Lagrange step (cached in the process).
    """
    lines = []
    for defn in DEFINITIONS:
        if defn.coordinates == ALL[index]:
            fname = module_filename(defn.name)
            (out / fname).write_text(module_source(derive(defn)))
            lines.append(f"  {defn.name:<24} -> {out.name}/{fname}")
    if index == 0:  # the planar circular index tables
        (out / "layout.py").write_text(codegen.layout_source(FAMILY_ORDER))
    return lines


# submitted longest first (the 3-D free pair shares one Lagrange derivation and takes
# about as long as the other three together), so two workers finish close together
LONGEST_FIRST = (3, 1, 0, 2)


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else Path(__file__).resolve().parent.parent / "generated"
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    # the four families share nothing but their inputs: one process each, as many at a
    # time as there are cores (each writes its own files; the output is the same bytes)
    workers = min(len(ALL), os.cpu_count() or 1)
    with ProcessPoolExecutor(max_workers=workers) as pool:
        futures = {i: pool.submit(_group, i, out) for i in LONGEST_FIRST}
        for i in range(len(ALL)):
            print("\n".join(futures[i].result()))
    every = DEFINITIONS
    modules = [module_filename(d.name)[:-3] for d in every]
    init = ['"""GENERATED FILE - DO NOT EDIT.  Numba kernels of every model, by name.',
            "",
            "Each module carries its own layout (STATE, STATE_UNITS, PARAMETERS,",
            "PARAMETER_UNITS, FAMILIES), what it models (DESCRIPTION, GEOMETRY, ORBIT)",
            "and the kernels rhs, family_forces, jacobi, tether_margins and body_radii;",
            "the thesis's planar models also jacobian (tethersim/engine/jacobian.py",
            "differentiates the others' rhs).  tethersim.model.registry reads this table;",
            'nothing else lists the models."""',
            "from . import (", *(f"    {n}," for n in sorted(modules)), ")", "",
            "MODELS = {", *(f"    {d.name!r}: {n}," for d, n in zip(every, modules)), "}", ""]
    (out / "__init__.py").write_text("\n".join(init))
    (out / "trig.py").write_text(trig_source())
    print(f"derive: {len(every)} models in {time.perf_counter() - t0:.1f} s "
          f"({workers} processes)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
