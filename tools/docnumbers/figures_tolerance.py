"""Figures of docs/tolerances.md: the convergence study behind CLASS_RTOL (issue 22).

Four 9 x 9 grids of 50-orbit runs (the thesis's moduli and damping maps of SatI, the
moduli of SatII and DumbSat) at rtol 1e-9 ... 1e-4 against rtol 1e-9:
:func:`tethersim.experiments.sweep.convergence.class_convergence`.
"""
from __future__ import annotations

from functools import cache

import numpy as np

from tethersim.experiments.sweep import SweepSpec
from tethersim.experiments.sweep.convergence import class_convergence
from tethersim.experiments.sweep.plan import CLASS_RTOL, DEFAULT_RTOL
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

T = "docs/tolerances.md"
_TABLE = "## The study"
RTOLS = (1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4)
GRIDS = {
    "SatI E1 × E2": ("satI", (("E1", np.linspace(0.0005, 0.02, 9)),
                              ("E2", np.linspace(0.005, 0.06, 9)))),
    "SatI c1 × c2": ("satI", (("c1", np.linspace(0.0, 0.012, 9)),
                              ("c2", np.linspace(0.0, 0.012, 9)))),
    "SatII E1 × E2": ("satII", (("E1", np.linspace(0.0005, 0.06, 9)),
                                ("E2", np.linspace(0.005, 0.06, 9)))),
    "DumbSat E1 × E2": ("dumbsat", (("E1", np.linspace(0.0005, 0.06, 9)),
                                    ("E2", np.linspace(0.005, 0.06, 9)))),
}
COLUMNS = ("class_changes", "max_dtheta_ss", "max_dsettling", "work")


@cache
def study(grid: str) -> dict:
    """{rtol: row of class_convergence} of one grid."""
    preset, axes = GRIDS[grid]
    spec = SweepSpec(load_preset(preset), axes, periods=50.0, progress=False)
    return {row["rtol"]: row for row in class_convergence(spec, RTOLS)}


def _key(grid: str, rtol: float, column: str) -> str:
    return f"tolerance_{grid}_{rtol:g}_{column}"


def loosest_unchanged() -> float:
    """The loosest tolerance of the study at which no grid changed a class."""
    return max(r for r in RTOLS if all(study(g)[r]["class_changes"] == 0 for g in GRIDS))


QUANTITIES = {_key(g, r, c): (lambda g=g, r=r, c=c: study(g)[r][c])
              for g in GRIDS for r in RTOLS[1:] for c in COLUMNS}
QUANTITIES.update(class_rtol=lambda: CLASS_RTOL, default_rtol=lambda: DEFAULT_RTOL,
                  loosest_unchanged=loosest_unchanged)
FIGURES = [Figure(T, (_TABLE, f"| {g} | {r:g} |", *(" | ",) * i), _key(g, r, c), slow=True)
           for g in GRIDS for r in RTOLS[1:] for i, c in enumerate(COLUMNS)]
FIGURES += [Figure(T, ("`DEFAULT_RTOL = ",), "default_rtol"),
            Figure(T, ("`CLASS_RTOL = ",), "class_rtol"),
            Figure(T, ("no class changes anywhere up to rtol ",), "loosest_unchanged", slow=True),
            Figure("README.md", ("run at `CLASS_RTOL` = ",), "class_rtol"),
            Figure("README.md", ("no class changes against ",), "default_rtol"),
            Figure("README.md", ("9 × 9 grids up to", "rtol "), "loosest_unchanged", slow=True)]


def table() -> str:
    """The study's table in the doc's format (``python -m tools.docnumbers.figures_tolerance``)."""
    lines = ["| grid | rtol | class changes | largest Δθ_ss [rad] | largest Δ settling time, "
             "stable points [s] | work (f evaluations) vs 1e-9 |", "|---|---|---|---|---|---|"]
    for g in GRIDS:
        for r in RTOLS[1:]:
            row = study(g)[r]
            lines.append(f"| {g} | {r:g} | {row['class_changes']} | {row['max_dtheta_ss']:.2g} | "
                         f"{row['max_dsettling']:.2g} | {row['work']:.2f} |")
    return "\n".join(lines)


if __name__ == "__main__":
    print(table())
