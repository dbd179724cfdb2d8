"""Figures of docs/real-tethers.md, "One line": SatI's balloon on a single Dyneema line held
at a point s of the boom (issue 21; ``Satellite.s1``, a chain of no beads).

The line is tether 1 (30 m, Dyneema SK75 1 mm, tethersim.experiments.real_tethers'
material), tether 2 absent (E2 = c2 = 0), in the objective-damper model.  The boom's pitch
at the equilibrium (tethersim.find_equilibrium: the run's own start) and its pitch mode
(the slowest, from the linearisation) against the
torque balance in closed form: the line pulls the boom at s with the balloon's drag T along
the flow, a torque T s cos θ; the gravity-gradient torque 3 ω² I sin θ cos θ holds it, so
sin θ = T s / (3 ω² I) = s / s_c (the end bodies' own drag and the line's small slope are
the rest).  An upright trim needs s < s_c = 3 ω² I / T.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np

from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.experiments.real_tethers import LINE, REAL_MODEL
from tethersim.model.materials import with_tethers
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

D = "docs/real-tethers.md"
LENGTH = 30.0  # m: the single line's rest length (about the thesis's stretched 30.83 m)
POINTS = (0.0, 0.01, 0.02, 0.025, 0.05, 1.0)  # s [m]: where the line holds the boom


def single(s: float):
    """SatI on one Dyneema line of LENGTH held at s [m] along the boom."""
    sat = load_preset("satI").replace(l10=LENGTH, E2=0.0, c2=0.0, s1=float(s))
    return with_tethers(sat, *LINE, tethers=(1,))


@cache
def equilibrium(s: float):
    """tethersim.find_equilibrium of the single line held at s (a chain of no beads)."""
    return find_equilibrium(single(s), REAL_MODEL)


def tension(s: float) -> float:
    """The line's spring tension at rest [N]."""
    eq, sat = equilibrium(s), single(s)
    hold = s * np.array([math.sin(eq.theta), math.cos(eq.theta)])
    lam = float(np.hypot(*(np.array([eq.delta_x, eq.delta_y]) - hold)))
    return sat.E1 * (lam / sat.l10 - 1.0)


def pitch_mode(s: float) -> tuple:
    """(ω [rad/s], decay time [h]) of the slowest oscillatory mode: the boom's pitch."""
    w, _, tau = min(equilibrium(s).modes(), key=lambda m: m[0])
    return w, tau / 3600


def closed_form(s: float) -> float:
    """θ [rad] of the torque balance with the line along the flow: sin θ = s / s_c."""
    return math.asin(s / critical_s())


def critical_s() -> float:
    """s_c = 3 ω² I / T [m]: beyond it no upright trim (the line's tension at s = 0)."""
    sat = single(0.0)
    return 3 * sat.omega ** 2 * sat.pitch_inertia / tension(0.0)


_T = "| line held at s [m] | θ at rest [rad] |"
QUANTITIES = {"single_tension": lambda: tension(0.0), "single_s_c": critical_s,
              "single_length": lambda: LENGTH,
              "single_sqrt3_omega": lambda: math.sqrt(3) * single(0.0).omega}
# each equilibrium compiles the chain's finite-difference Jacobian (~20 s cold): slow tier
FIGURES = [Figure(D, ("## One line", "on one Dyneema line of "), "single_length"),
           Figure(D, ("The line pulls with T = ",), "single_tension", slow=True),
           Figure(D, ("s_c = 3 ω² I / T = ",), "single_s_c", slow=True),
           Figure(D, ("the boom alone's √3 ω = ",), "single_sqrt3_omega")]
COLUMNS = (lambda s: equilibrium(s).theta, closed_form, lambda s: pitch_mode(s)[0],
           lambda s: pitch_mode(s)[1])
for _i, _s in enumerate(POINTS):
    for _j, _col in enumerate(COLUMNS):
        if _j == 1 and _s >= 0.028:  # beyond s_c the balance has no upright root
            continue
        QUANTITIES[f"single_{_i}_{_j}"] = (lambda col, s: lambda: col(s))(_col, _s)
        FIGURES.append(Figure(D, (_T, f"| {_s:g} | ") + (" | ",) * _j, f"single_{_i}_{_j}",
                              slow=True))
