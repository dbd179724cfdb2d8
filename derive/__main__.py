"""``python -m derive [OUTDIR]``: regenerate generated/ (default) from the derivation."""
from __future__ import annotations

import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from . import codegen, orbit_codegen
from .kinematics import planar_kinematics
from .models import DEFINITIONS, FAMILY_ORDER
from .pipeline import derive
from .printer import module_filename
from .symbols import state_substitution
from .three_d import codegen3d, free3d_codegen
from .three_d.free3d import FREE3D_DEFINITIONS
from .three_d.models3d import DEFINITIONS_3D
from .three_d.pipeline3d import derive3d


def _planar(out: Path) -> list:
    """The thesis's four variants and their layout; lines to print."""
    kin = planar_kinematics()
    sub = state_substitution()
    length_defs = {lam: d.subs(sub) for lam, d in kin.tether_length_defs.items()}
    lines = []
    for defn in DEFINITIONS:
        fname = module_filename(defn.name)
        (out / fname).write_text(codegen.module_source(derive(defn), length_defs, kin))
        lines.append(f"  {defn.name:<17} -> {out.name}/{fname}")
    (out / "layout.py").write_text(codegen.layout_source(FAMILY_ORDER))
    return lines


def _three_d(out: Path) -> list:
    """The 3-D models."""
    lines = []
    geometry3d = codegen3d.geometry_lines()
    for defn in DEFINITIONS_3D:
        fname = module_filename(defn.name)
        (out / fname).write_text(codegen3d.module_source(derive3d(defn), geometry3d))
        lines.append(f"  {defn.name:<19} -> {out.name}/{fname}")
    return lines


def _free(out: Path) -> list:
    """The free-orbit models (issue 12)."""
    return [f"  {f[:-3].replace('_', '-'):<17} -> {out.name}/{f}"
            for f in orbit_codegen.write_free_models(out)]


def _free3d(out: Path) -> list:
    """The 3-D models on a free orbit."""
    return [f"  {d.name:<24} -> {out.name}/{f}"
            for f, d in zip(free3d_codegen.write_free3d_models(out), FREE3D_DEFINITIONS)]


GROUPS = (_planar, _three_d, _free, _free3d)  # independent: derived side by side
# submitted longest first (the 3-D free pair shares one Lagrange derivation and takes
# about as long as the other three together), so two workers finish close together
LONGEST_FIRST = (_free3d, _three_d, _planar, _free)


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else Path(__file__).resolve().parent.parent / "generated"
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    # the four families share nothing but their inputs: one process each, as many at a
    # time as there are cores (each writes its own files; the output is the same bytes)
    workers = min(len(GROUPS), os.cpu_count() or 1)
    with ProcessPoolExecutor(max_workers=workers) as pool:
        futures = {group: pool.submit(group, out) for group in LONGEST_FIRST}
        for group in GROUPS:
            print("\n".join(futures[group].result()))
    from .orbit import FREE_DEFINITIONS
    # one registry of every model, in one order: the thesis variants, 3-D, free orbit, 3-D free
    every = (tuple(DEFINITIONS) + tuple(DEFINITIONS_3D) + tuple(FREE_DEFINITIONS)
             + tuple(FREE3D_DEFINITIONS))
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
    print(f"derive: {len(every)} models in {time.perf_counter() - t0:.1f} s "
          f"({workers} processes)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
