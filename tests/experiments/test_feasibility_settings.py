"""The feasibility atlas sets the orbit and the air of every point itself: a satellite
that sets one of those fields is refused (naming it), the other fields are used."""
from __future__ import annotations

import pytest

from tethersim import load_preset
from tethersim.experiments.feasibility import ATLAS_FIELDS, FeasibilitySpec

SAT = load_preset("satI")
SET_BY_ATLAS = [dict(density_scale=3.0), dict(orbit="free"), dict(atmosphere="nrlmsise00"),
                dict(density_mode="per-body"), dict(epoch="2018-01-01T00:00:00")]


@pytest.mark.parametrize("change", SET_BY_ATLAS, ids=lambda c: next(iter(c)))
def test_a_field_the_atlas_sets_is_refused_naming_it(change):
    sat = SAT.replace(**change)
    field = next(iter(change))
    with pytest.raises(ValueError) as err:
        FeasibilitySpec(sat, (200.0,), solar=("min",), periods=0.1, max_lifetime_h=0.1)
    line = str(err.value)
    assert "\n" not in line and "atlas sets" in line
    assert ("density" if field == "density_mode" else field) in line


def test_every_atlas_field_is_a_satellite_field():
    assert all(hasattr(SAT, f) for f in ATLAS_FIELDS)


def test_the_other_fields_reach_every_run_of_a_point():
    sat = SAT.replace(CD=1.5, E1=SAT.E1 * 2)
    spec = FeasibilitySpec(sat, (200.0,), solar=("min",), periods=0.1, max_lifetime_h=0.1)
    for run in (spec.circular(200.0, sat.A3), spec.free(200.0, sat.A3),
                spec.free(200.0, sat.A3, "min")):
        assert (run.CD, run.E1) == (1.5, SAT.E1 * 2)
