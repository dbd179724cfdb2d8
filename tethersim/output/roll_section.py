"""The report's section "does the balloon make the satellite resist rolling?" (docs/roll.md).

The thesis's abstract (p. iv) and introduction (p. 1-1) say the drag balloon makes
the system resist rolling; its model is planar.  Computed at report time with
:mod:`tethersim.analysis.roll`: the out-of-plane linear modes of SatI at its
planar equilibrium for the balloon (thesis and objective damper), the boom alone
and the balloon's drag area carried by the boom, beside the closed forms; and two
3-D runs from the equilibrium disturbed out of the plane, plotted.
"""
from __future__ import annotations

import html
import math

from tethersim.output.page import Page
from tethersim.output.page import table as _table

H = 3600.0
# (row label, case of tethersim.analysis.roll.CASES, 3-D model)
ROWS = (
    ("balloon, thesis damper (3d)", "balloon", "3d"),
    ("balloon, objective damper (3d-objective-damper)", "balloon", "3d-objective-damper"),
    ("boom alone (tethers off)", "boom alone", "3d"),
    ("balloon's drag area split on the boom's ends", "drag area split", "3d"),
    ("balloon's drag area on the bus", "drag area on the bus", "3d"),
)
RUN_MODELS = (("thesis damper", "3d"), ("objective damper", "3d-objective-damper"))
START = {"phi0_deg": 5.0, "psi0_deg": 5.0, "delta_z0": 1.0}  # as docs/roll.md
MAX_RUN_ORBITS = 40.0  # the runs: the report's length, at most docs/roll.md's 40 orbits
DAMPS = 10.0  # "resists rolling": damps roll at least this much faster than the boom alone


def _h(seconds: float) -> str:
    if not math.isfinite(seconds):
        return "never"
    hours = seconds / H
    return f"{hours:,.0f}" if hours >= 1e4 else f"{hours:.4g}"


def roll_numbers(sat, periods: float) -> dict:
    """Everything the section prints, computed (tests compare it with the analysis).

    Parameters
    ----------
    sat : Satellite
        The satellite (SatI in the report).
    periods : float
        Orbits of each 3-D run (at most :data:`MAX_RUN_ORBITS`).

    Returns
    -------
    dict
        ``cases``: {row label: RollCase}; ``responses``: {label: RollResponse};
        ``closed``: the closed forms (``gg_roll_w`` [n], ``drag_tau``,
        ``damper_tau`` [s]); ``verdict``: ``"yes"``, ``"partly"`` or ``"no"``
        with ``holds``: {"thesis damper": bool, "objective damper": bool};
        ``stiffening``: the largest relative change of the roll frequency the
        balloon makes (either damper) against the boom alone; ``periods``: run length.
    """
    from tethersim.analysis.roll import (
        boom_inertias,
        roll_case,
        roll_drag_rate,
        roll_response,
        roll_yaw_quartic,
    )

    cases = {label: roll_case(sat, case, model) for label, case, model in ROWS}
    runs = min(float(periods), MAX_RUN_ORBITS)
    responses = {label: roll_response(sat, model, periods=runs, **START)
                 for label, model in RUN_MODELS}
    drag = roll_drag_rate(sat)
    closed = {"gg_roll_w": math.sqrt(-roll_yaw_quartic(sat)[0]),
              "drag_tau": 1.0 / drag,
              "damper_tau": 1.0 / ((sat.c1 * sat.b**2 + sat.c2 * sat.a**2)
                                   / (2 * boom_inertias(sat)["roll"]) + drag)}
    boom = cases[ROWS[2][0]].mode("roll").decay_time
    holds = {name: cases[ROWS[i][0]].mode("roll").decay_time * DAMPS < boom
             for i, name in enumerate(("thesis damper", "objective damper"))}
    verdict = "yes" if all(holds.values()) else "partly" if any(holds.values()) else "no"
    w_boom = cases[ROWS[2][0]].mode("roll").frequency
    stiffening = max(abs(cases[ROWS[i][0]].mode("roll").frequency / w_boom - 1) for i in (0, 1))
    return {"cases": cases, "responses": responses, "closed": closed, "holds": holds,
            "verdict": verdict, "periods": runs, "stiffening": stiffening}


