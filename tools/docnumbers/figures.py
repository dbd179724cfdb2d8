"""Which number in which doc is which quantity: the table the doc-number test walks.

Each key of :data:`QUANTITIES` computes one value (quantities.py); each entry of
:data:`FIGURES` says where a doc prints it.  A figure edited in a doc without the
code agreeing, or code changed without the doc, fails ``tests/output/test_doc_numbers.py``.
"""
from __future__ import annotations

import math
from dataclasses import replace

from tools.docnumbers import quantities as q
from tools.docnumbers.check import Figure

H, TB, README, CONV = "docs/headlines.md", "docs/torque-balance.md", "README.md", \
    "docs/conventions.md"


def _nominal():
    return q.branch("derived", 0.0, 1.0)


QUANTITIES = {
    # where the inverted branch of the thesis damper vanishes
    "fold": lambda: q.fold_factor(),
    "fold_c": lambda: q.fold_factor() * q.sat().c1,
    # nominal SatI equilibrium and its modes
    "tether_fast": lambda: q.mode_freq(-1),
    "tether_slow": lambda: q.mode_freq(-2),
    "tether_fast_period": lambda: 2 * math.pi / q.mode_freq(-1),
    "tether_slow_period": lambda: 2 * math.pi / q.mode_freq(-2),
    "rk4_limit": lambda: q.rk4_max_step(q.sat()),
    "faithful_pct": lambda: 100 * q.step() / q.rk4_max_step(q.sat()),
    "moduli_pct": lambda: 100 * q.step(q.MODULI_STEP) / q.rk4_max_step(q.sat()),
    "faithful_step": lambda: q.step(),
    "moduli_step": lambda: q.step(q.MODULI_STEP),
    "theta_eq": lambda: _nominal().theta,
    "pitch_w": lambda: q.pitch_mode(_nominal())[0],
    "pitch_zeta": lambda: q.pitch_mode(_nominal())[1],
    "pitch_decay_h": lambda: q.pitch_mode(_nominal())[2] / 3600,
    "amplitude": lambda: q.sat().initial[2] - _nominal().theta,
    "predicted_settling_h":
        lambda: _nominal().predicted_settling_time(q.sat().initial[2] - _nominal().theta) / 3600,
    # the mirror pair of E1 + 10 %, c = 0
    "mirror_low": lambda: q.mirror(1.1, 0.6),
    "mirror_high": lambda: q.mirror(1.1, 2.5),
    # the thesis damper's torque at rest
    "rest_torque_1": lambda: q.rest_torque(1.0),
    "rest_torque_10": lambda: q.rest_torque(10.0),
    "upright_shift_per_factor":
        lambda: (q.branch("derived", 0.0, 10.0).theta - _nominal().theta) / 9,
    "objective_upright": lambda: q.branch("objective-damper", 0.0, 1.0).theta,
    "objective_upright_x10000": lambda: q.branch("objective-damper", 0.0, 10000.0).theta,
    "objective_inverted": lambda: q.branch("objective-damper", math.pi, 1.0).theta,
    "inverted_x10": lambda: q.branch("derived", math.pi, 10.0).theta,
    "inverted_x10_derived": lambda: q.inverted_mod_2pi("derived", 10.0),
    "inverted_x10_printed": lambda: q.inverted_mod_2pi("printed", 10.0),
    "inverted_x10_objective": lambda: q.inverted_mod_2pi("objective-damper", 10.0),
    "decay_x10_inverted_h": lambda: q.pitch_mode(q.branch("derived", math.pi, 10.0))[2] / 3600,
    "amp_x10": lambda: q.scan_row(10.0, "amp"),
    "max_step_x10": lambda: q.scan_row(10.0, "max_step"),
    "amp_nominal": lambda: q.scan_row(1.0, "amp"),
    "air_speed": q.air_speed,
    "amp_moduli": lambda: q.rk4_amplification(q.sat(factor=0.0), q.step(q.MODULI_STEP), "derived"),
}
for _f in (1, 10, 100, 1000, 10000):
    QUANTITIES[f"upright_{_f}"] = (lambda f: lambda: q.branch("derived", 0.0, float(f)).theta)(_f)
