"""The generated Jacobian equals central finite differences of the generated rhs."""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tethersim.model.inputs import parameter_vector
from tethersim.model.registry import KERNELS, THESIS_VARIANTS, model_index


def _fd_jacobian(m, y, p):
    J = np.empty((6, 6))
    a, b = np.empty(6), np.empty(6)
    for i in range(6):
        d = 1e-6 * max(1.0, abs(y[i]))
        e = np.zeros(6)
        e[i] = d
        KERNELS[m].rhs(0.0, y + e, p, a)
        KERNELS[m].rhs(0.0, y - e, p, b)
        J[:, i] = (a - b) / (2 * d)
    return J


STATES = {
    "both taut": [20.0, 1.0, 0.3, 0.01, -0.02, 1e-3],
    "tether 2 slack": [4.0, 0.2, 0.3, 0.01, -0.02, 1e-3],
    "both slack": [0.5, 0.5, 2.0, 0.0, 0.1, -1e-3],
}


@pytest.mark.parametrize("model", THESIS_VARIANTS)  # 6-state models; every model: test_contract_symbolic
@pytest.mark.parametrize("case", STATES)
@pytest.mark.parametrize("preset", ["satI", "dumbsat"])
def test_generated_jacobian_matches_finite_differences(model, case, preset):
    sat = ts.load_preset(preset)
    p = parameter_vector(sat, model)
    y = np.array(STATES[case])
    m = model_index(model)
    J = np.empty((6, 6))
    KERNELS[m].jacobian(0.0, y, p, J)
    # central differences with step 1e-6: truncation ~1e-12, rounding ~1e-10 relative
    assert np.abs(J - _fd_jacobian(m, y, p)).max() <= 1e-8 * np.abs(J).max()


def test_no_tether_libration_eigenvalues_are_root_three_omega():
    """No drag, no tethers, θ = 0: pitch frequency √3 ω (issue 5; Hughes p. 302 regime)."""
    from tethersim.engine.linearise import attitude_jacobian
    sat = ts.load_preset("satI").replace(CD=0.0, E1=0.0, E2=0.0, c1=0.0, c2=0.0)
    ev = np.linalg.eigvals(attitude_jacobian(sat, [29.0, 0.0, 0.0, 0.0, 0.0, 0.0]))
    pitch = ev[np.argsort(-np.abs(ev.imag))][:2]  # the balloon's Hill modes are ≤ ω
    w = np.sqrt(3) * sat.omega
    assert np.allclose(np.sort(pitch.imag), [-w, w], rtol=1e-6) and np.allclose(pitch.real, 0, atol=1e-12)