def section_roll(page: Page, periods: float, sat_name: str = "satI") -> dict:
    """Compute :func:`roll_numbers`, plot the runs into OUT/img/roll.png and add the section.

    Parameters
    ----------
    page : Page
        The report page.
    periods : float
        Orbits of each 3-D run (at most :data:`MAX_RUN_ORBITS`).
    sat_name : str, optional
        Preset.

    Returns
    -------
    dict
        :func:`roll_numbers`.
    """
    from tethersim.model.presets import load_preset
    from tethersim.output.plots.roll import plot_roll_responses

    sat = load_preset(sat_name)
    nums = roll_numbers(sat, periods)
    n = sat.omega
    rows = []
    for label, c in nums["cases"].items():
        roll = c.mode("roll")
        rows.append([label, f"{math.degrees(c.theta):+.1f}", f"{roll.frequency / n:.4f}",
                     _h(roll.decay_time), f"{c.pitch.frequency / n:.4f}",
                     _h(c.pitch.decay_time)])
    cl = nums["closed"]
    body = [f"<p>{html.escape(sat.name)} at its planar equilibrium: the out-of-plane block of "
            f"the 3-D Jacobian (roll, yaw about the boom, balloon sideways). Closed forms: the "
            f"boom alone rolls at √(1 + 3k1) n = {cl['gg_roll_w']:.4f} n (roll–yaw quartic), "
            f"damped by its end bodies' drag in {_h(cl['drag_tau'])} h; the thesis's damper "
            f"adds (c1 b² + c2 a²)/(2 I_roll): {_h(cl['damper_tau'])} h. Yaw about the "
            f"boom is neutral in every case.</p>",
            _table(["case", "pitch θ_eq [deg]", "roll ω/n", "roll decay [h]", "pitch ω/n",
                    "pitch decay [h]"], rows)]
    runs = []
    for label, r in nums["responses"].items():
        res = r.result
        runs.append([label, res.status, _h(1 / r.roll_decay_rate if r.roll_decay_rate > 0
                                             else math.inf),
                     f"{math.degrees(r.orbit_peaks['phi'][-1]):.3g}",
                     f"{math.degrees(r.orbit_peaks['theta'][-1]):.3g}"])
    body.append(f"<p>3-D runs from that equilibrium with roll {START['phi0_deg']:g}°, yaw "
                f"{START['psi0_deg']:g}°, δz {START['delta_z0']:g} m, {nums['periods']:g} "
                f"orbits (tethersim.analysis.roll.roll_response):</p>")
    body.append(_table(["damper", "status", "fitted roll decay [h]",
                        "roll, last orbit [deg]", "|θ − θ_eq|, last orbit [deg]"], runs))
    png = plot_roll_responses(nums["responses"], page.out / "img" / "roll.png",
                              title=f"{sat.name}: roll and yaw after a "
                                    f"{START['phi0_deg']:g}° roll, {START['psi0_deg']:g}° "
                                    f"yaw start")
    body.append(page.img(png, "Roll (per-orbit peaks as dots) and yaw, thesis damper and "
                              "objective (along-tether) damper."))
    body.append(f"<p class='note'>{html.escape(_note(nums))}</p>")
    page.add("Does the balloon make the satellite resist rolling? (3-D models)",
             "\n".join(body))
    page.fact("By attaching a drag device, the system resists rolling movements", "iv, 1-1",
              _ours(nums, n), nums["verdict"], _why(nums))
    return nums


def _ours(nums: dict, n: float) -> str:
    c = nums["cases"]
    tau = {label: c[label].mode("roll").decay_time for label, _, _ in ROWS[:3]}
    w = [c[label].mode("roll").frequency / n for label, _, _ in ROWS[:3]]
    t_thesis, t_obj, t_boom = tau.values()
    return (f"roll decays in {_h(t_thesis)} h with the thesis damper, {_h(t_obj)} h with an "
            f"along-tether damper, {_h(t_boom)} h for the boom alone; roll ω/n {w[0]:.4f}, "
            f"{w[1]:.4f}, {w[2]:.4f}")


def _why(nums: dict) -> str:
    h = nums["holds"]
    if h["thesis damper"] and not h["objective damper"]:
        return ("in the thesis's own model only: its damper −c(ṙ3 − ṙ_end) resists any "
                "sideways motion of a boom end relative to the balloon; a damper along the "
                "tether leaves roll as the boom alone's (docs/roll.md)")
    if all(h.values()):
        return "both damper laws damp roll faster than the boom alone (docs/roll.md)"
    return "neither damper law damps roll faster than the boom alone (docs/roll.md)"


def _note(nums: dict) -> str:
    from tethersim.model.satellite import ROLL_LIMIT_DEG

    return (f"'Resists rolling' is read as: roll damped at least {DAMPS:g} times faster than "
            f"by the boom alone; the balloon changes the roll frequency by "
            f"{100 * nums['stiffening']:.2g} % at most (no stiffness to speak of). Runs that "
            f"roll past {ROLL_LIMIT_DEG:g}° end 'left-domain' (the roll-pitch-yaw angles are "
            f"singular at 90°, docs/limits.md). Evidence, and the planar stability maps under "
            f"out-of-plane starts: docs/roll.md.")