for _f in (1, 10, 50, 80):
    QUANTITIES[f"w_up_{_f}"] = (lambda f: lambda: q.pitch_mode(
        q.branch("derived", 0.0, float(f)))[0])(_f)
    QUANTITIES[f"w_inv_{_f}"] = (lambda f: lambda: q.pitch_mode(
        q.branch("derived", math.pi, float(f)))[0])(_f)
for _f in (1, 10, 30, 70, 100, 270, 280, 290):
    for _w in ("amp", "max_step", "inverted"):
        QUANTITIES[f"scan_{_w}_{_f}"] = (lambda f, w: lambda: q.scan_row(float(f), w))(_f, _w)

FIGURES = [
    Figure(H, ("vanishes at a damping factor of ",), "fold"),
    Figure(H, ("vanishes at a damping factor of ", "(c = "), "fold_c"),
    Figure(H, ("lost at ×",), "fold"),
    Figure(H, ("bouncing on its two taut tethers, at ",), "tether_fast"),
    Figure(H, ("bouncing on its two taut tethers, at ", " and "), "tether_slow"),
    Figure(H, ("(periods ",), "tether_fast_period"),
    Figure(H, ("(periods ", "s and "), "tether_slow_period"),
    Figure(H, ("which puts the limit at **",), "rk4_limit"),
    Figure(H, ("The thesis's 26.55 s is\n",), "faithful_pct"),
    Figure(H, ("The thesis's 26.55 s is\n", "of that limit and 17.70 s is "), "moduli_pct"),
    Figure(H, ("1500 steps, **",), "moduli_step"),
    Figure(H, ("10,000 steps, **",), "faithful_step"),
    Figure(H, ("At the equilibrium θ = ",), "theta_eq"),
    Figure(H, ("pitch libration: ω = ",), "pitch_w"),
    Figure(H, ("pitch libration: ω = ", "damping ratio "), "pitch_zeta"),
    Figure(H, ("pitch libration: ω = ", "decay time\n"), "pitch_decay_h"),
    Figure(H, ("takes ln(",), "amplitude"),
    Figure(H, ("takes ln(", "× "), "pitch_decay_h"),
    Figure(H, ("takes ln(", "h = "), "predicted_settling_h"),
    Figure(H, ("E1 +10 % has them at ",), "mirror_low"),
    Figure(H, ("E1 +10 % has them at ", " and "), "mirror_high"),
    Figure(H, ("E1 +10 % has them at ", "= π − "), "mirror_low"),
    Figure(H, ("tilts every equilibrium towards +θ.** It is\n   ",), "rest_torque_1"),
    Figure(H, ("at the nominal c and ",), "rest_torque_10"),
    Figure(H, ("moves the upright equilibrium by about ",), "upright_shift_per_factor"),
    Figure(H, ("the equilibrium stays at ",), "objective_upright"),
    Figure(H, ("the equilibrium stays at ",), "objective_upright_x10000"),
    Figure(H, ("exact mirror images for every\n   factor: ",), "objective_upright"),
    Figure(H, ("exact mirror images for every\n   factor: ", "rad and "), "objective_inverted"),
    Figure(H, ("which is π + ",), "objective_upright", absolute=True),
    Figure(H, ("It sits at θ = ",), "inverted_x10"),
    Figure(H, ("It sits at θ = ", "≡ **"), "inverted_x10_derived"),
    Figure(H, ("It sits at θ = ", "(derived), "), "inverted_x10_printed"),
    Figure(H, ("It sits at θ = ", "(printed) and "), "inverted_x10_objective"),
    Figure(H, ("its slowest decay time is ",), "decay_x10_inverted_h"),
    Figure(H, ("the amplification is ",), "amp_x10"),
    Figure(H, ("the amplification is ", "the largest stable step is "), "max_step_x10"),
    Figure(H, ("it lengthens it slightly** (",), "rk4_limit"),
    Figure(H, ("it lengthens it slightly** (", "s → "), "max_step_x10"),
    Figure(H, ("| nominal (5-7) |", "amplification "), "amp_nominal"),
    Figure(H, ("| damping ×10 (5-13) |", "amplification "), "amp_x10"),
    Figure(H, ("up to the linear limit\n(",), "rk4_limit"),
    Figure(H, ("up to the linear limit\n(", "s and "), "max_step_x10"),
    Figure(H, ("| moduli only (5-2) |", "amplification "), "amp_moduli"),
    Figure("docs/numbers.md", ("puts the fold at\n×",), "fold"),
    Figure(CONV, ("air speed of the COM is (ω − ω_E) r0 ≈ ",), "air_speed"),
    Figure(README, ("1500 steps) and ",), "faithful_step"),
    Figure(README, ("come out exactly: ",), "moduli_step"),
]
# the upright-equilibrium table and the pitch-mode table of the damper section
_TABLE1 = "| damping factor | upright equilibrium [rad] |"
for _f, _label in ((1, "1"), (10, "10"), (100, "100"), (1000, "1000"), (10000, "10,000")):
    FIGURES.append(Figure(H, (_TABLE1, f"| {_label} | "), f"upright_{_f}"))
