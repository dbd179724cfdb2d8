"""The 3-D free-orbit derivation (derive/three_d/free3d.py) reduces exactly, symbolically.

* (a) On the thesis's orbit (r = r0, ṙ = r̈ = 0, ν̇ = ω, ν̈ = 0, μ = ω² r0³,
  J2 = 0) the δx, δy, δz, φ, θ, ψ rows of ``3d-free`` and
  ``3d-free-objective-damper`` are the circular 3-D model's (derive/three_d/
  pipeline3d.py): M q̈ + f and every force family, difference expanded to 0.
* In the plane (δz = φ = ψ = 0 and rates, point masses I = 0) the δx, δy, θ,
  r, ν rows are the planar free model's (derive/orbit.py), J2 included, and
  the out-of-plane rows vanish: a planar state stays planar.
"""
from __future__ import annotations

import functools

import pytest
import sympy as sp

from derive.models import FREE_3D_DEFINITIONS as FREE3D_DEFINITIONS
from derive.orbit import circular_substitution
from derive.reference import derived
from derive.reference import derived as derived_3d
from derive.three_d.free3d import (
    FREE3D_ACCELERATION_SYMBOLS,
    FREE3D_STATE_SYMBOLS,
)
from derive.three_d.symbols3d import ACCELERATION_SYMBOLS, INERTIAS

pytestmark = pytest.mark.slow  # sympy derivations of minutes

NAMES = tuple(d.name for d in FREE3D_DEFINITIONS)
ROWS3D = ("delta_x", "delta_y", "delta_z", "phi", "theta", "psi")
PLANAR_FREE_TWIN = {"3d-free": "free", "3d-free-objective-damper": "free-objective-damper"}


@functools.cache
def free3d(name):
    return derived(name)


def _zero(expr) -> bool:
    return sp.expand(expr) == 0


def _zero_mod_trig(expr) -> bool:
    """Zero up to sin² + cos² = 1 (the 3-D terms at φ = 0 leave such sums)."""
    e = sp.expand(expr)
    return e == 0 or sp.trigsimp(e) == 0


def test_the_emitted_variants_and_their_twins():
    assert NAMES == ("3d-free", "3d-free-objective-damper")
    assert [d.circular for d in FREE3D_DEFINITIONS] == ["3d", "3d-objective-damper"]


@pytest.mark.parametrize("name", NAMES)
def test_circular_orbit_reproduces_the_3d_equations(name):
    """Rows 0-5 of M q̈ + f and of each family equal the circular 3-D model's."""
    model = free3d(name)
    ref = derived_3d(model.definition.circular)
    sub = circular_substitution()
    for k in range(6):
        ref_lhs = sum(ref.mass_matrix[k, m] * ACCELERATION_SYMBOLS[m] for m in range(6)) + ref.f[k]
        assert _zero(model.lhs[k].subs(sub) - ref_lhs), ROWS3D[k]
    assert [f.name for f in model.families] == [f.name for f in ref.families]
    for fam, want in zip(model.families, ref.families):
        for k in range(6):
            assert _zero(fam.Q[k].subs(sub) - want.Q[k]), (fam.name, ROWS3D[k])


def _planar_state() -> dict:
    y = {s.name: s for s in FREE3D_STATE_SYMBOLS}
    sub = {y[n]: 0 for n in ("delta_z", "phi", "psi", "delta_z_dot", "phi_dot", "psi_dot")}
    sub.update({p.symbol: 0 for p in INERTIAS})
    return sub


@pytest.mark.parametrize("name", NAMES)
def test_in_the_plane_with_point_masses_it_is_the_planar_free_model(name):
    """δx, δy, θ, r, ν rows (J2 on) = derive/orbit.py's; δz and φ rows and forces vanish."""
    model = free3d(name)
    planar = derived(PLANAR_FREE_TWIN[name])
    sub = _planar_state()
    acc = {s: 0 for s in FREE3D_ACCELERATION_SYMBOLS[2:4]}  # out-of-plane q̈ (δz, φ)
    acc[FREE3D_ACCELERATION_SYMBOLS[5]] = 0  # ψ̈: no ψ row or column with I = 0
    rows = (0, 1, 4, 6, 7)  # δx, δy, θ, r, ν in the 3-D free coordinates
    for k3, k2 in zip(rows, range(5)):
        assert _zero_mod_trig(model.lhs[k3].subs(sub).subs(acc) - planar.lhs[k2]), (name, k2)
    for k in (2, 3, 5):  # δz, φ, ψ rows: no in-plane acceleration or force drives them
        assert _zero_mod_trig(model.lhs[k].subs(sub).subs(acc)), (name, k)
    for fam, want in zip(model.families, planar.families):
        for k3, k2 in zip(rows, range(5)):
            assert _zero_mod_trig(fam.Q[k3].subs(sub) - want.Q[k2]), (fam.name, k2)
        for k in (2, 3, 5):
            assert _zero_mod_trig(fam.Q[k].subs(sub)), (fam.name, k)
