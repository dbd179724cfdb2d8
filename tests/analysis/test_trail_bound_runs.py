"""The trail bound against simulations: the decay it predicts, the settling it allows."""
from __future__ import annotations

import pytest

import tethersim as ts
from tethersim.analysis.free_orbit import osculating_elements
from tethersim.analysis.outcome import outcome
from tethersim.analysis.trail_bound import decay_life, decay_rate, trail_bound

SAT = ts.load_preset("satI")


@pytest.mark.slow
def test_the_decay_rate_is_a_free_orbits_over_one_orbit():
    """ȧ of the bound's formula against the osculating semi-major axis of a free run in
    air of one density (so the rate is constant)."""
    res = ts.simulate(SAT.replace(orbit="free", density_mode="uniform"), 1.0, rtol=1e-10,
                      progress=False)
    a, _ = osculating_elements(res)
    measured = (a[-1] - a[0]) / (res.t[-1] - res.t[0])
    assert measured == pytest.approx(-decay_rate(SAT, SAT.rho), rel=0.01)


@pytest.mark.slow
@pytest.mark.parametrize("stiffer", [1.0, 10.0])
def test_a_free_runs_usable_life_stays_within_the_decay_estimate(stiffer):
    """Balloon lost (soft tethers) or nearly re-entered (stiffer ones): never more than 20 %
    past the quasi-circular decay time of the same drag."""
    sat = SAT.replace(orbit="free", density_mode="per-body", E1=SAT.E1 * stiffer,
                      E2=SAT.E2 * stiffer)
    res = ts.simulate(sat, 20.0, rtol=1e-9, progress=False)
    assert res.status in ("left-domain", "re-entered")
    assert res.t[-1] <= 1.2 * decay_life(sat)


@pytest.mark.parametrize("c", [0.003, 0.03])
def test_a_simulated_settling_is_never_faster_than_the_bound_allows(c):
    sat = SAT.replace(c1=c, c2=c)
    out = outcome(ts.simulate(sat, 10.0, rtol=1e-9, progress=False), forces=False)
    settle = out.metrics.settling_time
    assert settle > 0  # the start (30 deg) is outside the band: a real test of the bound
    b = trail_bound(sat, abs(complex(out.trail_delta_x, out.trail_delta_y)), 0.05)
    assert 0 < b.settle_min <= settle
