"""Why a test runs in the slow tier (make test-slow, which CI runs too).

Every compiled time loop is specialised per model and scheme, and each costs 12-16 s to
compile on a cold cache (mostly the model's generated rhs).  The fast tier runs the time
loops of the default model (derived) and of the free-orbit twin only; the thesis
variants' loops (printed, exact-gravity, objective-damper) are run by the tests marked
``VARIANT_LOOP``, in the slow tier.  The variants themselves stay in the fast tier where
no loop is compiled: their generated rhs against the sympy derivation and the hand-derived
Eqs 3.48-3.50 (tests/derive), their Jacobians, forces and equilibria.

The same rule for the other kernels: a test that would be the only fast test to compile a
kernel (the 3-D finite-difference Jacobian: tests/derive/test_3d_planar.py, the
find_equilibrium example of tests/test_docstrings.py) runs in the slow tier, and a test
of printed formulas calls the generated function uncompiled (``.py_func``).  The faithful
sweep's RK4 lane block (``RK4_LANES``) and the variants' compiled finite-difference
Jacobians follow it too; the adaptive sweep's lane block, the sweeps' default, stays fast.
"""
from __future__ import annotations

import pytest

VARIANT_LOOP = pytest.mark.slow
# the faithful (RK4) sweep block on SIMD lanes (experiments/sweep/lanes.py): 21 s of compile
# for the three tests that run it, its equality with the scalar block and with simulate()
RK4_LANES = pytest.mark.slow


def models(*names):
    """Parametrize values of model names: the variants' in the slow tier (VARIANT_LOOP)."""
    return [n if n == "derived" else pytest.param(n, marks=VARIANT_LOOP) for n in names]
