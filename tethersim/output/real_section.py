"""The report's section "and on real tethers?" (docs/real-tethers.md, issue 21 item 5).

Computed at report time with :mod:`tethersim.experiments.real_tethers`: SatI's trim,
its move with the air density and its slowest decay on the thesis's tethers and on
1 mm Dyneema lines of two geometries (SatI's 6 m, and cut to the thesis's stretched
equilibrium); then a run of the stretched lines from rest at the nominal-air
equilibrium into doubled air (the solar cycle's step in drag), its tensions against
the breaking load plotted; and the end of the stretched lines' deployment
(:mod:`tethersim.experiments.deployment`): a braked arrival and a free release; and the
feasibility atlas of the stretched lines (:mod:`tethersim.experiments.feasibility`).
"""
from __future__ import annotations

import html
import math

from tethersim.output.page import Page
from tethersim.output.page import table as _table

BAND = 0.05  # rad: the thesis's pitch trim band (p. 5-18)
STEP_DENSITY = 2.0  # x nominal air: the run's step in drag
ARRIVAL = 0.1  # m/s: the braked arrival of the deployment table (docs/real-tethers.md)
ATLAS_KM = (200.0, 300.0, 400.0)  # the real-line atlas's start altitudes (docs/real-tethers.md)
ATLAS_RTOL = 1e-6  # its class tolerance, checked at rtol / 100 (the atlas's own check)


def real_numbers(sat, periods: float) -> dict:
    """Everything the section prints, computed.

    Parameters
    ----------
    sat : Satellite
        The satellite on its own (thesis) tethers.
    periods : float
        Orbits of the density-step run.

    Returns
    -------
    dict
        ``rows``: {label: (satellite, :func:`~tethersim.experiments.real_tethers.trim`)};
        ``run``: the density-step run of the stretched lines; ``loads``: its
        :class:`~tethersim.analysis.tethers.TetherLoads`; ``deploy``: {label:
        :class:`~tethersim.experiments.deployment.Deployment` without its run} for a
        braked arrival and a free release of the stretched lines (one orbit each);
        :func:`section_real` adds ``atlas``, the real-line atlas's rows.
    """
    from dataclasses import replace

    from tethersim.analysis.tethers import tether_loads
    from tethersim.experiments.deployment import RELEASE, arrival, deploy, released
    from tethersim.experiments.real_tethers import (
        LINE,
        STRETCHED_LENGTHS,
        density_step,
        real_lines,
        trim,
    )

    line = f"{LINE[0]} {LINE[1] * 1e3:g} mm"
    stretched = real_lines(sat, STRETCHED_LENGTHS)
    sats = {"thesis tethers": sat,
            f"{line}, {sat.l10:g} / {sat.l20:g} m lines": real_lines(sat),
            f"{line}, {STRETCHED_LENGTHS[0]:g} / {STRETCHED_LENGTHS[1]:g} m lines": stretched}
    run = density_step(stretched, periods, STEP_DENSITY)
    starts = {f"braked arrival at {ARRIVAL:g} m/s": arrival(stretched, ARRIVAL),
              f"free release {RELEASE:g} m behind the COM": released(stretched, RELEASE)}
    return {"rows": {k: (s, trim(s)) for k, s in sats.items()}, "run": run,
            "loads": tether_loads(run),
            # the runs' 2 ms grids are hundreds of MB: only the record is kept
            "deploy": {k: replace(deploy(s), result=None) for k, s in starts.items()}}


