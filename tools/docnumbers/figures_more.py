"""Figures of docs/torque-balance.md, the README, the slow (simulated) headline figures and
the 3-D roll limit (docs/limits.md, docs/three-d.md)."""
from __future__ import annotations

import math

from tools.docnumbers import quantities as q
from tools.docnumbers.check import Figure

TB, H, README = "docs/torque-balance.md", "docs/headlines.md", "README.md"
SATS = (("satI", "SatI"), ("satII", "SatII"), ("dumbsat", "DumbSat"))
E1S = (0.0005, 0.001, 0.002, 0.004, 0.0055, 0.01, 0.02)


def _rel(name, key):
    b = q.balance(name)
    return abs(b[key] / b["exact"] - 1)


def _ba(name):
    """How far the exact ratio lies from b/a, relative to b/a."""
    b = q.balance(name)
    return abs(b["exact"] / b["b_over_a"] - 1)


QUANTITIES = {
    "satI_tip_torque": lambda: _tip_torque("satI"),
    "satI_drag_asymmetry": lambda: 2 * (q.sat().a + q.sat().b) / q.sat().r0,
}
FIGURES = [Figure(TB, ("relative 2(a + b)/r0 (",), "satI_drag_asymmetry"),
           Figure(TB, ("In the tether torque, T1 b δx/λ1 is ",), "satI_tip_torque")]


def _tip_torque(name):
    s = q.load_preset(name)
    b = q.balance(name)
    t1 = s.E1 * (b["lambda1"] / s.l10 - 1)
    return t1 * s.b * b["dx"] / b["lambda1"]


# the table of the three presets and the table of the TB4 terms
_T1 = "| satellite | b/a (TB5) |"
_T2 = "| satellite | geometric factor |"
for _n, _label in SATS:
    for _i, _k in enumerate(("b_over_a", "second_order", "ratio", "exact", "preset",
                             "theta_eq", "dx")):
        QUANTITIES[f"{_n}_{_k}"] = (lambda n, k: lambda: q.balance(n)[k])(_n, _k)
        FIGURES.append(Figure(TB, (_T1, f"| {_label} |") + (" | ",) * _i, f"{_n}_{_k}"))
    QUANTITIES[f"{_n}_dy"] = (lambda n: lambda: q.balance(n)["dy"])(_n)
    FIGURES.append(Figure(TB, (_T1, f"| {_label} |") + (" | ",) * 6 + (", ",), f"{_n}_dy"))
    for _i, _k in enumerate(("geometric", "drag_torque", "damper_torque")):
        QUANTITIES[f"{_n}_{_k}"] = (lambda n, k: lambda: q.balance(n)[k])(_n, _k)
        FIGURES.append(Figure(TB, (_T2, f"| {_label} |") + (" | ",) * _i, f"{_n}_{_k}"))
    # accuracy list: TB4 at the own trail, TB6, b/a, and the presets' miss of the balance
    QUANTITIES[f"{_n}_err_tb4"] = (lambda n: lambda: _rel(n, "ratio"))(_n)
    QUANTITIES[f"{_n}_err_tb6"] = (lambda n: lambda: _rel(n, "second_order"))(_n)
    QUANTITIES[f"{_n}_err_ba"] = (lambda n: lambda: _ba(n))(_n)
    QUANTITIES[f"{_n}_err_ba_pct"] = (lambda n: lambda: 100 * _ba(n))(_n)
    QUANTITIES[f"{_n}_miss"] = (lambda n: lambda: q.balance(n)["preset"] / q.balance(n)["exact"]
                                - 1)(_n)
_pos = {"satI": 0, "satII": 1, "dumbsat": 2}
for _n, _ in SATS:
    _skip = (", ",) * _pos[_n] if _n != "dumbsat" else (", ", " and ")
    FIGURES.append(Figure(TB, ("the error is ",) + _skip, f"{_n}_err_tb4"))
    FIGURES.append(Figure(TB, ("The errors are ",) + {"satI": (), "satII": ("(SatI), ",),
                                                      "dumbsat": ("(SatII) and ",)}[_n],
                          f"{_n}_err_tb6"))
    FIGURES.append(Figure(TB, ("miss the exact balance by ",) + _skip, f"{_n}_miss"))
