"""Figures of the moduli cases (headlines.md, torque-balance.md) and the band (sweeps.md)."""
from __future__ import annotations

from tools.docnumbers import quantities as q
from tools.docnumbers.check import Figure

H, TB, SW = "docs/headlines.md", "docs/torque-balance.md", "docs/sweeps.md"
CASES = (("E1-10%", 0.9, 1.0), ("E1+10%", 1.1, 1.0), ("E2-10%", 1.0, 0.9), ("E2+10%", 1.0, 1.1))


def _eq(factor, E1, E2, guess):
    s = q.sat(factor=factor, E1=E1, E2=E2)
    return q._eq(s, "derived", (s.initial[0], s.initial[1], guess))


def _eq_theta(factor, E1, E2, guess):
    return _eq(factor, E1, E2, guess).theta


def _band_slope():
    """dθ_eq/dE2 at SatI's preset, per 0.001 N/mm² of E2 (a central difference)."""
    d = 0.001
    return (_eq_theta(1.0, 1.0, 1 + d, 0.0) - _eq_theta(1.0, 1.0, 1 - d, 0.0)) \
        / (2 * d * q.edge_value(q.sat(), "E2")) * 0.001


def _damped(E1, E2):
    """θ_ss of a 50-orbit adaptive run with nominal damping and scaled moduli."""
    from tethersim.analysis.outcome import outcome
    from tethersim.engine.simulate import simulate

    res = simulate(q.sat(E1=E1, E2=E2), 50.0, progress=False)
    return outcome(res, forces=False).metrics.steady_state_pitch


QUANTITIES = {
    "eq_E1+10%": lambda: _eq_theta(0.0, 1.1, 1.0, 0.65),
    "eq_E2-10%": lambda: _eq_theta(0.0, 1.0, 0.9, 0.8),
    "eq_E2+10%_a": lambda: _eq_theta(0.0, 1.0, 1.1, -1.15),
    "eq_E2+10%_b": lambda: _eq_theta(0.0, 1.0, 1.1, -2.0),
    "tb_E1x0.9": lambda: _eq_theta(1.0, 0.9, 1.0, -1.5),
    "tb_E1x1.1": lambda: _eq_theta(1.0, 1.1, 1.0, 0.65),
    "tb_E1x1.2": lambda: _eq_theta(1.0, 1.2, 1.0, 1.1),
    "band_slope": _band_slope,
    "hl_e150_max": lambda: q.headline("E1+50%")["theta_max"],
}
_ROW_EQ = "| centre of the oscillation (equilibrium) [rad] |"
FIGURES = [
    Figure(H, (_ROW_EQ, "| "), "eq_E1+10%"),
    Figure(H, (_ROW_EQ, "| ", "| "), "eq_E2-10%"),
    Figure(H, (_ROW_EQ, "mirror pair "), "eq_E2+10%_a"),
    Figure(H, (_ROW_EQ, "mirror pair ", " and "), "eq_E2+10%_b"),
    Figure(TB, ("At fixed E2, θ_eq = ",), "tb_E1x0.9"),
    Figure(TB, ("At fixed E2, θ_eq = ", "× 0.9, "), "tb_E1x1.1"),
    Figure(TB, ("At fixed E2, θ_eq = ", "× 1.1, "), "tb_E1x1.2"),
    Figure(SW, ("the steady pitch changes by about ",), "band_slope", absolute=True),
    Figure(H, ("**exactly 5π/6** (",), "hl_e150_max", slow=True),
]
_ROW_RANGE = "| range [rad] |"
_ROW_DAMPED = "| with nominal damping, 50 orbits: θ_ss [rad] |"
for _i, (_c, _e1, _e2) in enumerate(CASES):
    QUANTITIES[f"hl_min_{_c}"] = (lambda c: lambda: q.headline(c)["theta_min"])(_c)
    QUANTITIES[f"hl_max_{_c}"] = (lambda c: lambda: q.headline(c)["theta_max"])(_c)
    QUANTITIES[f"damped_{_c}"] = (lambda a, b: lambda: _damped(a, b))(_e1, _e2)
    FIGURES.append(Figure(H, (_ROW_RANGE,) + ("[",) * (_i + 1), f"hl_min_{_c}", slow=True))
    FIGURES.append(Figure(H, (_ROW_RANGE,) + ("[",) * (_i + 1) + (", ",), f"hl_max_{_c}",
                          slow=True))
    FIGURES.append(Figure(H, (_ROW_DAMPED,) + ("| ",) * _i, f"damped_{_c}", slow=True))
