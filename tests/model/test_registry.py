"""The model registry (tethersim/model/registry.py): free twins from the generated modules."""
from __future__ import annotations

import pytest

import tethersim.generated as generated
from tethersim.model.registry import BY_NAME, FREE_VARIANTS, MODELS, model_for_orbit


def test_every_free_model_names_a_circular_twin_of_its_own_geometry():
    free = [m for m in MODELS if m.orbit == "free"]
    assert {m.name for m in free} == set(FREE_VARIANTS.values())
    for m in free:
        twin = BY_NAME[m.module.CIRCULAR_TWIN]
        assert twin.orbit == "circular" and twin.geometry == m.geometry
        # the twin's state is the free model's without r, ν; its parameters without r0, ω
        assert tuple(n for n in m.state if n not in ("r", "nu", "r_dot", "nu_dot")) == twin.state
        assert set(twin.parameters) - {"r0", "omega"} <= set(m.parameters)
        assert FREE_VARIANTS[twin.name] == m.name
    assert all(not hasattr(m, "CIRCULAR_TWIN") for n, m in generated.MODELS.items()
               if BY_NAME[n].orbit == "circular")


@pytest.mark.parametrize("name, twin", [("derived", "free"), ("exact-gravity", "free-exact-gravity"),
                                        ("objective-damper", "free-objective-damper"),
                                        ("3d", "3d-free"), ("3d-objective-damper",
                                                            "3d-free-objective-damper")])
def test_model_for_orbit_gives_the_free_twin(name, twin):
    assert model_for_orbit(name, "free") == twin
    assert model_for_orbit(name, "circular") == name
    assert model_for_orbit(twin, "free") == twin


@pytest.mark.parametrize("name", ["printed", "3d-exact-gravity"])
def test_a_model_without_a_free_twin_is_refused(name):
    with pytest.raises(ValueError, match=rf"^model = '{name}' has no free-orbit variant"):
        model_for_orbit(name, "free")
