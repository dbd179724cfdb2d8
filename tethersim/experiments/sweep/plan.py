"""How a plan of many runs integrates: the settings every point of a block shares.

A :class:`Plan` is plain data (orbits per run, scheme, model, tolerance, output
density, settling band); with a list of satellites it is everything the compiled
block runner needs (:func:`tethersim.experiments.sweep.batch.run_satellites`).  A
sweep is a plan over a grid of one or two parameters (:class:`SweepSpec`); ``tune``,
the design search and the Monte Carlo are plans over satellites they build
themselves (:func:`tethersim.experiments.sweep.runner.run_plan`).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

from tethersim.analysis.metrics import SETTLING_TOL, check_tol
from tethersim.engine.arguments import check_range
from tethersim.engine.guards import MAX_STEPS_PER_PERIOD
from tethersim.engine.simulate import (
    ATOL_RANGE,
    FAITHFUL_STEPS_PER_PERIOD,
    METRIC_SAMPLES_PER_PERIOD,
    RTOL_RANGE,
)
from tethersim.engine.start import check_start_mode
from tethersim.model.registry import DEFAULT_MODEL, model_index

METHODS = ("adaptive", "faithful", "implicit")
#: the engine scheme (simulate's method) of each plan method
SCHEMES = {"adaptive": "adaptive", "faithful": "rk4", "implicit": "implicit"}
SAMPLES_PER_PERIOD = 100  # adaptive output grid for the metrics
DEFAULT_RTOL = 1e-9
# runs that only need a class or a verdict (maps, searches): chosen by the convergence study
# of docs/tolerances.md (no class changes on its grids, with two decades to spare; checked
# by tests/experiments/test_sweep_convergence.py); runs whose numbers are reported keep
# DEFAULT_RTOL
CLASS_RTOL = 1e-6
ATOL_PER_RTOL = 1e-2  # atol = rtol x this: states are O(1) rad and O(10) m
# per-orbit counts: RK4 steps up to the engine's step budget; output samples up to 50x the
# metrics grid (more adds nothing the metrics use, and multiplies the store)
MAX_STEPS = MAX_STEPS_PER_PERIOD
MAX_SAMPLES = 50 * METRIC_SAMPLES_PER_PERIOD


@dataclass(frozen=True)
class Plan:
    """The integration shared by every run of a plan of many.

    Attributes
    ----------
    periods : float
        Orbits per run (thesis: 50, about three days, p. 5-6); a run stopped by an
        event (re-entry, a limit of the model's domain) ends at the located time.
    method : str
        "adaptive" (DOP853 at rtol), "faithful" (the thesis's fixed RK4 step,
        ``steps_per_period`` per orbit, switches not located) or "implicit" (Radau IIA
        at rtol: real, stiff tethers; docs/tethers.md).
    model : str
        Model name (a satellite on a free orbit runs the model's free twin).
    rtol : float
        Adaptive tolerance.
    atol : float or None
        Adaptive absolute tolerance (None: rtol x ``ATOL_PER_RTOL``; a feasibility
        atlas gives real lines their floor, tethersim.engine.start.atol_floor).
    steps_per_period, samples_per_period : int
        RK4 steps and adaptive output samples per orbit.
    tol : float
        Settling band [rad].
    start : {"auto", "given", "equilibrium"}
        Where every run starts (simulate's ``start``, tethersim.engine.start): ``auto``
        (the default) starts real lines at their equilibrium, the thesis's tethers as
        given; ``given`` for satellites whose ``initial`` is the start (a Monte Carlo's
        deployment offsets about the equilibrium, tethersim.experiments.mc.inputs).
    """

    periods: float = 50.0
    method: str = "adaptive"
    model: str = DEFAULT_MODEL
    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    steps_per_period: int = FAITHFUL_STEPS_PER_PERIOD
    samples_per_period: int = SAMPLES_PER_PERIOD
    tol: float = SETTLING_TOL
    start: str = "auto"

    def __post_init__(self):
        if self.method not in METHODS:
            raise ValueError(f"method = {self.method!r}: allowed values {', '.join(METHODS)}")
        model_index(self.model)
        for key in ("periods", "rtol", "tol"):
            v = getattr(self, key)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"{key} = {v!r}: must be a finite number > 0")
        check_tol(self.tol)  # the settling band: (0, pi) rad, as outcome() takes it
        check_start_mode(self.start)
        if not RTOL_RANGE[0] <= self.rtol <= RTOL_RANGE[1]:
            raise ValueError(f"rtol = {self.rtol:g}: allowed range {RTOL_RANGE[0]:g} <= rtol "
                             f"<= {RTOL_RANGE[1]:g}")
        if self.atol is not None:
            check_range("atol", self.atol, ATOL_RANGE)  # simulate()'s own check
        for key, hi in (("steps_per_period", MAX_STEPS), ("samples_per_period", MAX_SAMPLES)):
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= hi:
                raise ValueError(f"{key} = {v!r}: must be an integer in 1..{hi}")

    @property
    def absolute_tolerance(self) -> float:
        """The runs' atol: :attr:`atol`, or rtol x ``ATOL_PER_RTOL``."""
        return self.rtol * ATOL_PER_RTOL if self.atol is None else float(self.atol)

    def to_dict(self) -> dict:
        """The fields as plain data (JSON, store attributes)."""
        return asdict(self)
