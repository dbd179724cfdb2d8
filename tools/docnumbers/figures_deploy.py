"""Figures of docs/real-tethers.md, "Deployment: the catch at full length": SatI's stretched
bridle of 1 mm Dyneema (tethersim.experiments.real_tethers) started at the end of a braked
deployment and as free releases (tethersim.experiments.deployment), one orbit each on the
implicit scheme, sampled every 2 ms (about 40 s on 2 cores: the slow tier).

``tethersim deploy satI --set l10=30.83 --set l20=28.92 --tethers dyneema-sk75:1`` runs the
table's starts.  The loads do not move with the last bits of the arithmetic; the pitch
excursions of the arrivals do, by up to 30 % (the phases of hundreds of rebounds: over
rtol 1e-8 to 1e-10, :data:`SPREAD_RTOLS`), and are checked to that; the time back in the
band at 1 m/s jumps between two values, and the table prints both; a boom that turned
over is chaotic and only the fact is printed.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.experiments.deployment import (
    RELEASE,
    arrival,
    balloon_radius,
    catch_closed_form,
    deploy,
    pull_along_trim,
    released,
    settle,
)
from tethersim.experiments.real_tethers import (
    RUN_TOLERANCES,
    STRETCHED_LENGTHS,
    real_lines,
)
from tethersim.model.materials import LOSS_FACTOR
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

D = "docs/real-tethers.md"
H = "## Deployment: the catch at full length"
SPEEDS = (0.01, 0.03, 0.1, 0.3, 1.0, 3.0)  # m/s: the table's arrivals
SPREAD_RTOLS = (1e-8, 1e-9, 1e-10)  # the pitch's figures' spread with the arithmetic
SCAN = tuple(round(0.05 * k, 2) for k in range(1, 13))  # m/s: 0.05 ... 0.6
RELEASES = tuple((d, o) for d in (2.5, 3.0, 5.0, 10.0) for o in (-0.5, 0.0, 0.5))  # (δx, δy) m


@cache
def bridle():
    return real_lines(load_preset("satI"), STRETCHED_LENGTHS)


def _summary(dep) -> dict:
    keep = ("first_catch", "catch_speed", "catch_duration", "first_peak", "spin", "peak",
            "safety_factor", "catches", "excursion", "turned_over", "inverted", "clearance")
    return {k: getattr(dep, k) for k in keep}


def late_catches(res, fraction: float = 0.1) -> int:
    """Slack-to-taut switches seen on the run's sampling grid in its last ``fraction``,
    both lines together: a line still ringing at the end of the orbit."""
    taut = res.tether_tensions()[res.t >= (1 - fraction) * res.t[-1]] > 0
    return int(np.sum(~taut[:-1] & taut[1:]))


@cache
def arrived(speed: float, rtol: float = RUN_TOLERANCES["rtol"]) -> dict:
    start = arrival(bridle(), speed)
    dep = deploy(start, rtol=rtol)
    res = dep.result  # the ringing line's counts (the releases do not need them)
    return {**_summary(dep), **settle(start, rtol=rtol), "switches": res.n_switches,
            "steps": res.n_accepted, "late_catches": late_catches(res)}


def spread(speed: float, key: str) -> tuple:
    """(smallest, largest) of an arrival's figure over :data:`SPREAD_RTOLS`."""
    values = [arrived(speed, rtol)[key] for rtol in SPREAD_RTOLS]
    return min(values), max(values)


@cache
def release() -> dict:
    """The free release from :data:`RELEASE` behind the COM, with the boom's spin after
    the catch."""
    dep = deploy(released(bridle(), RELEASE))
    return {**_summary(dep), "spin_orbits": dep.spin / bridle().omega}


@cache
def ensemble() -> tuple:
    return tuple(_summary(deploy(released(bridle(), d, o))) for d, o in RELEASES)


@cache
def first_leaving_speed() -> float:
    """The slowest arrival of :data:`SCAN` whose pitch leaves the ±0.05 rad band."""
    for v in SCAN:
        if deploy(arrival(bridle(), v)).excursion > SETTLING_TOL:
            return v
    return math.nan


def closed_form_ratio() -> float:
    """The first catch's pull along the trim line over the modal closed form, SatI at 1 m/s
    with the dampers off (tests/experiments/test_deployment.py)."""
    start = arrival(bridle().replace(c1=0.0, c2=0.0), 1.0)
    dep = deploy(start, periods=1e-4, sample=2e-4)
    return float(pull_along_trim(dep.result, start).max() / catch_closed_form(start))


@cache
def rubber_bands() -> tuple:
    """(peak tension [N], further stretch [m]) of SatI's own tethers taking an arrival at
    1 m/s: the first catch (0.05 orbit holds it: the bounce's period is ~70 s)."""
    dep = deploy(arrival(load_preset("satI"), 1.0), periods=0.05)
    y = dep.result.model_states
    r = np.hypot(y[:, 0], y[:, 1])
    return dep.first_peak, float(r.max() - r[0])


