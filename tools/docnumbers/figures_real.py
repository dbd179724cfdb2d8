"""Figures of docs/real-tethers.md: SatI on real (Dyneema SK75, 1 mm) lines (issue 21).

Every configuration is SatI on the lines of ``tethersim.experiments.real_tethers``
(``real_lines``: EA, the loss factor's damping c, the breaking load Fb), in the
objective-damper model (a Kelvin-Voigt line: the damper acts on the stretch rate);
"thesis" is SatI's own tethers in the same model.  The linear figures are fast; the
nonlinear runs (Radau IIA, 50 orbits each) are the slow tier.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np

from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.roll import roll_case, roll_drag_rate
from tethersim.analysis.tethers import tether_loads
from tethersim.engine.simulate import simulate
from tethersim.engine.start import equilibrium_satellite
from tethersim.experiments.real_tethers import (
    REAL_MODEL,
    RUN_TOLERANCES,
    STRETCHED_LENGTHS,
    density_step,
    real_lines,
)
from tethersim.model.materials import MAX_FAILURE_STRAIN, REAL_TETHER_EA
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

D = "docs/real-tethers.md"
MODEL = REAL_MODEL
LENGTHS = {"6 m": (6.0, 6.0), "stretched": STRETCHED_LENGTHS}
RUN_ORBITS = 50


def _sat():
    return load_preset("satI")


@cache
def real(config: str):
    """SatI on Dyneema 1 mm lines of rest lengths ``LENGTHS[config]``; ``"thesis"``: SatI."""
    return _sat() if config == "thesis" else real_lines(_sat(), LENGTHS[config])


@cache
def equilibrium(config: str, density: float = 1.0):
    return find_equilibrium(real(config).replace(density_scale=density), MODEL)


def slowest_decay_h(config: str) -> float:
    """Slowest oscillatory mode's decay time [h] at the nominal equilibrium."""
    return max(tau for _, _, tau in equilibrium(config).modes()) / 3600


def axial_mode(config: str) -> float:
    """Fastest mode's frequency [rad/s]: the balloon bouncing on its lines."""
    return max(w for w, _, _ in equilibrium(config).modes())


def apex() -> tuple:
    """(s, h) [m]: the rigid 6 m bridle's apex, along the boom from the COM towards the
    tip-mass and off it (the triangle of sides l10, l20 over the attachment points)."""
    s = real("6 m")
    d = s.a + s.b
    along = (s.l10 ** 2 - s.l20 ** 2 + d ** 2) / (2 * d)
    return s.b - along, math.sqrt(s.l10 ** 2 - along ** 2)


def balloon_in_boom_frame(config: str) -> tuple:
    """(s, h) [m] of the equilibrium balloon in the boom frame."""
    eq = equilibrium(config)
    e = np.array([math.sin(eq.theta), math.cos(eq.theta)])
    p = np.array([eq.delta_x, eq.delta_y])
    s = float(p @ e)
    return s, float(np.linalg.norm(p - s * e))


@cache
def run(config: str, density: float):
    """RUN_ORBITS orbits from the nominal-density equilibrium, flying at ``density`` x the
    nominal air: the solar cycle's step in drag, met from rest."""
    return density_step(real(config), RUN_ORBITS, density, MODEL)


def run_row(config: str, density: float, column: str) -> float:
    res = run(config, density)
    loads = tether_loads(res)
    theta0 = res.theta[0]
    return {"peak1": loads[0].peak, "peak2": loads[1].peak,
            "safety": min(ld.safety_factor for ld in loads),
            "slack": max(ld.slack_fraction for ld in loads),
            "switches": res.n_switches,
            "excursion": float(np.max(np.abs(res.theta - theta0))),
            "final": float(res.theta[-1] - equilibrium(config, density).theta)}[column]


QUANTITIES = {
    "real_c_6m": lambda: real("6 m").c1,
    "real_EA": lambda: real("6 m").E1,
    "real_Fb": lambda: real("6 m").Fb1,
    "real_apex_s": lambda: apex()[0],
    "real_apex_h": lambda: apex()[1],
    "real_balloon_s": lambda: balloon_in_boom_frame("6 m")[0],
    "real_balloon_h": lambda: balloon_in_boom_frame("6 m")[1],
    "real_6m_theta_deg": lambda: math.degrees(equilibrium("6 m").theta),
    "real_thesis_damper_theta": lambda: thesis_damper_theta(),
    "real_gg_ratio": lambda: drag_lever_ratio(),
    "real_stretched_tension2": lambda: real("stretched").E2 * (
        math.hypot(*_bus_offset("stretched")) / real("stretched").l20 - 1),
    "real_bounce_snaps1": lambda: bounce()[0].snaps,
    "real_bounce_snap1": lambda: bounce()[0].snap,
    "real_bounce_peak2": lambda: bounce()[1].peak,
}


