"""Figures of docs/roll.md: the out-of-plane modes and runs of SatI (issue 13)."""
from __future__ import annotations

import math
from functools import cache

import numpy as np

from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.roll import (
    boom_inertias,
    case_satellite,
    roll_case,
    roll_drag_rate,
    roll_response,
    roll_yaw_quartic,
)
from tethersim.engine.simulate import simulate
from tethersim.model.params import with_values
from tethersim.model.presets import load_preset
from tools.docnumbers.check import Figure

R = "docs/roll.md"
H = 3600.0


def _sat():
    return load_preset("satI")


@cache
def _case(case: str, model: str = "3d", c_factor: float = 1.0):
    s = _sat()
    if c_factor != 1.0:
        s = s.replace(c1=s.c1 * c_factor, c2=s.c2 * c_factor)
    return roll_case(s, case, model)


def _w(case, name, model="3d", c=1.0):
    return _case(case, model, c).mode(name).frequency / _sat().omega


def _tau(case, name, model="3d", c=1.0):
    return _case(case, model, c).mode(name).decay_time / H


def _pitch(case, model="3d", c=1.0):
    return _case(case, model, c).pitch


@cache
def _response(model: str):
    return roll_response(_sat(), model, periods=40)


@cache
def _thirty(model: str, phi0_deg: float):
    """20 orbits from the preset's θ0 = 30° with a roll start."""
    s = _sat().replace(initial_3d={"phi": math.radians(phi0_deg)})
    res = simulate(s, periods=20, model=model, progress=False)
    return float(np.degrees(np.max(np.abs(res.series("phi")))))


def _yaw_rate(model: str):
    """Mean yaw advance per orbit over the last 10 orbits of the 40-orbit run [deg]."""
    res = _response(model).result
    psi, t, P = res.series("psi"), res.t, _sat().period
    late = t >= 30 * P
    return float(np.degrees(np.polyfit(t[late] / P, psi[late], 1)[0]))


def _damper_tau():
    s = _sat()
    rate = (s.c1 * s.b**2 + s.c2 * s.a**2) / (2 * boom_inertias(s)["roll"]) + roll_drag_rate(s)
    return 1 / rate / H


def _damper_stiffness():
    s = _sat()
    eq = find_equilibrium(s, "3d")
    n = s.omega
    return (s.c1 * s.b - s.c2 * s.a) * n * eq.delta_x / (boom_inertias(s)["roll"] * n * n)


def _split_tau():
    s = _sat()
    split = case_satellite(s, "drag area split")
    return 1 / roll_drag_rate(s, (split.A1, split.A2)) / H


QUANTITIES = {
    "roll_n": lambda: _sat().omega,
    "roll_I_roll": lambda: boom_inertias(_sat())["roll"],
    "roll_I_yaw": lambda: boom_inertias(_sat())["yaw"],
    "roll_gg": lambda: math.sqrt(-roll_yaw_quartic(_sat())[0]),
    "roll_drag_tau": lambda: 1 / roll_drag_rate(_sat()) / H,
    "roll_split_tau_closed": _split_tau,
    "roll_damper_tau_closed": _damper_tau,
    "roll_damper_stiffness": _damper_stiffness,
    "roll_stiffness_model": lambda: _w("balloon", "roll") ** 2 - _w("boom alone", "roll") ** 2,
    "roll_bal_dz_w": lambda: _w("balloon", "balloon sideways"),
    "roll_bal_dz_tau": lambda: _tau("balloon", "balloon sideways"),
    "roll_obj_dz_tau": lambda: _tau("balloon", "balloon sideways", "3d-objective-damper"),
    "roll_bus_theta": lambda: math.degrees(_case("drag area on the bus").theta),
    "roll_sim_tau": lambda: 1 / _response("3d").roll_decay_rate / H,
    "roll_sim_end": lambda: math.degrees(_response("3d").orbit_peaks["phi"][-1]),
    "roll_sim_obj_tau": lambda: 1 / _response("3d-objective-damper").roll_decay_rate / H,
    "roll_sim_obj_end": lambda: math.degrees(
        _response("3d-objective-damper").orbit_peaks["phi"][-1]),
    "roll_sim_theta_end": lambda: math.degrees(_response("3d").orbit_peaks["theta"][-1]),
    "roll_yaw_rate_closed": lambda: 360 * math.sin(math.radians(5.0)),
    "roll_yaw_rate": lambda: _yaw_rate("3d-objective-damper"),
    "roll_thirty_3d": lambda: _thirty("3d", 5.0),
    "roll_thirty_obj": lambda: _thirty("3d-objective-damper", 5.0),
    "roll_seed_3d": lambda: _thirty("3d", 1e-4) / 1e-4,
    "roll_seed_obj": lambda: _thirty("3d-objective-damper", 1e-4) / 1e-4,
}

