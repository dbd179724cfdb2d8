"""A satellite on real lines: the study of docs/real-tethers.md (issue 21, item 5).

The thesis's tethers are rubber bands (E·1 mm² of 0.004 and 0.0427 N for SatI) that
stretch ~5x to hold the balloon ~29 m behind the boom.  This module puts the same
satellite on real fibre lines (1 mm Dyneema SK75 by default: EA, the loss factor's
damping and the breaking load from ``tethersim.model.materials.with_tethers``) and asks
the questions of the issue:

* :func:`real_lines`: the satellite with real lines of given rest lengths, either the
  thesis's own 6 m (a rigid triangle with the boom) or :data:`STRETCHED_LENGTHS`, the
  lengths the thesis's tethers reach at their equilibrium (so the drag line passes near
  the COM, as it did in the thesis's runs);
* :func:`trim`: where the balloon sits and the boom trims, and how the trim moves with
  the air density (the solar cycle's ×0.5 … ×2), with the slowest mode's decay time and
  the lines' axial mode from the linearisation (tethersim.analysis.equilibrium);
* :func:`single_line_reach`: how far from the COM a single line may hold the boom and
  still leave an upright trim (docs/real-tethers.md, "One line");
* :func:`density_step`: a nonlinear run from the nominal-air equilibrium, at rest,
  flying in air ``density`` x nominal (the step in drag a solar cycle makes), on the
  implicit scheme (Radau IIA), whose tensions, peak and snap loads and safety factor
  (tethersim.analysis.tethers) say whether the lines hold.

Real lines run the ``objective-damper`` model (:data:`REAL_MODEL`): the thesis damper
acts on the whole relative velocity and, on a stiff line, pushes the balloon sideways
at rest (docs/real-tethers.md).
"""
from __future__ import annotations

import math

from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.engine.simulate import simulate
from tethersim.engine.start import equilibrium_satellite
from tethersim.model.materials import with_tethers
from tethersim.model.satellite import Satellite

REAL_MODEL = "objective-damper"
LINE = ("dyneema-sk75", 1e-3)  # material and diameter [m] of docs/real-tethers.md
#: m: SatI's tether lengths at its thesis-tether equilibrium, to the centimetre (issue 21;
#: :func:`stretched_lengths` computes them, a test holds the two within 5 mm)
STRETCHED_LENGTHS = (30.83, 28.92)
DENSITIES = (0.5, 2.0)  # x nominal air: the solar cycle's range about the mean
RUN_TOLERANCES = {"rtol": 1e-8, "atol": 1e-10}  # a real line's atol floor (docs/tethers.md)


def real_lines(sat: Satellite, lengths=None, material: str = LINE[0],
               diameter: float = LINE[1]) -> Satellite:
    """``sat`` on real lines of rest lengths ``lengths`` [m] (default: its own).

    Parameters
    ----------
    sat : Satellite
        The satellite (its tethers' rest lengths are replaced by ``lengths``).
    lengths : (float, float), optional
        Rest lengths l10, l20 [m].
    material, diameter : str, float, optional
        A key of ``tethersim.model.materials.MATERIALS`` and the line diameter [m].

    Returns
    -------
    Satellite
        A copy with l10, l20, E1, E2 = EA [N], c1, c2 and Fb1, Fb2 set.
    """
    if lengths is not None:
        sat = sat.replace(l10=float(lengths[0]), l20=float(lengths[1]))
    return with_tethers(sat, material, diameter)


def stretched_lengths(sat: Satellite, model: str = "derived") -> tuple:
    """Distances [m] from the tip-mass and the bus to the balloon at ``sat``'s own
    equilibrium in ``model``: the rest lengths of real lines that hold the balloon where
    the satellite's (thesis) tethers hold it."""
    eq = find_equilibrium(sat, model)
    s, c = math.sin(eq.theta), math.cos(eq.theta)
    return (math.hypot(sat.b * s - eq.delta_x, sat.b * c - eq.delta_y),
            math.hypot(-sat.a * s - eq.delta_x, -sat.a * c - eq.delta_y))


def trim(sat: Satellite, model: str = REAL_MODEL, densities=DENSITIES) -> dict:
    """The equilibrium of ``sat`` and how it moves with the air density.

    Returns
    -------
    dict
        ``delta_x``, ``delta_y`` [m], ``theta`` [rad] at nominal air; ``theta_at``,
        {density scale: θ [rad]}; ``slowest_decay_h``, the slowest oscillatory mode's
        decay time [h]; ``axial_mode``, the fastest mode's frequency [rad/s] (on real
        lines the balloon bouncing on them).
    """
    eq = find_equilibrium(sat, model)
    modes = eq.modes()
    return {"delta_x": eq.delta_x, "delta_y": eq.delta_y, "theta": eq.theta,
            "theta_at": {k: find_equilibrium(sat.replace(density_scale=k), model).theta
                         for k in densities},
            "slowest_decay_h": max(tau for _, _, tau in modes) / 3600,
            "axial_mode": max(w for w, _, _ in modes)}


def single_line_reach(sat: Satellite) -> float:
    """s_c = 3 ω² I / D [m]: a single line held farther than this from the COM turns the
    boom out of upright.

    Held at s along the boom, the line pulls with the balloon's drag D along the flow, a
    torque D s cos θ that the gravity gradient's 3 ω² I sin θ cos θ balances at
    sin θ = s / s_c; beyond s_c the boom lies along the flow.  D = ½ ρ C_D A3 v², v the
    air's speed past the COM, (ω − ω_E) r0 (Eq 3.33): the balloon's drag at a trim
    behind the COM.  A stiff line's equilibrium (a chain of no beads,
    tests/model/test_beads_attachment.py) agrees to 1e-4 rad.
    """
    from tethersim.model.constants import OMEGA_EARTH
    v = (sat.omega - OMEGA_EARTH) * sat.r0
    drag = 0.5 * sat.rho * sat.CD * sat.A3 * v * v  # rho: density_scale included
    return 3 * sat.omega ** 2 * sat.pitch_inertia / drag


def density_step(sat: Satellite, periods: float, density: float, model: str = REAL_MODEL,
                 **options):
    """``periods`` orbits from ``sat``'s nominal-air equilibrium, at rest, in air
    ``density`` x nominal, on the implicit scheme (:data:`RUN_TOLERANCES` unless given).

    Returns
    -------
    tethersim.SimResult
    """
    start = equilibrium_satellite(sat, model).replace(density_scale=density)
    return simulate(start, periods=periods, method="implicit", model=model, progress=False,
                    start="given", **{**RUN_TOLERANCES, **options})
