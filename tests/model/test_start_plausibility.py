"""Absurd starts and balloons are refused as implausible, naming the field and the bound
(docs/limits.md): starting rates against the orbit rate, the balloon's starting distance
(δz included) and speed against the tether geometry, its area per mass against the
thinnest balloon films.  ``allow_implausible`` still runs them, and the presets pass."""
from __future__ import annotations

import math

import pytest

from tethersim import load_preset
from tethersim.model.plausibility import MAX_AREA_PER_MASS, RATE_FACTOR, REACH_FACTOR
from tethersim.model.satellite import SatelliteError

SAT = load_preset("satI")
W = RATE_FACTOR * SAT.omega  # the rate bound, from the orbit rate
REACH = REACH_FACTOR * max(SAT.l10 + SAT.b, SAT.l20 + SAT.a)
V = W * REACH


def _initial(**kw):
    names = ("delta_x", "delta_y", "theta", "delta_x_dot", "delta_y_dot", "theta_dot")
    return tuple(kw.get(n, v) for n, v in zip(names, SAT.initial))


CASES = {
    "theta_dot 1e3": (dict(initial=_initial(theta_dot=1e3)), "theta_dot"),
    "theta_dot just over": (dict(initial=_initial(theta_dot=-1.01 * W)), "theta_dot"),
    "delta_x_dot orbital": (dict(initial=_initial(delta_x_dot=7800.0)), "delta_x_dot"),
    "delta_y_dot just over": (dict(initial=_initial(delta_y_dot=1.01 * V)), "delta_x_dot"),
    "psi_dot 1000": (dict(initial_3d={"psi_dot": 1000.0}), "psi_dot"),
    "phi_dot just over": (dict(initial_3d={"phi_dot": 1.01 * W}), "phi_dot"),
    "delta_z_dot": (dict(initial_3d={"delta_z_dot": 1.01 * V}), "delta_z_dot"),
    "delta_z 10 km": (dict(initial_3d={"delta_z": 1e4}), "delta_z"),
    "balloon 1 g, 1e4 m^2": (dict(m3=0.001, A3=1e4), "A3 / m3"),
    "area per mass just over": (dict(A3=1.01 * MAX_AREA_PER_MASS * SAT.m3), "A3 / m3"),
}


@pytest.mark.parametrize("change, field", CASES.values(), ids=CASES.keys())
def test_implausible_start_is_refused_naming_the_field(change, field):
    with pytest.raises(SatelliteError) as err:
        SAT.replace(**change)
    line = str(err.value)
    assert "\n" not in line and field in line and "plausible range" in line, line
    allowed = SAT.replace(allow_implausible=True, **change)  # knowingly: it runs
    assert any(field in p for p in allowed.implausible)


def test_starts_at_the_bounds_are_plausible():
    SAT.replace(initial=_initial(theta_dot=0.99 * W, delta_x_dot=0.99 * V))
    SAT.replace(initial_3d={"psi_dot": -0.99 * W, "delta_z": 0.5 * REACH})
    SAT.replace(A3=0.99 * MAX_AREA_PER_MASS * SAT.m3)


@pytest.mark.parametrize("name", ["satI", "satII", "dumbsat"])
def test_presets_are_far_inside_the_bounds(name):
    sat = load_preset(name)
    assert sat.implausible == ()
    assert abs(sat.initial[5]) < W / 10 and math.hypot(*sat.initial[3:5]) < V / 10
    assert sat.A3 / sat.m3 < MAX_AREA_PER_MASS / 2


def test_docs_state_the_bounds():
    from pathlib import Path
    doc = (Path(__file__).parents[2] / "docs" / "limits.md").read_text()
    assert f"{RATE_FACTOR:g} × the orbit rate" in doc
    assert f"A3 / m3 ≤ {MAX_AREA_PER_MASS:g} m²/kg" in doc
    assert f"~{RATE_FACTOR / math.sqrt(3):.0f} × √3 n" in doc  # the rate bound over libration
