"""The evaluation loops called from Python: same numbers as the kernels, no compile per call."""
from __future__ import annotations

import numpy as np
import pytest
from numba.core import event

import tethersim as ts
from tethersim.engine.evaluate import (
    family_force_peaks,
    family_forces_series,
    jacobi_series,
    tether_margin_series,
)


class _Compiles(event.Listener):
    def __init__(self):
        self.count = 0

    def on_start(self, ev):
        self.count += 1

    def on_end(self, ev):
        pass


def test_force_peaks_are_the_largest_family_force_of_the_series():
    res = ts.simulate(ts.load_preset("satI"), periods=1, progress=False)
    m, air, p = res.layout.index, res.air, res.parameters
    Q = family_forces_series(m, air, res.t, res.states, p)
    np.testing.assert_array_equal(family_force_peaks(m, air, res.t, res.states, p),
                                  np.abs(Q).max(axis=(0, 1)))
    assert tether_margin_series(m, res.states, p).shape == (res.t.size, 2)
    assert np.all(np.isfinite(jacobi_series(m, res.states, p)))


def test_a_python_call_does_not_go_through_numbas_compiler():
    # a literal model index sent through numba's dispatcher retries its type inference on
    # every call (milliseconds); the loop is picked once, then called directly
    res = ts.simulate(ts.load_preset("satI"), periods=0.2, progress=False)
    args = (res.layout.index, res.air, res.t, res.states, res.parameters)
    family_force_peaks(*args)
    tether_margin_series(res.layout.index, res.states, res.parameters)
    listener = _Compiles()
    with event.install_listener("numba:compile", listener):
        for _ in range(3):
            family_force_peaks(*args)
            tether_margin_series(res.layout.index, res.states, res.parameters)
    assert listener.count == 0


@pytest.mark.parametrize("seed", range(4))
def test_domain_scan_finds_the_first_over_stretched_sample_as_the_full_margins_do(seed):
    """The scan skips the tether lengths where the balloon is too close for any stretch
    beyond the limit (|λ_j| <= d + end_j); the sample and value it finds must be those of
    the margins evaluated everywhere."""
    from tethersim.engine.domain import MAX_STRETCH
    from tethersim.engine.evaluate import domain_scan, tether_margin_series
    from tethersim.model.inputs import parameter_vector
    sat = ts.load_preset("satI")
    p = parameter_vector(sat, "derived")
    rng = np.random.default_rng(seed)
    n = 4000
    Y = np.zeros((n, 10))
    # the balloon wandering out to ~1.2x the stretch limit of the 6 m tethers
    radius = np.linspace(1.0, 1.2 * MAX_STRETCH * 6.0, n) * rng.uniform(0.9, 1.0, n)
    ang = rng.uniform(-np.pi, np.pi, n)
    Y[:, 0], Y[:, 1], Y[:, 2] = radius * np.cos(ang), radius * np.sin(ang), rng.uniform(-1, 1, n)
    g = tether_margin_series(0, Y, p)
    strain = np.column_stack([g[:, 0] / sat.l10, g[:, 1] / sat.l20]) + 1.0
    over = np.nonzero(np.any(strain > MAX_STRETCH, axis=1))[0]
    _, _, _, i_over, j_over, s_over = domain_scan(0, Y, p, 0, 1, -1, sat.l10, sat.l20, sat.a,
                                                  sat.b, 1e30, MAX_STRETCH)
    assert over.size and i_over == over[0]
    assert (j_over, s_over) == (int(np.argmax(strain[i_over])), strain[i_over].max())
