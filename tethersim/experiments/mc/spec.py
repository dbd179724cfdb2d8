"""What a Monte Carlo computes: the design, the draws, and the two runs of every sample.

Per sample (docs/montecarlo.md):

* **settling** -- the thesis's held circular orbit for ``periods`` orbits, in the
  uniform NRLMSISE-00 density of the sample's epoch and that day's indices;
* **life** -- the free, decaying orbit in per-body NRLMSISE-00 air with each UTC day's
  own F10.7, F10.7a and Ap from the bundled table, until it re-enters, loses its balloon
  (the model's domain: a tether stretched 20x, docs/feasibility.md) or reaches
  ``max_lifetime_h``.  It runs in stages: first to :data:`FIRST_STAGE_H` and only the
  samples still flying then again to the cap, because the MSIS grid of a run is built
  for every UTC day of its planned length before it starts (0.1 s a day, most of a
  sample's cost) while most designs end within hours.  Which stage decides is a
  function of the sample alone, so the record does not depend on the batch.
"""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, fields
from functools import cached_property

import numpy as np

from tethersim.experiments.mc.inputs import default_inputs, observed_days, with_ranges
from tethersim.experiments.sweep.plan import DEFAULT_RTOL, Plan
from tethersim.model.satellite import Satellite

FIRST_STAGE_H = 6.0  # SatI-like designs lose the balloon within hours: one or two days of grid
MAX_SAMPLES = 100_000  # a store's samples (and Sobol' rows): the rows live in memory
PARTS = ("sample", "sobol")
# satellite fields the Monte Carlo sets per sample: a design that sets them is refused
OWN_FIELDS = ("orbit", "epoch", "f107", "f107a", "ap", "density_scale")


