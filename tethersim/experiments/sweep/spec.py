"""What a sweep computes: a base satellite, one or two parameter axes, and how to integrate.

Axis values are in edge units (tethersim.model.params.EDGE_UNITS: E in N/mm^2,
altitude in km, else SI).  A spec is plain data: it travels to Dask workers
and is written into the store's attributes, so a resumed sweep can check that
it continues the same computation.
"""
from __future__ import annotations

import itertools
import json
from dataclasses import InitVar, dataclass, field

import numpy as np

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD
from tethersim.experiments.sweep.plan import DEFAULT_RTOL, SAMPLES_PER_PERIOD, Plan
from tethersim.model import params, plausibility
from tethersim.model.registry import DEFAULT_MODEL, model_for_orbit
from tethersim.model.satellite import Satellite, SatelliteError


@dataclass(frozen=True)
class SweepSpec:
    """A grid of runs of ``satellite`` with one or two parameters changed.

    Plain data: it travels to Dask workers and into the store's attributes.

    Attributes
    ----------
    satellite : Satellite
        The base satellite.
    axes : tuple
        ((name, values), ...) with values in edge units (tethersim.model.params).
    periods : float
        Orbits per run (thesis: 50, about three days, p. 5-6).
    method : str
        "adaptive" (DOP853 at rtol) or "faithful" (the thesis's fixed RK4 step,
        ``steps_per_period`` per orbit, switches not located).
    model : str
        Model name.
    rtol : float
        Adaptive tolerance.
    steps_per_period, samples_per_period : int
        RK4 steps and adaptive output samples per orbit.
    tol : float
        Settling band [rad].
    progress : bool or None
        Init only: a progress bar while the points are checked (None: if that takes
        over a second, as a million-point grid does; False: never).
    check : bool
        Init only: build and check every grid point's satellite (default True; False
        for a copy of a spec that was checked, :meth:`from_json`).
    names : tuple
        The axis names, in order.
    """

    satellite: Satellite
    axes: tuple
    periods: float = 50.0
    method: str = "adaptive"
    model: str = DEFAULT_MODEL
    rtol: float = DEFAULT_RTOL
    steps_per_period: int = FAITHFUL_STEPS_PER_PERIOD
    samples_per_period: int = SAMPLES_PER_PERIOD
    tol: float = SETTLING_TOL
    progress: InitVar[bool | None] = None
    check: InitVar[bool] = True
    names: tuple = field(init=False)

    def __post_init__(self, progress=None, check=True):
        if not isinstance(self.satellite, Satellite):
            raise TypeError("satellite must be a tethersim Satellite")
        if not isinstance(self.axes, (tuple, list)) or not all(
                isinstance(a, (tuple, list)) and len(a) == 2 and isinstance(a[0], str)
                for a in self.axes):
            raise TypeError(f"axes = {self.axes!r:.80}: must be a tuple of (name, values) "
                            f"pairs, e.g. (('E1', [0.001, 0.004]),)")
        if not 1 <= len(self.axes) <= 2:
            raise ValueError(f"a sweep has one or two axes, got {len(self.axes)}")
        axes = []
        for name, values in self.axes:
            params.check_name(name)
            try:
                v = np.asarray(values, dtype=float).ravel()
            except (TypeError, ValueError):
                raise ValueError(f"axis {name} = {values!r:.80}: must be numbers "
                                 f"({params.unit(name)})") from None
            if v.size == 0 or not np.all(np.isfinite(v)):
                raise ValueError(f"axis {name}: needs finite values")
            if np.unique(v).size != v.size:
                raise ValueError(f"axis {name}: values repeat (each point once)")
            axes.append((name, tuple(float(x) for x in v)))
        names = tuple(n for n, _ in axes)
        if len(set(names)) != len(names):
            raise ValueError(f"axes repeat a parameter: {names}")
        object.__setattr__(self, "axes", tuple(axes))
        object.__setattr__(self, "names", names)
        _ = self.plan  # the integration's fields, checked once (plan.py)
        # the model that runs (a free orbit runs the free twin): the store names it
        object.__setattr__(self, "model", model_for_orbit(self.model, self.satellite.orbit))
        from tethersim.engine.guards import check_sweep  # before validating (or allocating) 10^12 points
        check_sweep([len(v) for _, v in axes], names)
        if check:
            self.check_points(progress)

    @property
    def plan(self) -> Plan:
        """The integration every point shares (the compiled block's settings)."""
        return Plan(periods=self.periods, method=self.method, model=self.model, rtol=self.rtol,
                    steps_per_period=self.steps_per_period,
                    samples_per_period=self.samples_per_period, tol=self.tol)

    # --- the grid --------------------------------------------------------------
    @property
    def shape(self) -> tuple:
        """Store shape: (n_y, n_x) for two axes (the first axis is x), (n,) for one."""
        return tuple(len(v) for _, v in reversed(self.axes))

    @property
    def size(self) -> int:
        return int(np.prod(self.shape))

    def values_at(self, k: int) -> dict:
        """{name: edge value} of flat point k (C order over ``shape``)."""
        idx = np.unravel_index(k, self.shape)[::-1]  # back to axis order (x first)
        return {name: values[i] for (name, values), i in zip(self.axes, idx)}

    def satellite_at(self, k: int) -> Satellite:
        return params.with_values(self.satellite, self.values_at(k))

    def check_points(self, progress: bool | None = None) -> None:
        """Every grid point must be a valid satellite: fail before any run, naming it.

        Every combination is built: the satellite's checks relate parameters (the COM
        on the boom, the plausibility of pairs), so the axes' values alone do not decide.
        About 40 us a point: a million-point grid takes most of a minute, so a bar shows
        it (``progress``: None when it takes over a second, False never); Ctrl-C or
        SIGTERM stop it at once (nothing was written).
        """
        from tqdm.auto import tqdm

        # the grid's corners first: a range that leaves the allowed values mostly does so
        # at an end, and is then refused at once rather than after the bar
        corners = sorted({int(np.ravel_multi_index(c, self.shape))
                          for c in itertools.product(*[(0, n - 1) for n in self.shape])})
        for k in corners:
            self._check_point(k)
        step = 1000  # points per bar update: the bar costs nothing beside the checks
        with tqdm(total=self.size, desc="checking sweep points", unit="point",
                  delay=0.0 if progress else 1.0, disable=progress is False,
                  leave=False) as bar:
            for k in range(self.size):
                self._check_point(k)
                if k % step == step - 1:
                    bar.update(step)

    def _check_point(self, k: int) -> None:
        try:
            sat = self.satellite_at(k)
        except SatelliteError as exc:
            raise SatelliteError(f"sweep point {self._where(k)} is not a valid satellite: "
                                 f"{exc}") from None
        # a tether too stiff for an explicit scheme (a real fibre line, docs/tethers.md) is
        # refused here, before any store, not in the middle of the run
        stiff = ([] if sat.allow_implausible or self.method == "implicit"
                 else plausibility.stiffness_problems(sat))
        if stiff:
            raise SatelliteError(f"sweep point {self._where(k)} is too stiff for the sweep's "
                                 f"{self.method} scheme: {stiff[0]}; run such a tether with "
                                 f"the implicit scheme (--method implicit)")

    def _where(self, k: int) -> str:
        return ", ".join(f"{n} = {v:g} {params.unit(n)}" for n, v in self.values_at(k).items())

    # --- plain-data form (store attributes, Dask) -------------------------------
    def to_json(self) -> str:
        sat = self.satellite.to_dict()
        sat["initial"] = list(sat["initial"])
        return json.dumps({
            "satellite": sat, "axes": [[n, list(v)] for n, v in self.axes],
            "periods": self.periods, "method": self.method, "model": self.model,
            "rtol": self.rtol, "steps_per_period": self.steps_per_period,
            "samples_per_period": self.samples_per_period, "tol": self.tol,
        }, sort_keys=True)

    @classmethod
    def from_json(cls, text: str, check: bool = True) -> SweepSpec:
        """The spec of :meth:`to_json`'s text; ``check=False`` skips the points' checks
        (the copy of a spec that was checked: a worker's)."""
        d = json.loads(text)
        sat = d.pop("satellite")
        sat["initial"] = tuple(sat["initial"])
        # a copy checks its points without a bar: the command that made the spec showed one
        return cls(satellite=Satellite(**sat), axes=tuple((n, v) for n, v in d.pop("axes")),
                   progress=False, check=check, **d)
