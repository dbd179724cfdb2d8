"""What the engine feeds its progress bar never passes the bar's total.

The chunks' float sums overshoot the total by an ulp (0.1 orbit in 101 RK4 steps:
1.4e-16), and tqdm then printed 'warning: TqdmWarning: clamping frac' under a run.
"""
from __future__ import annotations

import pytest

import tethersim.engine.simulate as sim
from tethersim import load_preset

SAT = load_preset("satI")


class Recorder:
    """A tqdm stand-in that keeps every position it is moved to."""

    bars: list = []

    def __init__(self, total, **kwargs):
        self.total, self.n, self.seen = total, 0.0, []
        Recorder.bars.append(self)

    def update(self, k):
        self.n += k
        self.seen.append(self.n)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


@pytest.mark.parametrize("method, steps", [("rk4", 101), ("rk4", 1234), ("adaptive", None)])
def test_bar_positions_stay_within_the_total(monkeypatch, method, steps):
    monkeypatch.setattr(sim, "tqdm", Recorder)
    Recorder.bars = []
    # progress=True: the run is chunked (CHUNKS pauses), so the float sums accumulate
    res = sim.simulate(SAT, periods=0.1, steps=steps, method=method, progress=True,
                       step_warning=False)
    assert res.status == "ok"
    (bar,) = Recorder.bars
    assert len(bar.seen) > 10
    assert max(bar.seen) <= bar.total
    assert bar.seen[-1] == pytest.approx(bar.total, rel=1e-12)
    assert all(b >= a for a, b in zip(bar.seen, bar.seen[1:])), "never moves back"