FIGURES += [Figure(TB, ("**b/a** is within ",), "satI_err_ba_pct"),
            Figure(TB, ("**b/a** is within ", "(SatI), "), "satII_err_ba_pct"),
            Figure(TB, ("**b/a** is within ", "(SatII) and "), "dumbsat_err_ba")]
# SatI's balanced E2/E1 and trail against E1
for _i, _e1 in enumerate(E1S):
    QUANTITIES[f"balanced_{_e1}"] = (lambda e: lambda: q.balanced_at(e)[0])(_e1)
    QUANTITIES[f"balanced_trail_{_e1}"] = (lambda e: lambda: q.balanced_at(e)[1])(_e1)
    _sep = (", ",) * _i if _i < len(E1S) - 1 else (", ",) * (_i - 1) + (" and ",)
    FIGURES.append(Figure(TB, ("`balanced_E2` gives E2/E1 = ",) + _sep, f"balanced_{_e1}"))
    FIGURES.append(Figure(TB, ("The trail at balance is ",) + _sep, f"balanced_trail_{_e1}"))
FIGURES.append(Figure(README, ("near b/a (",), "satI_exact"))
FIGURES.append(Figure(README, ("near b/a (", "for SatI, "), "satII_exact"))

# --- slow: simulated -----------------------------------------------------------------------
for _k in ("settling_h", "settling_orbits", "trail", "delta_x", "delta_y", "theta"):
    QUANTITIES[f"run_{_k}"] = (lambda k: lambda: q.run_satI()[k])(_k)
_HL = {"hl_nominal_ss": ("nominal", "derived", "theta_ss"),
       "hl_nominal_mean": ("nominal", "derived", "mean_pitch"),
       "hl_nominal_settling": ("nominal", "derived", "settling_h"),
       "hl_nominal_settling_printed": ("nominal", "printed", "settling_h"),
       "hl_nominal_settling_objective": ("nominal", "objective-damper", "settling_h"),
       "hl_moduli_min": ("moduli-nominal", "derived", "theta_min"),
       "hl_moduli_max": ("moduli-nominal", "derived", "theta_max"),
       "hl_moduli_mean": ("moduli-nominal", "derived", "mean_pitch"),
       "hl_x10_ss": ("damping-x10", "derived", "theta_ss"),
       "hl_x10_settling": ("damping-x10", "derived", "settling_h"),
       "hl_x10_ss_printed": ("damping-x10", "printed", "theta_ss"),
       "hl_x10_settling_printed": ("damping-x10", "printed", "settling_h"),
       "hl_x10_ss_objective": ("damping-x10", "objective-damper", "theta_ss"),
       "hl_x10_settling_objective": ("damping-x10", "objective-damper", "settling_h")}
for _k, (_c, _m, _f) in _HL.items():
    QUANTITIES[_k] = (lambda c, m, f: lambda: q.headline(c, m)[f])(_c, _m, _f)
for _c, _label in (("E1-10%", "E1 −10 %"), ("E1+10%", "E1 +10 %"), ("E2-10%", "E2 −10 %"),
                   ("E2+10%", "E2 +10 %")):
    QUANTITIES[f"hl_mean_{_c}"] = (lambda c: lambda: q.headline(c)["mean_pitch"])(_c)
