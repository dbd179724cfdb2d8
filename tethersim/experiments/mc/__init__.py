"""Monte Carlo over what is uncertain: the epoch's real space weather, drag, inflation,
tethers and deployment (docs/montecarlo.md).

``run_mc(MCSpec(sat, n=..., seed=...), out)`` runs (or resumes) every sample into a
resumable store and returns the rows; ``summarise(rows, spec)`` gives the probabilities,
quantiles and Sobol' indices with their confidence intervals.
"""
from __future__ import annotations

from tethersim.experiments.mc.run import MCInterrupted, read_rows, run_mc
from tethersim.experiments.mc.spec import MCSpec
from tethersim.experiments.mc.summary import summarise, summary_rows

__all__ = ["MCSpec", "MCInterrupted", "read_rows", "run_mc", "summarise", "summary_rows"]