@cache
def bounce():
    """The first 0.05 orbit of the 6 m, x2 run of :func:`run`, sampled every ~1 ms."""
    start = equilibrium_satellite(real("6 m"), MODEL).replace(density_scale=2.0)
    res = simulate(start, periods=0.05, samples=250_000, method="implicit", model=MODEL,
                   progress=False, start="given", **RUN_TOLERANCES)
    return tether_loads(res)


def drag_lever_ratio() -> float:
    """The balloon's drag times the rigid 6 m bridle's lever at θ = 0 (the apex's height
    along the boom) over the largest gravity-gradient torque 3/2 ω² I of the boom; the
    drag: what the lines hold at the equilibrium."""
    s = real("6 m")
    return math.hypot(*_pull("6 m")) * apex()[0] / (1.5 * s.omega ** 2 * s.pitch_inertia)


def _pull(config: str) -> tuple:
    """The tethers' total force on the balloon at the equilibrium [N] (x, y)."""
    eq, s = equilibrium(config), real(config)
    fx = fy = 0.0
    for (px, py), E, l0 in (((s.b * math.sin(eq.theta), s.b * math.cos(eq.theta)), s.E1, s.l10),
                            ((-s.a * math.sin(eq.theta), -s.a * math.cos(eq.theta)), s.E2,
                             s.l20)):
        dx, dy = px - eq.delta_x, py - eq.delta_y
        lam = math.hypot(dx, dy)
        t = E * max(lam - l0, 0.0) / l0
        fx, fy = fx + t * dx / lam, fy + t * dy / lam
    return fx, fy


def thesis_damper_theta() -> float:
    """θ [rad] of the 6 m Dyneema bridle's equilibrium with the thesis's damper."""
    return find_equilibrium(real("6 m"), "derived").theta


def _bus_offset(config: str) -> tuple:
    eq, s = equilibrium(config), real(config)
    return (eq.delta_x + s.a * math.sin(eq.theta), eq.delta_y + s.a * math.cos(eq.theta))


_T = "| configuration | δx [m] |"
ROWS = {"Dyneema 1 mm, 6 m lines": "6 m", "Dyneema 1 mm, 30.83 / 28.92 m lines": "stretched",
        "thesis tethers": "thesis"}
COLUMNS = (
    lambda c: equilibrium(c).delta_x,
    lambda c: equilibrium(c).delta_y,
    lambda c: equilibrium(c).theta,
    lambda c: equilibrium(c, 0.5).theta,
    lambda c: equilibrium(c, 2.0).theta,
    slowest_decay_h,
    axial_mode,
)
FIGURES = [
    Figure(D, ("EA = ",), "real_EA"),
    Figure(D, ("breaking load Fb = ",), "real_Fb"),
    Figure(D, ("c = η √(k m) = ",), "real_c_6m"),
    Figure(D, ("the apex of the triangle lies ",), "real_apex_s"),
    Figure(D, ("the apex of the triangle lies ", "m along the boom and "), "real_apex_h"),
    Figure(D, ("the equilibrium balloon sits at ",), "real_balloon_s"),
    Figure(D, ("the equilibrium balloon sits at ", "m and "), "real_balloon_h"),
    Figure(D, ("the boom pitches to ",), "real_6m_theta_deg"),
    Figure(D, ("tether 2 pulls with ",), "real_stretched_tension2"),
    Figure(D, ("turned over to θ = ",), "real_thesis_damper_theta"),
    Figure(D, ("The balloon's drag then acts through that fixed lever, ",), "real_gg_ratio"),
    Figure(D, ("in 55.4 h (the thesis's tethers: ",), "real_table_2_5"),
    Figure(D, ("bridle's slowest mode decays\nin ",), "real_table_1_5"),
    Figure(D, ("the 6 m bridle's in ",), "real_table_0_5"),
    Figure(D, ("swing from ",), "real_table_2_3"),
    Figure(D, ("swing from ", "to "), "real_table_2_4", absolute=True),
    Figure(D, ("tether 1 re-tautens ",), "real_bounce_snaps1", slow=True),
    Figure(D, ("with a snap tension of ",), "real_bounce_snap1", slow=True),
    Figure(D, ("and tether 2\n  peaks at ",), "real_bounce_peak2", slow=True),
    Figure(D, ("above the grid's ",), "real_run_0_1", slow=True),
    Figure(D, ("against\n  a ",), "real_Fb"),
    Figure(D, ("Fb = ",), "real_Fb"),
]
for _i, (_label, _config) in enumerate(ROWS.items()):
    for _j, _col in enumerate(COLUMNS):
        _key = f"real_table_{_i}_{_j}"
        QUANTITIES[_key] = (lambda col, c: lambda: col(c))(_col, _config)
        FIGURES.append(Figure(D, (_T, f"| {_label} | ") + (" | ",) * _j, _key))

