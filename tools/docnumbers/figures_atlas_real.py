"""Figures of docs/real-tethers.md, "The feasibility atlas on real lines": SatI's stretched
bridle of 1 mm Dyneema (tethersim.experiments.real_tethers) through the feasibility atlas
(tethersim.experiments.feasibility) at 200, 300 and 400 km, beside the thesis's tethers at
the same altitudes (docs/feasibility.md's table).

The command the doc prints runs the same spec (`tethersim feasibility satI --set l10=30.83
--set l20=28.92 --tethers dyneema-sk75:1 --model objective-damper --method implicit --rtol
1e-6 --altitude 200:400:3`).  Every run starts at its own equilibrium (engine/start.py), so
the settling time is zero by construction: the atlas judges the trim across the solar
cycle and the life, not the capture after a deployment (not modelled).
"""
from __future__ import annotations

import math
import tempfile
from functools import cache

from tethersim.experiments.feasibility import SOLAR_CASES, FeasibilitySpec, run_feasibility
from tethersim.experiments.real_tethers import REAL_MODEL, STRETCHED_LENGTHS, real_lines
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

D = "docs/real-tethers.md"
ALTITUDES = (200.0, 300.0, 400.0)  # km
RTOL = 1e-6  # the class tolerance of the atlas's runs; the check runs at 1e-8


@cache
def rows() -> tuple:
    """The atlas's rows, one per altitude (about 2 minutes on 2 cores, compiling)."""
    sat = real_lines(load_preset("satI"), STRETCHED_LENGTHS)
    spec = FeasibilitySpec(sat, ALTITUDES, model=REAL_MODEL, method="implicit", rtol=RTOL)
    with tempfile.TemporaryDirectory() as out:
        return tuple(run_feasibility(spec, out, log=lambda *_: None, progress=False))


TRIM_KEYS = ("theta_ss_rad", *(f"theta_ss_{c}_rad" for c in SOLAR_CASES))
_T = "| start altitude [km] | balloon lost [h] |"
QUANTITIES = {
    "atlas_real_feasible": lambda: sum(r["verdict"] == "feasible" for r in rows()),
    "atlas_real_lost": lambda: sum(math.isfinite(r["balloon_lost_h"]) for r in rows()),
    "atlas_real_points": lambda: len(rows()),
    "atlas_real_scale_min": lambda: rows()[-1]["scale_min"],
    "atlas_real_scale_max": lambda: rows()[-1]["scale_max"],
    "atlas_real_end_km": lambda: rows()[0]["end_altitude_km"],
    "atlas_real_A3": lambda: rows()[0]["A3_m2"],
    # every trim of the table, nominal and solar: the doc prints their mean to 3 decimals
    "atlas_real_trim": lambda: sum(r[k] for r in rows() for k in TRIM_KEYS) / (
        len(rows()) * len(TRIM_KEYS)),
}
FIGURES = [
    Figure(D, ("## The feasibility atlas on real lines", "feasible at "), "atlas_real_feasible",
           slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "feasible at ", " of "),
           "atlas_real_points", slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "balloon is lost at "),
           "atlas_real_lost", slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "the trim stays near "),
           "atlas_real_trim", slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "the air is ×"), "atlas_real_scale_min",
           slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "the air is ×", " to ×"),
           "atlas_real_scale_max", slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "the run ends at "), "atlas_real_end_km",
           slow=True),
    Figure(D, ("## The feasibility atlas on real lines", "whole satellite's: the "),
           "atlas_real_A3", slow=True),
]
# the cells after the altitude: re-entry [h] (the cap where the free run outlived it: the
# row prints "≥ 240"), θ_ss nominal, then θ_ss at solar min, mean, max [rad]
COLUMNS = ("reentry_h", *TRIM_KEYS)
for _i, _h in enumerate(ALTITUDES):
    for _j, _key in enumerate(COLUMNS):
        QUANTITIES[f"atlas_real_{_i}_{_j}"] = (lambda i, key: lambda: rows()[i][key])(_i, _key)
        # the row's cells: altitude | balloon lost | re-entry | θ_ss | θ_ss min | mean | max
        FIGURES.append(Figure(D, (_T, f"| {_h:g} | ", " | ") + (" | ",) * _j
                              + (("≥ ",) if _j == 0 and _i == 2 else ()),
                              f"atlas_real_{_i}_{_j}", slow=True))
