"""tethersim.engine.jacobian: the generated Jacobian where there is one, else central differences.

The central differences of a planar model's generated rhs against its generated
analytic Jacobian (an independent computation: sympy's derivative of the same
equations), at the presets' starts and at their equilibria.
"""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tests.messages import one_line
from tests.tiers import models
from tethersim.engine.integrators.select import call
from tethersim.engine.jacobian import _jacobian, analytic, central_differences, jacobian
from tethersim.model.inputs import initial_model_state, parameter_vector
from tethersim.model.registry import BY_NAME, KERNELS, MODELS, THESIS_VARIANTS


def _states(preset, model):
    sat = ts.load_preset(preset)
    eq = ts.find_equilibrium(sat, model)
    return sat, (initial_model_state(sat, model), np.asarray(eq.state, float))


@pytest.mark.parametrize("preset", ("satI", "satII"))
@pytest.mark.parametrize("model", models(*THESIS_VARIANTS))
def test_central_differences_equal_the_generated_jacobian(preset, model):
    """Within 1e-9 of the largest entry (the documented error is ~ε^(2/3) ≈ 4e-11 of it).
    The variants' compiled differences (4 s of compile each) run in the slow tier
    (tests/tiers.py)."""
    sat, states = _states(preset, model)
    m = BY_NAME[model].index
    p = parameter_vector(sat, model)
    for y in states:
        J, F = np.empty((6, 6)), np.empty((6, 6))
        KERNELS[m].jacobian(0.0, y, p, J)
        central_differences(m, 0.0, y, p, F)
        assert np.max(np.abs(F - J)) <= 1e-9 * np.max(np.abs(J))


def test_jacobian_is_the_generated_one_where_derive_printed_it():
    sat = ts.load_preset("satI")
    for model in THESIS_VARIANTS:
        m = BY_NAME[model].index
        assert analytic(m)
        y, p = initial_model_state(sat, model), parameter_vector(sat, model)
        J, G = np.empty((6, 6)), np.empty((6, 6))
        jacobian(m, 0.0, y, p, J)
        KERNELS[m].jacobian(0.0, y, p, G)
        assert np.array_equal(J, G)
    # compiled callers (model_jacobian: the implicit scheme's route) get the same
    m = BY_NAME["derived"].index
    y, p = initial_model_state(sat, "derived"), parameter_vector(sat, "derived")
    J, G = np.empty((6, 6)), np.empty((6, 6))
    call(_jacobian, m, 0.0, y, p, J)
    KERNELS[m].jacobian(0.0, y, p, G)
    assert np.array_equal(J, G)


def test_only_the_planar_circular_models_carry_a_generated_jacobian():
    assert {m.name for m in MODELS if analytic(m.index)} == set(THESIS_VARIANTS)


def test_a_state_of_the_wrong_size_is_refused_in_one_line():
    sat = ts.load_preset("satI")
    p = parameter_vector(sat, "derived")
    with pytest.raises(ValueError) as err:
        jacobian(BY_NAME["derived"].index, 0.0, np.zeros(5), p, np.empty((6, 6)))
    line = one_line(str(err.value))
    assert "y has shape (5,)" in line and "'derived' needs (6,) and (6, 6)" in line
