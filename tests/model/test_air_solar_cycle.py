"""Solar-cycle densities against the published figures (docs/sources.md).

At 200 km NRLMSISE-00 gives about 2.0, 3.2 and 4.6e-10 kg/m^3 for F10.7 = 70,
150, 250 (Ap 4, daytime equator); Vallado's table gives 2.79e-10.  The published
values carry two digits and state neither season nor local time; at 14 h local
time the June solstice is 20 % below the March equinox (F10.7 150: 2.55 vs
3.22e-10).  We evaluate at the March equinox, 14 h local time, and allow 10 %:
the largest difference is 8.5 % (solar minimum, 2.17 vs 2.0), within that
rounding-plus-season spread, while a wrong index (e.g. F10.7a swapped for Ap) or
a unit slip (km vs m) is off by far more.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tethersim.model import atmosphere
from tethersim.model.air import solar_cycle_densities
from tethersim.model.air.check import PUBLISHED_200KM, solar_cycle_table

PUBLISHED_REL = 0.10
DOCS = Path(__file__).resolve().parents[2] / "docs" / "air.md"


@pytest.fixture(scope="module")
def at_200km():
    return solar_cycle_densities(200e3)


@pytest.mark.parametrize("setting", ["min", "mean", "max"])
def test_matches_published_nrlmsise00(at_200km, setting):
    assert at_200km[setting] == pytest.approx(PUBLISHED_200KM[setting], rel=PUBLISHED_REL)


def test_vallado_lies_inside_the_cycle(at_200km):
    vallado = atmosphere.density(200e3)
    assert at_200km["min"] < vallado < at_200km["max"]
    assert at_200km["min"] < at_200km["mean"] < at_200km["max"]


def test_docs_table_is_computed():
    """docs/air.md carries solar_cycle_table(200 km) verbatim (no hand-typed numbers)."""
    assert solar_cycle_table(200e3) in DOCS.read_text()
