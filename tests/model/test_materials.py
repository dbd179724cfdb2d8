"""Tether materials: closed forms of a round line, the damping ratio a loss factor means,
the docs' table equal to the code's, one-line refusals."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from tethersim.model.materials import GPA, MATERIALS, material, tether_parameters

DOC = Path(__file__).parents[2] / "docs" / "tethers.md"


def test_a_round_line_has_area_pi_d2_over_4():
    d, l0, m = 1e-3, 6.0, 1.5
    t = tether_parameters("kevlar49", d, l0, m)
    area = math.pi * d * d / 4
    assert t["EA"] == pytest.approx(112e9 * area, rel=1e-15)
    assert t["breaking_load"] == pytest.approx(3.0e9 * area, rel=1e-15)
    assert t["mass_per_length"] == pytest.approx(1440 * area, rel=1e-15)
    # a mass on a spring k = EA / l0
    assert t["axial_period"] == pytest.approx(2 * math.pi / math.sqrt(t["EA"] / l0 / m), rel=1e-14)


@pytest.mark.parametrize("eta", [0.0, 0.01, 0.05])
def test_the_damping_ratio_is_half_the_loss_factor(eta):
    l0, m = 30.0, 1.2
    t = tether_parameters("dyneema-sk75", 2e-3, l0, m, loss_factor=eta)
    k = t["EA"] / l0
    assert t["c"] / (2 * math.sqrt(k * m)) == pytest.approx(eta / 2, rel=1e-14, abs=0)


def test_a_knockdown_scales_stiffness_and_strength_alike():
    full = tether_parameters("vectran-ht", 1e-3, 6.0, 1.0)
    braided = tether_parameters("vectran-ht", 1e-3, 6.0, 1.0, knockdown=0.6)
    assert braided["EA"] == pytest.approx(0.6 * full["EA"], rel=1e-15)
    assert braided["breaking_load"] == pytest.approx(0.6 * full["breaking_load"], rel=1e-15)
    assert braided["mass_per_length"] == full["mass_per_length"]


def test_the_docs_table_is_the_codes_table():
    rows = re.findall(r"^\| `([\w-]+)` \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| (.+) \|$",
                      DOC.read_text(), flags=re.M)
    assert [r[0] for r in rows] == list(MATERIALS)
    for name, e, s, rho, source in rows:
        m = MATERIALS[name]
        assert (float(e), float(s), float(rho), source) == (m.E / GPA, m.strength / GPA,
                                                            m.density, m.source)


@pytest.mark.parametrize("call, field", [
    (lambda: material("steel"), "material 'steel': allowed kevlar49"),
    (lambda: tether_parameters("kevlar49", 0.5, 6.0, 1.0), "diameter = 0.5: allowed range"),
    (lambda: tether_parameters("kevlar49", 1e-3, 6.0, 1.0, knockdown=2), "knockdown = 2"),
    (lambda: tether_parameters("kevlar49", 1e-3, -6.0, 1.0), "l0 = -6.0: must be"),
    (lambda: tether_parameters("kevlar49", 1e-3, 6.0, math.nan), "mass = nan: must be"),
    (lambda: tether_parameters("kevlar49", 1e-3, 6.0, 1.0, loss_factor=3), "loss_factor = 3"),
])
def test_bad_tether_input_is_refused_in_one_line_naming_the_field(call, field):
    with pytest.raises(ValueError) as e:
        call()
    assert field in str(e.value) and "\n" not in str(e.value)


def test_the_docs_figures_are_computed_ones():
    import tethersim as ts
    text = DOC.read_text()
    ea = float(re.search(r"1 mm Kevlar 49 line, EA ≈ ([\d.e+]+) N", text).group(1))
    assert ea == float(f"{tether_parameters('kevlar49', 1e-3, 6.0, 1.0)['EA']:.2g}")
    lo, hi = map(float, re.search(r"are moduli of (\d+) and (\d+) kPa", text).groups())
    sat = ts.load_preset("satI")
    moduli = sorted(e / 1e-6 / 1e3 for e in (sat.E1, sat.E2))  # E·1 mm² [N] -> kPa
    assert (lo, hi) == (round(moduli[0]), round(moduli[1]))