_T = "| case | roll ω/n | roll decay [h] | pitch ω/n | pitch decay [h] |"
ROWS = {  # table row label -> (case, model, damping factor)
    "balloon, thesis damper (`3d`)": ("balloon", "3d", 1.0),
    "balloon, thesis damper, exact gravity": ("balloon", "3d-exact-gravity", 1.0),
    "balloon, objective damper": ("balloon", "3d-objective-damper", 1.0),
    "balloon, thesis damper, c = 0": ("balloon", "3d", 0.0),
    "balloon, thesis damper, 10 c": ("balloon", "3d", 10.0),
    "boom alone": ("boom alone", "3d", 1.0),
    "balloon's area split on the ends": ("drag area split", "3d", 1.0),
    "balloon's area on the bus": ("drag area on the bus", "3d", 1.0),
}
COLUMNS = (
    lambda c, m, f: _w(c, "roll", m, f),
    lambda c, m, f: _tau(c, "roll", m, f),
    lambda c, m, f: _pitch(c, m, f).frequency / _sat().omega,
    lambda c, m, f: _pitch(c, m, f).decay_time / H,
)
FIGURES = [Figure(R, (_T, "| balloon's area on the bus (θ = "), "roll_bus_theta",
                  absolute=True)]
for _i, (_label, _args) in enumerate(ROWS.items()):
    _row = f"| {_label}" + (" (θ = " if _args[0] == "drag area on the bus" else " | ")
    for _j, _col in enumerate(COLUMNS):
        _key = f"roll_table_{_i}_{_j}"
        QUANTITIES[_key] = (lambda col, a: lambda: col(*a))(_col, _args)
        _at = (_T, _row) + ((" | ",) if _args[0] == "drag area on the bus" else ()) \
            + (" | ",) * _j
        FIGURES.append(Figure(R, _at, _key))
FIGURES += [
    Figure(R, ("n = ",), "roll_n"),
    Figure(R, ("I_roll = I_pitch = ",), "roll_I_roll"),
    Figure(R, ("I_yaw = ",), "roll_I_yaw"),
    Figure(R, ("√(1 + 3k1) = ",), "roll_gg"),
    Figure(R, ("(A1 b² + A2 a²): ",), "roll_drag_tau"),
    Figure(R, ("(c1 b² + c2 a²)/(2 I_roll) plus that drag rate: ",), "roll_damper_tau_closed"),
    Figure(R, ("(c1 b − c2 a) n δx / (I_roll n²) = ",), "roll_damper_stiffness"),
    Figure(R, ("the linear modes give ",), "roll_stiffness_model"),
    Figure(R, ("split drag closed form: ",), "roll_split_tau_closed"),
    Figure(R, ("sideways on its tethers at ",), "roll_bal_dz_w"),
    Figure(R, ("sideways on its tethers at ", "n, decaying in "), "roll_bal_dz_tau"),
    Figure(R, ("objective dampers it decays in ",), "roll_obj_dz_tau"),
    Figure(R, ("fitted roll decay time ",), "roll_sim_tau"),
    Figure(R, ("fitted roll decay time ", "roll in the 40th orbit "), "roll_sim_end"),
    Figure(R, ("fitted roll decay time ", "pitch within "), "roll_sim_theta_end"),
    Figure(R, ("objective damper: fitted ",), "roll_sim_obj_tau"),
    Figure(R, ("objective damper: fitted ", "40th orbit "), "roll_sim_obj_end"),
    Figure(R, ("360° sin φ0 = ",), "roll_yaw_rate_closed"),
    Figure(R, ("360° sin φ0 = ", "measured "), "roll_yaw_rate"),
    Figure(R, ("roll start grows to ",), "roll_thirty_3d"),
    Figure(R, ("roll start grows to ", " and "), "roll_thirty_obj"),
    Figure(R, ("amplified ",), "roll_seed_3d"),
    Figure(R, ("amplified ", " and "), "roll_seed_obj"),
]