def payout_rule() -> tuple:
    """(b² − a² [m²], l10² − l20² of the stretched bridle [m²], its rigid apex's height
    above the COM with the boom upright [m]): the pay-out rule's figures."""
    s = bridle()
    rule, lines = s.b ** 2 - s.a ** 2, s.l10 ** 2 - s.l20 ** 2
    # x² + (y − b)² = l10², x² + (y + a)² = l20²: their difference is linear in y
    return rule, lines, (rule - lines) / (2 * (s.a + s.b))


_T = "| arrival speed [m/s] |"
ROW = ("first_peak", "peak", "safety_factor", "excursion", "settling_h")
# the pitch's figures move with the rebounds' phases (module docstring): the excursions by up
# to 30 % over SPREAD_RTOLS (the doc's "deploy_spread_*"); the time back in the band at 1 m/s
# jumps between two values, so the table prints their range (deploy_1_settling_lo, _hi)
ROW_RTOL = {"excursion": 0.3}
SPREAD = {"deploy_spread_lo": lambda: spread(0.1, "excursion")[0],
          "deploy_spread_hi": lambda: spread(0.1, "excursion")[1],
          "deploy_1_settling_lo": lambda: spread(1.0, "settling_h")[0],
          "deploy_1_settling_hi": lambda: spread(1.0, "settling_h")[1]}
QUANTITIES = {
    "deploy_release_catch_s": lambda: release()["first_catch"],
    "deploy_release_speed": lambda: release()["catch_speed"],
    "deploy_release_peak": lambda: release()["first_peak"],
    "deploy_release_sf": lambda: release()["safety_factor"],
    "deploy_release_spin": lambda: release()["spin"],
    "deploy_release_spin_orbits": lambda: release()["spin_orbits"],
    "deploy_release_catch_ms": lambda: 1e3 * release()["catch_duration"],
    "deploy_k1": lambda: bridle().E1 / bridle().l10,
    "deploy_k2": lambda: bridle().E2 / bridle().l20,
    "deploy_m3": lambda: bridle().m3,
    "deploy_msat": lambda: bridle().m1 + bridle().m2,
    "deploy_ensemble_n": lambda: len(RELEASES),
    "deploy_ensemble_over": lambda: sum(r["turned_over"] for r in ensemble()),
    "deploy_ensemble_peak_min": lambda: min(r["first_peak"] for r in ensemble()),
    "deploy_ensemble_peak_max": lambda: max(r["first_peak"] for r in ensemble()),
    "deploy_ensemble_sf_min": lambda: min(r["safety_factor"] for r in ensemble()),
    "deploy_radius": lambda: balloon_radius(bridle()),
    "deploy_arrivals_over": lambda: sum(arrived(v)["turned_over"] for v in SPEEDS),
    "deploy_arrivals_n": lambda: len(SPEEDS),
    "deploy_over_speed": lambda: min(v for v in SPEEDS if arrived(v)["turned_over"]),
    "deploy_release_distance": lambda: RELEASE,
    "deploy_rubber_peak": lambda: rubber_bands()[0],
    "deploy_rubber_stretch": lambda: rubber_bands()[1],
    "deploy_rtol": lambda: RUN_TOLERANCES["rtol"],
    "deploy_atol": lambda: RUN_TOLERANCES["atol"],
    "deploy_loss": lambda: LOSS_FACTOR,
    "deploy_offset": lambda: max(o for _, o in RELEASES),
    **{f"deploy_release_at_{i}": (lambda k=i: sorted({d for d, _ in RELEASES})[k])
       for i in range(4)},
    "deploy_stable_n": lambda: sum(arrived(v)["settled_class"] == "stable" for v in SPEEDS),
    "deploy_arrivals_sf_min": lambda: min(arrived(v)["safety_factor"] for v in SPEEDS),
    # the rebounds' largest pull over the first catch's, among the arrivals that stay upright
    "deploy_rebound_pc": lambda: 100 * max(arrived(v)["peak"] / arrived(v)["first_peak"] - 1
                                           for v in SPEEDS if not arrived(v)["turned_over"]),
    "deploy_band_speed": first_leaving_speed,
    "deploy_1_switches": lambda: arrived(1.0)["switches"],
    "deploy_1_steps_m": lambda: arrived(1.0)["steps"] / 1e6,
    "deploy_1_late_catches": lambda: arrived(1.0)["late_catches"],
    "deploy_closed_form_pc": lambda: 100 * (1 - closed_form_ratio()),
}
QUANTITIES.update({"deploy_rule": lambda: payout_rule()[0],
                   "deploy_rule_lines": lambda: payout_rule()[1],
                   "deploy_rule_apex": lambda: abs(payout_rule()[2])})
