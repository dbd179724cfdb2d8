"""The air the compiled loop reads (model/air/vector.py through engine/dynamics.py).

Truths: pymsis's own NRLMSISE-00 value (``tethersim.air_density``, no grid) at each
body's inertial position from the independent kinematics of ``tethersim.bodies``,
and Vallado's table; the grid's interpolation bound is 0.5 % (tests/model/test_air_grid.py).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.engine.dynamics import parameters_at
from tethersim.model.air.grid import gmst
from tethersim.model.air.vector import MSIS, UNIFORM, VALLADO
from tethersim.model.constants import OMEGA_EARTH, R_EARTH
from tethersim.model.inputs import air_vector, parameter_vector
from tethersim.model.registry import get_model

SAT = ts.load_preset("satI")
MSIS_SAT = SAT.replace(density_mode="per-body", atmosphere="nrlmsise00",
                       epoch="2017-06-23T05:17:00", f107=150.0, f107a=150.0, ap=4.0)
GRID_REL = 5e-3  # the grid's bound (docs/air.md)
# a state with the balloon off to one side and the boom pitched
STATE = np.array([29.0, -3.0, 0.4, 0.01, 0.0, 1e-4])


def _loop_densities(sat, t, state, model="derived"):
    m = get_model(model)
    p = parameters_at(m.index, t, np.ascontiguousarray(state), parameter_vector(sat, model),
                      air_vector(sat, t))
    return np.array([p[m.parameters.index(n)] for n in ("rho1", "rho2", "rho3")])


def _pymsis_at_bodies(sat, t, state, model="derived"):
    pos = ts.bodies(sat, state, t=t, model=model).position
    theta0 = gmst(np.datetime64(sat.epoch))
    out = []
    for x, y, _ in pos:
        lon = math.atan2(y, x) - theta0 - OMEGA_EARTH * t
        out.append(ts.air_density(sat, math.hypot(x, y) - R_EARTH, t, lon))
    return np.array(out)


@pytest.mark.parametrize("t", [0.0, 2000.0, 40000.0, 100000.0])
def test_msis_per_body_densities_are_pymsis_at_each_body(t):
    loop = _loop_densities(MSIS_SAT, t, STATE)
    direct = _pymsis_at_bodies(MSIS_SAT, t, STATE)
    assert np.all(np.abs(loop / direct - 1) <= GRID_REL), (loop, direct)
    # and the three bodies do see different air (10.5 m up, 1 m down, the balloon behind)
    assert len(set(loop)) == 3


def test_msis_per_body_follows_the_day_night_cycle():
    """Half an orbit later the COM is on the other side of the Earth: the density
    changes by the diurnal swing, as pymsis says (not a uniform value)."""
    half = SAT.period / 2
    a, b = (_loop_densities(MSIS_SAT, t, STATE)[0] for t in (0.0, half))
    pa, pb = (_pymsis_at_bodies(MSIS_SAT, t, STATE)[0] for t in (0.0, half))
    assert abs(math.log(a / b)) > 0.1
    assert a / b == pytest.approx(pa / pb, rel=2 * GRID_REL)


def test_vallado_per_body_densities_are_the_table_at_each_body():
    sat = SAT.replace(density_mode="per-body")
    loop = _loop_densities(sat, 1234.0, STATE)
    pos = ts.bodies(sat, STATE, t=1234.0).position
    table = [ts.air_density(sat, math.hypot(x, y) - R_EARTH) for x, y, _ in pos]
    assert loop == pytest.approx(table, rel=1e-13)


def test_density_scale_multiplies_every_per_body_density():
    for sat in (SAT.replace(density_mode="per-body"), MSIS_SAT):
        base = _loop_densities(sat, 500.0, STATE)
        scaled = _loop_densities(sat.replace(density_scale=1.7), 500.0, STATE)
        assert scaled == pytest.approx(1.7 * base, rel=1e-14)


def test_air_vector_modes_and_grid_days():
    assert air_vector(SAT, 1e5)[0] == UNIFORM
    assert air_vector(SAT.replace(density_mode="per-body"), 1e5)[0] == VALLADO
    one, three = air_vector(MSIS_SAT, 3600.0), air_vector(MSIS_SAT, 2.5 * 86400.0)
    assert one[0] == three[0] == MSIS
    assert three.size > 2.5 * one.size  # one grid block per UTC day of the run
    assert not one.flags.writeable


def test_uniform_mode_reads_the_parameter_vector():
    loop = _loop_densities(SAT, 777.0, STATE)
    assert loop == pytest.approx([SAT.rho] * 3, rel=0)


def test_msis_run_is_a_per_body_run_with_other_air():
    """A short per-body MSIS run ends ok and differs from Vallado's by the density ratio's
    effect only (same model, same steps taken otherwise)."""
    a = ts.simulate(MSIS_SAT, periods=0.2, progress=False)
    b = ts.simulate(MSIS_SAT.replace(atmosphere="vallado", f107=None, f107a=None, ap=None),
                    periods=0.2, progress=False)
    assert a.status == b.status == "ok"
    assert not np.array_equal(a.states[-1], b.states[-1])
    assert "NRLMSISE-00 at each body" in ts.run_summary(a)["air density"]