def section_real(page: Page, periods: float, sat_name: str = "satI", workers=None,
                 progress: bool | None = None) -> dict:
    """Add the section (module docstring) to ``page``; return :func:`real_numbers`.
    ``workers``, ``progress``: the real-line atlas's threads and progress bar."""
    from tethersim.experiments.real_tethers import single_line_reach
    from tethersim.model.presets import load_preset
    from tethersim.output.feasibility_section import atlas_table
    from tethersim.output.plots.run import plot_tensions

    sat = load_preset(sat_name)
    nums = real_numbers(sat, periods)
    rows = []
    for label, (s, t) in nums["rows"].items():
        lo, hi = (t["theta_at"][k] for k in sorted(t["theta_at"]))
        holds = all(abs(v) <= BAND for v in (t["theta"], lo, hi))
        rows.append([label, f"{s.E1:.3g} / {s.E2:.3g}", f"{t['delta_x']:.3f}",
                     f"{t['theta']:+.4f}", f"{lo:+.4f} / {hi:+.4f}", "yes" if holds else "no",
                     f"{t['slowest_decay_h']:.3g}", f"{t['axial_mode']:.3g}"])
    k_lo, k_hi = sorted(next(iter(nums["rows"].values()))[1]["theta_at"])
    body = [_table(["tethers", "EA1 / EA2 [N]", "δx [m]", "trim θ [rad]",
                    f"θ at ×{k_lo:g} / ×{k_hi:g} air [rad]", f"trim within ±{BAND:g} rad",
                    "slowest decay [h]", "fastest mode [rad/s]"], rows)]
    run, loads = nums["run"], nums["loads"]
    png = plot_tensions(run, page.out / "img" / "real_tensions.png")
    excursion = float(max(abs(v - run.theta[0]) for v in run.theta))
    body.append(_table(
        ["tether", "peak tension [N]", "snap tension [N]", "breaking load [N]",
         "safety factor", "slack [% of the time]"],
        [[str(ld.tether), f"{ld.peak:.4g}", "—" if not math.isfinite(ld.snap) else
          f"{ld.snap:.4g}", f"{fb:.4g}", f"{ld.safety_factor:.4g}",
          f"{100 * ld.slack_fraction:.3g}"]
         for ld, fb in zip(loads, (run.satellite.Fb1, run.satellite.Fb2))],
        caption=f"The stretched lines from rest at the nominal-air equilibrium into "
                f"×{STEP_DENSITY:g} air, {run.t[-1] / sat.period:.3g} orbits on the implicit "
                f"scheme (status {run.status}): θ moves by at most {excursion:.3g} rad"))
    body.append(page.img(png, "Tensions of the stretched Dyneema lines after the step in "
                              "drag, with each breaking load."))
    body.append(_table(
        ["end of the deployment", "first catch's peak tension [N]", "safety factor",
         "pitch excursion [rad]", "boom turned over"],
        [[label, f"{d.first_peak:.4g}", f"{d.safety_factor:.4g}", f"{d.excursion:.3g}",
          "yes" if d.turned_over else "no"] for label, d in nums["deploy"].items()],
        caption="The stretched lines at the end of a deployment, one orbit on the implicit "
                "scheme sampled every 2 ms: the lines catch the balloon within centimetres, "
                "and each catch's impulse turns the boom (docs/real-tethers.md, "
                "\"Deployment\"; tethersim deploy)"))
    nums["atlas"] = _real_atlas(page, periods, sat, workers, progress)
    body.append(atlas_table(nums["atlas"], caption=(
        f"The feasibility atlas on the stretched lines (Radau IIA at rtol {ATLAS_RTOL:g}, "
        f"checked at rtol / 100; every run starts at its equilibrium, so the settling time "
        f"is zero by construction): a real line does not stretch, so the balloon is not "
        f"lost as the air thickens (docs/real-tethers.md, \"The feasibility atlas on real "
        f"lines\")")))
    reach = single_line_reach(sat)
    body.append(f"<p>One line instead of two: held at the COM it exerts no torque, so the "
                f"boom trims upright but the balloon neither holds nor damps its pitch; held "
                f"at s from the COM it tilts the boom to sin θ = s / s_c, and beyond "
                f"s_c = 3 ω² I / D = {100 * reach:.3g} cm (D the balloon's drag) it lays the "
                f"boom along the flow (docs/real-tethers.md, \"One line\").</p>")
    body.append(f"<p class='note'>{html.escape(_note())}</p>")
    page.add("And on real tethers?", "\n".join(body))
    return nums


def _real_atlas(page: Page, periods: float, sat, workers, progress) -> list:
    """The feasibility atlas's rows of the stretched lines at :data:`ATLAS_KM` (into
    OUT/feasibility-real)."""
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    from tethersim.experiments.real_tethers import REAL_MODEL, STRETCHED_LENGTHS, real_lines

    spec = FeasibilitySpec(real_lines(sat, STRETCHED_LENGTHS), ATLAS_KM, periods=periods,
                           model=REAL_MODEL, method="implicit", rtol=ATLAS_RTOL)
    return run_feasibility(spec, page.out / "feasibility-real", workers=workers,
                           log=lambda *a: None, progress=progress)


def _note() -> str:
    return ("The thesis's tethers are rubber bands (E·1 mm² = 0.004 and 0.0427 N for SatI, a "
            "4-43 kPa modulus); here the same satellite flies on Dyneema SK75 lines (EA, "
            "breaking load and the material's loss factor as a Kelvin-Voigt damper, model "
            "objective-damper). The trim and its move with the air are the equilibria of the "
            "full model; the decay and the fastest mode are from its linearisation. "
            "docs/real-tethers.md.")