FIGURES = [
    Figure(D, (H, "l10² − l20² = b² − a², "), "deploy_rule"),
    Figure(D, (H, "The stretched bridle's lengths give "), "deploy_rule_lines"),
    Figure(D, (H, "puts the apex "), "deploy_rule_apex"),
    Figure(D, (H, "first pull at "), "deploy_release_catch_s", slow=True),
    Figure(D, (H, "first pull at ", " s and "), "deploy_release_speed", slow=True),
    Figure(D, (H, "One line snaps to "), "deploy_release_peak", slow=True),
    Figure(D, (H, "One line snaps to ", "safety factor "), "deploy_release_sf", slow=True),
    Figure(D, (H, "in a catch of "), "deploy_release_catch_ms", slow=True),
    Figure(D, (H, "EA / l0 = "), "deploy_k1"),
    Figure(D, (H, "EA / l0 = ", " and "), "deploy_k2"),
    Figure(D, (H, "the balloon ("), "deploy_m3"),
    Figure(D, (H, "the balloon (", "satellite's "), "deploy_msat"),
    Figure(D, (H, "spins the boom at "), "deploy_release_spin", slow=True),
    Figure(D, (H, "spins the boom at ", " rad/s, "), "deploy_release_spin_orbits", slow=True),
    Figure(D, (H, "In all "), "deploy_ensemble_n", slow=True),
    Figure(D, (H, "the boom turned over in "), "deploy_ensemble_over", slow=True),
    Figure(D, (H, "first catches of "), "deploy_ensemble_peak_min", slow=True),
    Figure(D, (H, "first catches of ", " to "), "deploy_ensemble_peak_max", slow=True),
    Figure(D, (H, "safety factors down to "), "deploy_ensemble_sf_min", slow=True),
    Figure(D, (H, "of radius "), "deploy_radius"),
    Figure(D, (H, "turns the boom over in "), "deploy_arrivals_over", slow=True),
    Figure(D, (H, "turns the boom over in ", " of "), "deploy_arrivals_n", slow=True),
    Figure(D, (H, "the boom first turns over at "), "deploy_over_speed", slow=True),
    Figure(D, (H, "turns the boom over.** From "), "deploy_release_distance"),
    Figure(D, (H, "with a peak of "), "deploy_rubber_peak", slow=True),
    Figure(D, (H, "with a peak of ", "stretching "), "deploy_rubber_stretch", slow=True),
    Figure(D, (H, "on Radau IIA (rtol "), "deploy_rtol"),
    Figure(D, (H, "on Radau IIA (rtol ", "atol "), "deploy_atol"),
    Figure(D, (H, "loss factor of "), "deploy_loss"),
    Figure(D, (H, "In all 12 releases ("), "deploy_release_at_0"),
    Figure(D, (H, "In all 12 releases (", ", "), "deploy_release_at_1"),
    Figure(D, (H, "In all 12 releases (", ", ", ", "), "deploy_release_at_2"),
    Figure(D, (H, "In all 12 releases (", " and "), "deploy_release_at_3"),
    Figure(D, (H, "each level, "), "deploy_offset"),
    Figure(D, (H, "a libration of their own: "), "deploy_stable_n", slow=True),
    Figure(D, (H, "safety factor stays above "), "deploy_arrivals_sf_min", slow=True),
    Figure(D, (H, "pull comes up to "), "deploy_rebound_pc", slow=True),
    Figure(D, (H, "first leaves the band at "), "deploy_band_speed", slow=True),
    # counts of a ringing line: they move with the last bits as the real runs' switches do
    Figure(D, (H, "locates "), "deploy_1_switches", slow=True, rtol=0.25),
    Figure(D, (H, "Radau takes "), "deploy_1_steps_m", slow=True, rtol=0.25),
    Figure(D, (H, "the last tenth of the orbit alone, "), "deploy_1_late_catches", slow=True,
           rtol=0.25),
    Figure(D, (H, "softens the catch by "), "deploy_closed_form_pc", slow=True),
]
QUANTITIES.update(SPREAD)
_S = (H, _T, "| 1 | ") + (" | ",) * ROW.index("settling_h")
# each end of a spread moves with the arithmetic as the excursions do (another CPU's last
# bits): held to the same 30 %
_E = "0.1 m/s arrival's excursion goes from "
FIGURES += [Figure(D, at, key, slow=True, rtol=0.3) for at, key in (
    (_S, "deploy_1_settling_lo"), ((*_S, "–"), "deploy_1_settling_hi"),
    ((H, _E), "deploy_spread_lo"), ((H, _E, " to "), "deploy_spread_hi"),
    ((H, "at 1 m/s from "), "deploy_1_settling_lo"),
    ((H, "at 1 m/s from ", " to "), "deploy_1_settling_hi"))]
for _v in SPEEDS:
    for _j, _key in enumerate(ROW):
        if _key in ("excursion", "settling_h") and _v == SPEEDS[-1]:
            continue  # the row prints "turned over"
        if _key == "settling_h" and _v == 1.0:
            continue  # its range (above)
        QUANTITIES[f"deploy_{_v:g}_{_key}"] = (lambda v, key: lambda: arrived(v)[key])(_v, _key)
        FIGURES.append(Figure(D, (H, _T, f"| {_v:g} | ") + (" | ",) * _j,
                              f"deploy_{_v:g}_{_key}", slow=True, rtol=ROW_RTOL.get(_key, 0.0)))