# --- the planar stability map under an out-of-plane start (E1 x E2/E1 points) ------
MAP_POINTS = ((0.004, 10.7), (0.01, 10.7), (0.004, 5.0), (0.004, 20.0), (0.01, 20.0))
OUT_OF_PLANE_START = {"phi": math.radians(5.0), "psi": math.radians(5.0), "delta_z": 1.0}


# runs that leave the 3-D domain (|φ| > 80°, tethersim.engine.domain) before 50 orbits: the
# doc prints the orbit where they left in the θ column and "—" as φ end
LEFT_DOMAIN = {((0.01, 20.0), "3d"), ((0.01, 20.0), "3d-objective-damper")}


@cache
def _map_run(E1: float, ratio: float, model: str) -> tuple:
    """(pitch half-range, largest |φ| of the run, largest |φ| in the last 5 orbits) [rad]
    of 50 orbits from the preset's start (θ0 = 30°), out of the plane for a 3-D model; a
    run that left the domain gives (orbit where it left, largest |φ|, NaN)."""
    s = with_values(_sat(), {"E1": E1, "E2": E1 * ratio})
    s = s.replace(initial_3d=OUT_OF_PLANE_START if model.startswith("3d") else {})
    res = simulate(s, periods=50, model=model, progress=False)
    left = ((E1, ratio), model) in LEFT_DOMAIN
    if left != (res.status == "left-domain"):  # the doc's table says otherwise: fail there
        return math.nan, math.nan, math.nan
    late = res.t > res.t[-1] - 5 * s.period
    th = res.theta[late]
    if not model.startswith("3d"):
        return float((th.max() - th.min()) / 2), 0.0, 0.0
    phi = np.abs(res.series("phi"))
    if left:
        return float(res.t[-1] / s.period), float(phi.max()), math.nan
    return float((th.max() - th.min()) / 2), float(phi.max()), float(phi[late].max())


_M = "| E1 [N/mm²], E2/E1 | planar θ | `3d` θ | `3d` φ end |"  # start of the header
MAP_COLUMNS = (  # (model, item of _map_run)
    ("derived", 0), ("3d", 0), ("3d", 2), ("objective-damper", 0),
    ("3d-objective-damper", 0), ("3d-objective-damper", 1), ("3d-objective-damper", 2),
)
for _i, (_e, _r) in enumerate(MAP_POINTS):
    for _j, (_model, _item) in enumerate(MAP_COLUMNS):
        if _item == 2 and ((_e, _r), _model) in LEFT_DOMAIN:
            continue  # printed "—"
        _key = f"roll_map_{_i}_{_j}"
        QUANTITIES[_key] = (lambda e, r, m, k: lambda: _map_run(e, r, m)[k])(_e, _r, _model,
                                                                             _item)
        _left = ("left in orbit ",) if ((_e, _r), _model) in LEFT_DOMAIN and _item == 0 else ()
        FIGURES.append(Figure(R, (_M, f"| {_e:g}, {_r:g} | ") + (" | ",) * _j + _left, _key))
FIGURES += [
    Figure(R, ("past 80° in orbit ",), "roll_map_4_4"),
    Figure(R, ("the limit, ",), "roll_map_4_5"),
    Figure(R, ("rad) and orbit ",), "roll_map_4_1"),
]
