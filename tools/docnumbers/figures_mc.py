"""Figures of docs/montecarlo.md: the interval half-width at n = 2000 and the epoch days
left out of the default span."""
from __future__ import annotations

from tools.docnumbers.check import Figure

MC = "docs/montecarlo.md"


def _half_width() -> float:
    from tethersim.analysis.uncertainty import proportion_ci
    _, lo, hi = proportion_ci(1000, 2000)
    return (hi - lo) / 2


def _days_left_out() -> int:
    import numpy as np

    import tethersim as ts
    from tethersim.experiments.mc import MCSpec
    from tethersim.experiments.mc.inputs import usable_days
    ep = MCSpec(ts.load_preset("satI"), n=1, seed=0).inputs[0]  # the default span
    every = np.arange(np.datetime64(ep.low), np.datetime64(ep.high) + 1)
    return every.size - usable_days(ep.low, ep.high).size


QUANTITIES = {"mc_half_width_2000": _half_width, "mc_epoch_days_left_out": _days_left_out}
FIGURES = [Figure(MC, ("the half-width is at most ",), "mc_half_width_2000"),
           Figure(MC, ("below 60 sfu): ",), "mc_epoch_days_left_out")]
