"""The block form of the RK4 amplification is the per-satellite one, bit for bit."""
from __future__ import annotations

import numpy as np

from tethersim import load_preset
from tethersim.engine.linearise import rk4_amplification, rk4_amplifications


def test_amplifications_of_a_block_equal_each_satellites_own():
    sat = load_preset("satI")
    rng = np.random.default_rng(5)
    sats = [sat.replace(E1=e1, E2=rng.uniform(0.001, 0.08), c1=rng.uniform(0, 0.05))
            for e1 in np.linspace(0.0005, 0.05, 40)]
    steps = [s.period / 200 * rng.uniform(0.5, 4.0) for s in sats]
    got = rk4_amplifications(sats, steps)
    assert got == [rk4_amplification(s, h) for s, h in zip(sats, steps)]
    assert got[3:9] == rk4_amplifications(sats[3:9], steps[3:9])  # not the block's doing
    assert any(a > 1 for a in got) and any(a <= 1 for a in got)
    assert rk4_amplifications([], []) == []