_R = "| lines, air density | peak tension 1 [N] |"
RUN_ROWS = {"6 m, ×2": ("6 m", 2.0), "6 m, ×0.5": ("6 m", 0.5),
            "30.83 / 28.92 m, ×2": ("stretched", 2.0),
            "30.83 / 28.92 m, ×0.5": ("stretched", 0.5)}
RUN_COLUMNS = ("peak1", "peak2", "safety", "slack", "switches", "excursion", "final")
SLOW = []
for _i, (_label, (_config, _density)) in enumerate(RUN_ROWS.items()):
    for _j, _col in enumerate(RUN_COLUMNS):
        _key = f"real_run_{_i}_{_j}"
        QUANTITIES[_key] = (lambda c, d, col: lambda: run_row(c, d, col))(_config, _density,
                                                                          _col)
        # the switch count moves with the last bits of the arithmetic: the ±25 % the doc
        # states under the table
        SLOW.append(Figure(D, (_R, f"| {_label} | ") + (" | ",) * _j, _key, slow=True,
                           absolute=_col == "final", rtol=0.25 if _col == "switches" else 0.0))
FIGURES += SLOW

# roll with real lines: the out-of-plane modes at the planar equilibrium in the 3-D twin of
# the objective-damper model (tethersim.analysis.roll; the 3-D finite-difference Jacobian
# compiles for ~20 s cold, so these are slow-tier figures)
ROLL_MODEL = "3d-objective-damper"
_O = "| lines, 3-D objective-damper | roll ω [rad/s] |"
ROLL_ROWS = {"thesis tethers": ("thesis", "balloon"),
             "Dyneema 1 mm, 6 m lines": ("6 m", "balloon"),
             "Dyneema 1 mm, 30.83 / 28.92 m lines": ("stretched", "balloon"),
             "boom alone (no balloon)": ("stretched", "boom alone")}


@cache
def roll(config: str, case: str):
    """:func:`tethersim.analysis.roll.roll_case` of ``config`` in ROLL_MODEL."""
    return roll_case(real(config), case, ROLL_MODEL)


ROLL_COLUMNS = (lambda rc: rc.mode("roll").frequency,
                lambda rc: rc.mode("roll").decay_time / 3600,
                lambda rc: rc.mode("balloon sideways").frequency,
                lambda rc: rc.mode("balloon sideways").decay_time / 3600)
for _i, (_label, _args) in enumerate(ROLL_ROWS.items()):
    for _j, _col in enumerate(ROLL_COLUMNS[:2] if _args[1] == "boom alone" else ROLL_COLUMNS):
        _key = f"real_roll_{_i}_{_j}"
        QUANTITIES[_key] = (lambda col, a: lambda: col(roll(*a)))(_col, _args)
        FIGURES.append(Figure(D, (_O, f"| {_label} | ") + (" | ",) * _j, _key, slow=True))
QUANTITIES["real_roll_drag_h"] = lambda: 1 / roll_drag_rate(real("stretched")) / 3600
FIGURES.append(Figure(D, ("the end bodies' own drag, D/(2 I_roll) = 1/(",), "real_roll_drag_h"))

T = "docs/tethers.md"


def preset_start_tension() -> float:
    """Tether 1's tension [N] were SatI's preset start held by the 6 m Dyneema line."""
    s = real("6 m")
    th = s.initial[2]
    lam = math.hypot(s.b * math.sin(th) - s.initial[0], s.b * math.cos(th) - s.initial[1])
    return s.E1 * (lam - s.l10) / s.l10


QUANTITIES.update({
    "real_preset_start_tension": preset_start_tension,
    "real_max_strain_pct": lambda: 100 * MAX_FAILURE_STRAIN,
    "real_ea_mpa": lambda: REAL_TETHER_EA / 1e-6 / 1e6,  # N over 1 mm^2, in MPa
})
FIGURES += [
    Figure(T, ("line started so would pull with ",), "real_preset_start_tension"),
    Figure(T, ("stretched beyond ",), "real_max_strain_pct"),
    Figure(T, ("a modulus of ",), "real_ea_mpa"),
]

# docs/tethers.md, "Where a run starts": the thesis's damper turns the stretched real bridle
# over at rest, the auto start that engine/start.py refuses
QUANTITIES["real_thesis_damper_turned_theta"] = lambda: equilibrium_satellite(
    real("stretched"), "derived").initial[2]
FIGURES.append(Figure("docs/tethers.md", ("stretched Dyneema bridle: θ = ",),
                      "real_thesis_damper_turned_theta"))