_NOM = "| nominal (5-7) |"
_X10 = "| damping ×10 (5-13) |"
_MOD = "| 5 orbits, c = 0 |"
FIGURES += [Figure(README, ("±0.05 rad after ",), "run_settling_orbits", slow=True),
            Figure(README, ("±0.05 rad after ", "orbits ("), "run_settling_h", slow=True),
            Figure(README, ("the balloon\ntrails ",), "run_trail", slow=True),
            Figure(README, ("SatI, 50 orbits: δx ",), "run_delta_x", slow=True),
            Figure(README, ("SatI, 50 orbits: δx ", "δy "), "run_delta_y", slow=True),
            Figure(README, ("SatI, 50 orbits: δx ", "θ "), "run_theta", slow=True),
            Figure(H, (_NOM, "θ_ss "), "hl_nominal_ss", slow=True),
            Figure(H, (_NOM, "mean ", "mean "), "hl_nominal_mean", slow=True),
            Figure(H, (_NOM, "settled in "), "hl_nominal_settling", slow=True),
            Figure(H, (_NOM, "settled in ", "h ("), "hl_nominal_settling_printed", slow=True),
            Figure(H, (_NOM, "settled in ", "h; "), "hl_nominal_settling_objective", slow=True),
            Figure(H, ("settles within ±0.05 rad after ",), "hl_nominal_settling", slow=True),
            Figure(H, ("| moduli only (5-2) |", "libration in ["), "hl_moduli_min", slow=True),
            Figure(H, ("| moduli only (5-2) |", "libration in [", ", "), "hl_moduli_max",
                   slow=True),
            Figure(H, ("| moduli only (5-2) |", "rad, mean "), "hl_moduli_mean", slow=True),
            Figure(H, ("The pitch librates between ",), "hl_moduli_min", slow=True),
            Figure(H, ("The pitch librates between ", " and "), "hl_moduli_max", slow=True),
            Figure(H, (_X10, "θ_ss **"), "hl_x10_ss", slow=True),
            Figure(H, (_X10, "settled in "), "hl_x10_settling", slow=True),
            Figure(H, (_X10, "settled in ", "h ("), "hl_x10_ss_printed", slow=True),
            Figure(H, (_X10, "settled in ", "rad, "), "hl_x10_settling_printed", slow=True),
            Figure(H, (_X10, "settled in ", "h; "), "hl_x10_ss_objective", slow=True),
            Figure(H, (_X10, "settled in ", "h; ", "rad, "), "hl_x10_settling_objective",
                   slow=True)]
FIGURES += [Figure(H, (_MOD, "| mean pitch [rad] |") + (" | ",) * i, f"hl_mean_{c}", slow=True)
            for i, c in enumerate(("E1-10%", "E1+10%", "E2-10%", "E2+10%"))]

# --- the 3-D models' roll limit (tethersim.engine.domain; docs/limits.md, docs/three-d.md) --
LIMITS, THREE_D = "docs/limits.md", "docs/three-d.md"


def _roll_conditioning(deg: float) -> float:
    """2-norm condition number (1 + sin|φ|)/cos φ of the 3-1-2 kinematic matrix."""
    phi = math.radians(deg)
    return (1 + math.sin(abs(phi))) / math.cos(phi)


def _roll_limit() -> float:
    from tethersim.model.satellite import ROLL_LIMIT_DEG

    return ROLL_LIMIT_DEG


QUANTITIES.update({
    "roll_limit": _roll_limit,
    "roll_limit_band": lambda: 90.0 - _roll_limit(),
    "roll_cond_limit": lambda: _roll_conditioning(_roll_limit()),
    "roll_cond_89": lambda: _roll_conditioning(89.0),
})
FIGURES += [
    Figure(LIMITS, ("a 3-D model's roll passes ",), "roll_limit"),
    Figure(LIMITS, ("(1 + sin\\|φ\\|)/cos φ is ",), "roll_cond_limit"),
    Figure(LIMITS, ("(1 + sin\\|φ\\|)/cos φ is ", "at 80° and "), "roll_cond_89"),
    Figure(LIMITS, ("a boom within ",), "roll_limit_band"),
    Figure(THREE_D, ("a run whose roll passes ",), "roll_limit"),
    Figure(THREE_D, ("(1 + sin|φ|)/cos φ is ",), "roll_cond_limit"),
    Figure(THREE_D, ("a boom rolled that far is within ",), "roll_limit_band"),
    Figure(THREE_D, ("|φ| is guarded at ",), "roll_limit"),
]
FIGURES += [Figure(README, ("a 3-D run\nalso when its roll passes ",), "roll_limit")]
