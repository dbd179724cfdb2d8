"""A tether breaks when its spring tension reaches its breaking load (Satellite.Fb1, Fb2):
a stopping event located in the loop like the others (engine/events.py)."""
from __future__ import annotations

import tomllib

import numpy as np
import pytest

import tethersim as ts
from tests.engine.test_events import LOCATED, _ivp_root
from tethersim.engine.events import SLOT, event_parameters, events_at
from tethersim.model.presets import from_dict
from tethersim.model.presets.write import dumps

SAT = ts.load_preset("satI")
# 115 km (allowed knowingly): the dense air blows the balloon outwards, its tethers'
# tensions rise for seconds before any stretch limit (tests/engine/test_events.py)
BLOWN = SAT.replace(altitude=115e3, allow_implausible=True)


def _tensions(sat, y):
    """The springs' tensions E_j (λ_j − l_j0) / l_j0 at state y (Eqs 3.35-3.36), from the
    tether margins λ_j − l_j0 the event vector carries in its first two slots."""
    g = events_at(0, y, ts.simulate(sat, 1e-4, progress=False).parameters,
                  event_parameters(sat, "derived"))
    return np.array([sat.E1 * g[0] / sat.l10, sat.E2 * g[1] / sat.l20])


def test_a_tether_breaks_at_its_breaking_load_located_to_a_microsecond():
    t0 = _tensions(BLOWN, ts.simulate(BLOWN, 1e-4, progress=False).states[0])
    sat = BLOWN.replace(Fb1=2 * t0.max(), Fb2=2 * t0.max())
    res = ts.simulate(sat, periods=0.05, rtol=1e-13, atol=1e-14, progress=False)
    assert res.status == "tether-broke" and res.event in ("tether 1 break", "tether 2 break")
    j = int(res.event[7]) - 1
    assert f"tether {j + 1} broke" in res.message and "Fb" in res.message
    # the tension at the located state is the breaking load, to the location's accuracy
    assert _tensions(sat, res.states[-1])[j] == pytest.approx((sat.Fb1, sat.Fb2)[j], rel=1e-6)
    assert abs(res.event_time - _ivp_root(res, SLOT[res.event])) <= LOCATED


def test_an_unbreakable_tether_never_breaks_and_changes_no_step():
    with_limit = ts.simulate(SAT.replace(Fb1=1e6, Fb2=1e6), periods=1, progress=False)
    without = ts.simulate(SAT, periods=1, progress=False)
    assert with_limit.status == without.status == "ok"
    np.testing.assert_array_equal(with_limit.states, without.states)


def test_a_start_beyond_the_breaking_load_is_refused_before_any_step():
    """Issue 21 item 4: such a start is no physical state (the line would have broken
    before t = 0): refused in one line that points at the equilibrium start."""
    t0 = _tensions(SAT, ts.simulate(SAT, 1e-4, progress=False).states[0])
    with pytest.raises(ValueError, match=r"tether 2 starts stretched to .* at or beyond its "
                                         r"breaking load Fb2 = .*--start equilibrium"):
        ts.simulate(SAT.replace(Fb2=0.5 * t0[1]), periods=0.1, progress=False)


def test_a_breaking_load_survives_a_preset_round_trip_and_zero_is_unbreakable():
    sat = SAT.replace(Fb1=2356.2, Fb2=1000.0)
    again = from_dict(tomllib.loads(dumps(sat)))
    assert (again.Fb1, again.Fb2) == (2356.2, 1000.0)
    assert "Fb1" not in dumps(SAT)  # the thesis's tethers: no key written
    with pytest.raises(ts.SatelliteError, match=r"Fb1 = -1.0 N: must be >= 0"):
        SAT.replace(Fb1=-1.0)


def test_the_material_table_gives_the_breaking_load():
    t = ts.tether_parameters("kevlar49", 1e-3, 30.0, 1.0)
    sat = SAT.replace(E1=t["EA"], Fb1=t["breaking_load"], l10=30.83, l20=28.92)
    # Kevlar 49 breaks at 3.0 GPa / 112 GPa = 2.7 % strain: the extension at the break slot
    ev = event_parameters(sat, "derived")
    assert ev[7] == pytest.approx(sat.l10 * 3.0 / 112, rel=1e-12)
