"""The numbers of docs/feasibility.md: ``python -m tools.feasibility_doc``.

Prints the SatI answer at 200 km and a small altitude scan as Markdown, computed
with :mod:`tethersim.experiments.feasibility` (the same runs as ``tethersim
feasibility satI``); docs/feasibility.md pastes the output unchanged and
tests/output/test_feasibility_doc.py checks its 200 km row.
"""
from __future__ import annotations

import math
import tempfile

SCAN_KM = (200.0, 225.0, 250.0, 300.0, 350.0, 400.0)
PERIODS = 50.0  # orbits per circular run: three days (thesis p. 5-6)
MAX_LIFETIME_H = 240.0


def _f(v, fmt=".3g") -> str:
    return "–" if not math.isfinite(v) else format(v, fmt)


def scan_rows(altitudes=SCAN_KM, sat_name: str = "satI", workers: int = 2) -> list:
    """Atlas rows of ``sat_name`` at ``altitudes`` [km] (a throw-away store)."""
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    from tethersim.model.presets import load_preset

    spec = FeasibilitySpec(load_preset(sat_name), tuple(altitudes), periods=PERIODS,
                           max_lifetime_h=MAX_LIFETIME_H)
    with tempfile.TemporaryDirectory() as tmp:
        return run_feasibility(spec, tmp, workers=workers, log=lambda *a: None)


def table_line(r: dict) -> str:
    """One Markdown row of the scan."""
    reentry = ("≥ " if r["reentry_capped"] else "") + _f(r["reentry_h"])
    trims = " / ".join(_f(r[k], "+.3f") for k in ("theta_ss_min_rad", "theta_ss_mean_rad",
                                                   "theta_ss_max_rad"))
    scales = " / ".join(_f(r[f"scale_{c}"], ".2f") for c in ("min", "mean", "max"))
    verdicts = (r["verdict"] if r["verdict"] != "sensitive" else
                f"sensitive ({r['verdict_rtol']} / {r['verdict_check_rtol']})")
    return (f"| {r['altitude_km']:g} | {_f(r['balloon_lost_h'])} | {reentry} | "
            f"{r['free_end']} at {r['end_altitude_km']:.0f} km | {_f(r['settling_h'])} | "
            f"{_f(r['theta_ss_rad'], '+.3f')} / {_f(r['theta_ss_check_rad'], '+.3f')} | "
            f"{scales} | {trims} | {_f(r['drag_makeup_m_s_day'])} | {verdicts} |")


HEADER = ("| start altitude [km] | balloon lost [h] | re-entry [h] | free run ended | "
          "settling [h] | θ_ss nominal, rtol 1e-10 / 1e-12 [rad] | density scale min / mean / "
          "max | θ_ss min / mean / max [rad] | drag make-up [m/s/day] | verdict (1e-10 / "
          "1e-12 if sensitive) |\n|---|---|---|---|---|---|---|---|---|---|")


def main() -> None:
    """Print the Markdown of docs/feasibility.md's numbers."""
    rows = scan_rows()
    print(f"SatI, {PERIODS:g}-orbit circular runs, free runs capped at {MAX_LIFETIME_H:g} h:\n")
    print(HEADER)
    for r in rows:
        print(table_line(r))


if __name__ == "__main__":
    main()
