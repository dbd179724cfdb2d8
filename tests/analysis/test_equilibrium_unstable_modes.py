"""Equilibria (issue 19): every mode that makes one unstable is listed, real ones too, and
an equilibrium outside the model's domain says so (engine/domain.py's limits)."""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.equilibrium import find_equilibrium, format_equilibrium
from tethersim.engine.bodies import bodies_from_states
from tethersim.engine.domain import MAX_STRETCH

SAT = ts.load_preset("satI")
NO_E2 = SAT.replace(E2=0.0)  # `tethersim equilibrium satI --set E2=0`


@pytest.mark.parametrize("sat", [SAT, NO_E2, ts.load_preset("satII"),
                                 ts.load_preset("dumbsat")])
def test_every_eigenvalue_is_a_listed_mode_or_neutral(sat):
    eq = find_equilibrium(sat)
    assert 2 * len(eq.modes()) + len(eq.real_modes()) + eq.neutral == eq.eigenvalues.size
    growing = [w for w, zeta, _ in eq.modes() if zeta <= 0] + \
        [lam for lam, _ in eq.real_modes() if lam > 0]
    assert eq.stable == (not growing)


def test_a_real_unstable_eigenvalue_is_listed_as_growing():
    eq = find_equilibrium(NO_E2)
    worst = float(np.max(eq.eigenvalues.real))
    assert not eq.stable and worst > 0
    lam, tau = eq.real_modes()[0]
    assert lam == pytest.approx(worst) and tau == pytest.approx(1 / worst)
    text = format_equilibrium(eq)
    assert "linearly UNSTABLE" in text and "GROWS" in text


def test_an_equilibrium_beyond_the_stretch_limit_is_flagged_not_presented_as_normal():
    eq = find_equilibrium(NO_E2)
    # independent: tether 1's length from the body positions against 20 x its rest length
    off = bodies_from_states(NO_E2, eq.model, 0.0, np.concatenate([eq.state[:3],
                                                                   np.zeros(3)])).offset
    stretch = np.linalg.norm(off[0] - off[2]) / NO_E2.l10
    assert stretch > MAX_STRETCH
    assert not eq.in_domain and "tether 1 stretched" in eq.outside_domain
    assert f"{stretch:.3g} x" in eq.outside_domain
    text = format_equilibrium(eq)
    assert "OUTSIDE THE MODEL'S DOMAIN" in text.splitlines()[1]


def test_the_presets_equilibria_lie_inside_the_domain():
    for name in ("satI", "satII", "dumbsat"):
        eq = find_equilibrium(ts.load_preset(name))
        assert eq.in_domain and eq.outside_domain == ""
        assert "OUTSIDE" not in format_equilibrium(eq)
