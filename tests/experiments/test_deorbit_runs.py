"""Trail or hang: the closed form against coupled runs of a towed line (docs/deorbit.md)."""
import math

import pytest

import tethersim as ts
from tethersim.analysis import deorbit as law
from tethersim.experiments.deorbit_runs import coupled_runs, towed_line
from tethersim.model.options import uniform_density

SAT = ts.load_preset("satI")


@pytest.mark.slow  # compiles the objective-damper kernels (~20 s cold), then 3 x 6 orbits
def test_trail_angle_of_a_towed_line_matches_the_closed_form():
    # start 5 deg short of the closed form's angle: if the closed form were off, the balloon
    # would librate about the true equilibrium and its mean would show it
    heights = (540e3, 650e3, 900e3)
    runs = []
    for h in heights:
        s = SAT.replace(altitude=h)
        phi = law.trail_angle(s, uniform_density(s), 100.0 + SAT.a)
        runs += coupled_runs(towed_line(SAT, 100.0, phi - math.radians(5)), [h], periods=6)
    for r in runs:
        assert r["status"] == "ok"
        assert 0.005 < r["epsilon"] < 0.7  # all three hang
        assert math.degrees(abs(r["trail_angle"] - r["closed_form_angle"])) < 1.5
    # the tilt grows with the air: lower hangs further from the vertical
    assert runs[0]["trail_angle"] > runs[1]["trail_angle"] > runs[2]["trail_angle"]
    # below the epsilon = 1 altitude it trails level behind
    (low,) = coupled_runs(towed_line(SAT, 100.0, math.radians(85)), [500e3], periods=6)
    assert low["epsilon"] > 1 and abs(math.degrees(low["trail_angle"]) - 90) < 5


def test_loads_and_rates_of_a_coupled_run_are_reported():
    (r,) = coupled_runs(SAT, [200e3], periods=2, model="derived")
    assert r["status"] == "ok"
    # SatI at 200 km trails (epsilon >> 1): level behind, the line pulled by the drag
    assert r["epsilon"] > 1 and math.degrees(r["trail_angle"]) > 80
    assert r["peak_tension_2"] > 0 and r["max_rate"] >= r["settled_rate"] > 0
