"""The evaluation loops called from Python: same numbers as the kernels, no compile per call."""
from __future__ import annotations

import numpy as np
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