@dataclass(frozen=True)
class MCSpec:
    """A Monte Carlo over the uncertain inputs of one design.

    Attributes
    ----------
    satellite : Satellite
        The design (held circular orbit, no fixed indices; the inputs vary around it).
    n : int
        Random samples.
    seed : int
        Seed of every input's stream and of the Sobol' design (>= 0).
    periods : float
        Orbits of the settling run.
    max_lifetime_h : float
        Cap on the free run [h]; at least the settling run's length.
    sobol : int
        Base size N of the Sobol' design (a power of two; 0: none): N (d + 2) more samples.
    model : str
        Thesis model (the free run uses its free twin).
    rtol : float
        Adaptive tolerance of every run.
    ranges : tuple
        ((name, low, high), ...): bands replacing the defaults (inputs.default_inputs).
    """

    satellite: Satellite
    n: int
    seed: int
    periods: float = 50.0
    max_lifetime_h: float = 240.0
    sobol: int = 0
    model: str = "derived"
    rtol: float = DEFAULT_RTOL
    ranges: tuple = ()

    def __post_init__(self):
        from tethersim.analysis.uncertainty import check_sobol_base
        for key, lo in (("n", 1), ("seed", 0)):
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not \
                    lo <= v <= (MAX_SAMPLES if key == "n" else 2 ** 63 - 1):
                raise ValueError(f"{key} = {v!r}: must be an integer in {lo}.."
                                 f"{MAX_SAMPLES if key == 'n' else '2^63-1'}")
        if self.sobol:
            check_sobol_base(self.sobol)
            rows = self.sobol * (len(self.inputs) + 2)
            if rows > MAX_SAMPLES:
                raise ValueError(f"sobol = {self.sobol}: {rows} runs; at most {MAX_SAMPLES}")
        _check_own_fields(self.satellite)
        _ = self.circular_plan  # validates periods, model, rtol
        cap = self.max_lifetime_h
        if not (isinstance(cap, (int, float)) and math.isfinite(cap)
                and cap * 3600 >= self.periods * self.satellite.period):
            raise ValueError(f"max_lifetime_h = {cap!r}: must be >= the settling run's "
                             f"{self.periods * self.satellite.period / 3600:.4g} h "
                             f"(periods x the orbit period), so that every settling time "
                             f"can be set against the life")
        from tethersim.experiments.sweep.batch import check_point_size
        check_point_size(self.circular_plan, "periods")
        check_point_size(self.free_plans[-1], "max_lifetime_h")
        self._check_band_ends()

    def _check_band_ends(self) -> None:
        """Refuse a band whose end makes a satellite the model refuses (implausible CD,
        a pitch past 180 deg, ...), before any run: each input at its band's ends, the
        others mid-band (every band maps u monotonically)."""
        from tethersim.experiments.mc.inputs import sample_satellites
        d = len(self.inputs)
        for j, inp in enumerate(self.inputs):
            if inp.kind == "epoch":  # its days are the usable ones by construction
                continue
            for end, u in (("low", 0.0), ("high", 1.0)):
                row = np.full((1, d), 0.5)
                row[0, j] = u
                try:
                    sample_satellites(self.satellite, self.inputs, row, self.model)
                except ValueError as exc:
                    raise ValueError(f"range of {inp.name} = {inp.low}:{inp.high}: at its "
                                     f"{end} end, {exc}") from None

    @cached_property
    def inputs(self) -> tuple:
        """The uncertain inputs with their bands (defaults, then ``ranges``)."""
        first, last = observed_days()
        # the free run's last day must be an observed one: the epoch span ends that early
        days = math.ceil(self.max_lifetime_h / 24) + 1
        last_epoch = str(np.datetime64(last, "D") - np.timedelta64(days, "D"))
        ins = with_ranges(default_inputs(last_epoch), {k: (lo, hi) for k, lo, hi in self.ranges})
        ep = next((i for i in ins if i.kind == "epoch"), None)
        if ep is not None and not (first <= str(ep.low) and str(ep.high) <= last_epoch):
            raise ValueError(f"range of epoch = {ep.low}:{ep.high}: allowed days {first}.."
                             f"{last_epoch} (observed days of the bundled space-weather table, "
                             f"less the {days} days a run of max_lifetime_h may need)")
        return ins

    @property
    def names(self) -> tuple:
        return tuple(i.name for i in self.inputs)

    @cached_property
    def circular_plan(self) -> Plan:
        """The settling run's plan."""
        # every sample starts where sample_satellites put it (given): the deployment's
        # offsets about the thesis's start, or about a real line's equilibrium
        return Plan(periods=self.periods, model=self.model, rtol=self.rtol, start="given")

    @cached_property
    def free_plans(self) -> tuple:
        """The free run's plans, one per stage (orbits of the design's period)."""
        caps = sorted({min(FIRST_STAGE_H, self.max_lifetime_h), self.max_lifetime_h})
        return tuple(Plan(periods=h * 3600 / self.satellite.period, model=self.model,
                          start="given",
                          rtol=self.rtol) for h in caps)

    def size(self, part: str) -> int:
        """Samples of ``part`` ("sample": the random ones; "sobol": the design's rows)."""
        return self.n if part == "sample" else self.sobol * (len(self.inputs) + 2)

    def units(self, part: str) -> np.ndarray:
        """(size, d) unit numbers of ``part``'s samples."""
        from tethersim.analysis.uncertainty import sobol_design
        from tethersim.experiments.mc.inputs import stream, unit_draws
        if part == "sample":
            return unit_draws(self.inputs, self.n, self.seed)
        if not self.sobol:
            return np.empty((0, len(self.inputs)))
        design_seed = int(stream(self.seed, "sobol design").integers(2 ** 31))
        return sobol_design(self.names, self.sobol, design_seed)

    def to_json(self) -> str:
        d = {f.name: getattr(self, f.name) for f in fields(self)}
        d["satellite"] = self.satellite.to_dict()
        d["satellite"]["initial"] = list(d["satellite"]["initial"])
        d["ranges"] = [list(r) for r in self.ranges]
        d["inputs"] = [asdict(i) for i in self.inputs]  # the bands in force
        return json.dumps(d, sort_keys=True, default=list)

    @classmethod
    def from_json(cls, text: str) -> MCSpec:
        d = json.loads(text)
        d.pop("inputs")
        sat = d.pop("satellite")
        sat["initial"] = tuple(sat["initial"])
        d["satellite"] = Satellite(**sat)
        d["ranges"] = tuple(tuple(r) for r in d["ranges"])
        return cls(**d)


def _check_own_fields(sat: Satellite) -> None:
    defaults = {f.name: f.default for f in fields(Satellite)}
    given = [f for f in OWN_FIELDS if getattr(sat, f) != defaults[f]]
    if not sat.density_auto:  # the density follows each run's orbit
        given.append("density_mode")
    if given:
        raise ValueError(f"mc: {', '.join(f'{f} = {getattr(sat, f)!r}' for f in given)}: the "
                         f"Monte Carlo sets these per sample (held circular orbit and free "
                         f"orbit, drawn epoch, the table's daily indices); leave "
                         f"{', '.join(OWN_FIELDS)} at their defaults")