_TABLE2 = "| damping factor | upright ω [rad/s] | inverted ω [rad/s] |"
for _f in (1, 10, 50, 80):
    FIGURES.append(Figure(H, (_TABLE2, f"| {_f} | "), f"w_up_{_f}"))
    FIGURES.append(Figure(H, (_TABLE2, f"| {_f} | ", " | "), f"w_inv_{_f}"))
# the damping-scan table: RK4 amplification, largest stable step, inverted equilibrium
_SCAN = "| factor (c [N s/m]) |"
for _f, _c in ((1, "3e-4"), (10, "3e-3"), (30, "9e-3"), (70, "0.021"), (100, "0.03"),
               (270, "0.081"), (280, "0.084"), (290, "0.087")):
    _row = f"| {_f} ({_c}) |"
    FIGURES.append(Figure(H, (_SCAN, _row, " | ", " | "), f"scan_amp_{_f}"))
    FIGURES.append(Figure(H, (_SCAN, _row, " | ", " | ", " | "), f"scan_max_step_{_f}"))
    if _f <= 70:
        FIGURES.append(Figure(H, (_SCAN, _row, " | ", " | ", " | ", " | "),
                              f"scan_inverted_{_f}"))

from tools.docnumbers import figures_more as _more  # noqa: E402

QUANTITIES.update(_more.QUANTITIES)
FIGURES += _more.FIGURES

from tools.docnumbers import figures_cases as _cases  # noqa: E402

QUANTITIES.update(_cases.QUANTITIES)
FIGURES += _cases.FIGURES

from tools.docnumbers import figures_roll as _roll  # noqa: E402

QUANTITIES.update(_roll.QUANTITIES)
# every roll figure compiles the 3-D kernels (jacobian ~15 s cold) or runs them for 40-50
# orbits: the slow tier (make test-slow, CI) checks them all
FIGURES += [replace(f, slow=True) for f in _roll.FIGURES]

from tools.docnumbers import figures_air as _air  # noqa: E402

QUANTITIES.update(_air.QUANTITIES)
FIGURES += _air.FIGURES

from tools.docnumbers import figures_orbit as _orbit  # noqa: E402

QUANTITIES.update(_orbit.QUANTITIES)
FIGURES += _orbit.FIGURES

from tools.docnumbers import orbit_notes as _notes  # noqa: E402

QUANTITIES.update(_notes.QUANTITIES)
FIGURES += _notes.FIGURES

from tools.docnumbers import figures_tolerance as _tolerance  # noqa: E402

QUANTITIES.update(_tolerance.QUANTITIES)
FIGURES += _tolerance.FIGURES

from tools.docnumbers import figures_real as _real  # noqa: E402

QUANTITIES.update(_real.QUANTITIES)
FIGURES += _real.FIGURES

from tools.docnumbers import figures_single as _single  # noqa: E402

QUANTITIES.update(_single.QUANTITIES)
FIGURES += _single.FIGURES

from tools.docnumbers import figures_mc as _mc  # noqa: E402

QUANTITIES.update(_mc.QUANTITIES)
FIGURES += _mc.FIGURES

from tools.docnumbers import figures_deorbit as _deorbit  # noqa: E402

QUANTITIES.update(_deorbit.QUANTITIES)
FIGURES += _deorbit.FIGURES

from tools.docnumbers import figures_atlas_real as _atlas_real  # noqa: E402

QUANTITIES.update(_atlas_real.QUANTITIES)
FIGURES += _atlas_real.FIGURES

from tools.docnumbers import figures_deploy as _deploy  # noqa: E402

QUANTITIES.update(_deploy.QUANTITIES)
FIGURES += _deploy.FIGURES
