"""The report's section "why E2/E1 ≈ b/a" (docs/torque-balance.md): the torque balance of the
two tethers about the COM beside the stability maps' band slopes and the thesis's reading."""
from __future__ import annotations

from tethersim.model.presets import load_preset
from tethersim.output.page import Page
from tethersim.output.page import table as _table


def section_torque_balance(page: Page, maps: list, sats) -> None:
    """Add the section and a facts row per satellite: balanced E2/E1 (formula and exact)
    beside b/a, the preset's ratio and the E1 x E2 maps' band slopes (``maps``' rows).

    Parameters
    ----------
    page : Page
        The report page.
    maps : list
        The stability-map rows (satellite name, figure, axes, classes, band slope, ...).
    sats : sequence of str
        Preset names (satI, satII, dumbsat).
    """
    from tethersim.analysis.torque_balance import balanced_E2, torque_balance_ratio

    rows = []
    slopes = {r[0]: r[4] for r in maps if r[2].startswith("E1")}
    for n in sats:
        sat = load_preset(n)
        exact = balanced_E2(sat) / sat.E1
        formula = torque_balance_ratio(sat)
        rows.append((sat.name, f"{sat.b / sat.a:.4g}", f"{formula:.4g}", f"{exact:.4g}",
                     f"{sat.E2 / sat.E1:.4g}", slopes.get(sat.name, "—")))
        thesis_ratio, thesis = {"satI": (10.0, "about 10 (b/a a little over 10)"),
                                "satII": (20.0, "about 20 (b/a ≈ 24)"),
                                "dumbsat": (1.0, "1:1")}[n]
        close = abs(exact / thesis_ratio - 1) <= 0.1
        page.fact(f"{sat.name}: stable moduli around E2/E1 = {thesis}", "5-18, 5-19, 5-23",
                  f"balanced E2/E1 = {exact:.4g}; b/a = {sat.b / sat.a:.4g}; sweep band slope "
                  f"{slopes.get(sat.name, '—')}", "yes" if close else "partly",
                  "torque balance of the two tethers about the COM: b T1 = a T2 with equal "
                  "strains gives E2/E1 ≈ b/a (docs/torque-balance.md)"
                  + ("" if close else f"; the thesis read about {thesis_ratio:g} off a coarse "
                     f"map, the balance puts the band at {exact:.3g} ≈ b/a"))
    page.add("Why E2/E1 ≈ b/a: torque balance (docs/torque-balance.md)", _table(
        ("satellite", "b/a", "formula TB4", "exact balanced E2/E1", "preset E2/E1",
         "sweep band slope"), rows,
        reasons={"sweep band slope": "no stable band on the E1 x E2 grids of this report"}))
