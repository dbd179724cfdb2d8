"""The report's section "does the thesis's design work in a real orbit?" (docs/feasibility.md)."""
from __future__ import annotations

import html
import math

from tethersim.output.page import Page
from tethersim.output.page import table as _table

ALTITUDES_KM = (200.0, 250.0, 300.0)  # the thesis's 200 km and two higher starts
LIFETIME_CAP_ORBITS = 4  # x the circular runs' length: the free runs' cap


def _h(v) -> str:
    return "never" if not math.isfinite(v) else f"{v:.3g}"


def section_feasibility(page: Page, periods: float, workers=None, sat_name: str = "satI",
                        progress: bool | None = None) -> list:
    """Run the SatI atlas at :data:`ALTITUDES_KM` into OUT/feasibility and add the section.

    Parameters
    ----------
    page : Page
        The report page.
    periods : float
        Orbits of each circular run; the free runs are capped at
        :data:`LIFETIME_CAP_ORBITS` times as long.
    workers : int, optional
        Threads.
    sat_name : str, optional
        Preset.
    progress : bool or None, optional
        The atlas's progress bar (``run_feasibility``'s; False: none, the report's
        ``--quiet``).

    Returns
    -------
    list of dict
        The atlas rows.
    """
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    from tethersim.model.presets import load_preset
    from tethersim.output.plots.feasibility import plot_feasibility

    sat = load_preset(sat_name)
    cap_h = LIFETIME_CAP_ORBITS * periods * sat.period / 3600
    spec = FeasibilitySpec(sat, ALTITUDES_KM, periods=periods, max_lifetime_h=cap_h)
    store = page.out / "feasibility"
    rows = run_feasibility(spec, store, workers=workers, log=lambda *a: None, progress=progress)
    png = plot_feasibility(rows, page.out / "img" / "feasibility.png",
                           title=f"{sat.name}: does the design work in a real orbit?")
    body = [atlas_table(rows)]
    body.append(page.img(png, "When the free orbit loses its balloon (solid) and re-enters "
                              "(dotted), band: solar min to max air; settling time of the held "
                              "circular orbit (dashed); markers coloured by verdict (diamond: "
                              "sensitive to the integrator tolerance)."))
    body.append(f"<p class='note'>{html.escape(_note(spec))}</p>")
    page.add("Does the thesis's design work in a real orbit?", "\n".join(body))
    return rows


def atlas_table(rows, caption: str = "") -> str:
    """The atlas's rows as the report's table (one per start altitude)."""
    return _table(
        ["start altitude [km]", "balloon lost [h]", "re-entry [h]", "free run ended",
         "settling [h]",
         "θ_ss nominal / min / mean / max [rad]", "drag make-up [m/s/day]", "feasibility verdict"],
        [[f"{r['altitude_km']:g}", _h(r["balloon_lost_h"]),
          ("≥ " if r["reentry_capped"] else "") + _h(r["reentry_h"]),
          f"{r['free_end']} at {r['end_altitude_km']:.0f} km", _h(r["settling_h"]),
          " / ".join(f"{r[k]:+.3f}" for k in ("theta_ss_rad", "theta_ss_min_rad",
                                               "theta_ss_mean_rad", "theta_ss_max_rad")),
          f"{r['drag_makeup_m_s_day']:.3g}", r["verdict"]] for r in rows], caption=caption)


def _note(spec) -> str:
    return (f"Free orbit: per-body Vallado air, capped at {spec.max_lifetime_h:.3g} h; it also "
            f"loses the balloon when a tether stretches beyond 20x its rest length as the air "
            f"thickens; the boom alone then continues to re-entry. A verdict is decided at "
            f"rtol {spec.rtol:g} and {spec.check_rtol:g}: 'sensitive' where they differ. "
            f"Circular runs: {spec.periods:g} orbits, uniform density; trim runs scale it to "
            f"NRLMSISE-00 (24-h mean, equator, March equinox) at solar min/mean/max. "
            f"Trim band ±0.05 rad (thesis p. 5-18). docs/feasibility.md.")
