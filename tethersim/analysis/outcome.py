"""The one outcome of a run: metrics, class, trail, force peaks, error estimate.

Every consumer (``tethersim run``'s summary, compare, headlines, sweeps, tune,
the report) computes what a run *means* here, with one rule for runs that did
not finish:

* a run **counts** when its status is ``"ok"``, it has at least two samples and
  every pitch sample is finite; its class comes from its pitch metrics
  (:func:`tethersim.analysis.classify.classify`, docs/metrics.md);
* any other run (``"diverged"``, ``"failed"``, ``"interrupted"``, a NaN sample)
  is class ``failed`` and ``reason`` says why.  Its metrics are still computed
  on the finite samples before the first non-finite one, for display only.

Callers that must not record a truncated run (sweeps, headlines) test
``outcome.status == "interrupted"`` themselves.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, replace

import numpy as np

from tethersim.analysis.classify import CLASSES, FAILED, classify
from tethersim.analysis.metrics import (
    SETTLING_TOL,
    PitchMetrics,
    check_tol,
    steady_metrics,
)
from tethersim.engine.evaluate import family_force_peaks
from tethersim.engine.result import SimResult, dominant_error

NAN3 = (math.nan, math.nan, math.nan)


@dataclass(frozen=True)
class Outcome:
    """What one run amounts to (SI units).

    Attributes
    ----------
    status : str
        The run's status (``"ok"``, ``"diverged"``, ``"failed"``, ``"interrupted"``).
    reason : str
        Why the class is ``failed`` (empty for a run that counts).
    stability_class : int
        Code in :data:`tethersim.analysis.classify.CLASSES`.
    metrics : PitchMetrics or None
        Pitch metrics over the finite samples (None: fewer than two).
    trail_delta_x, trail_delta_y : float
        Balloon offset averaged over the steady-state window [m].
    max_force : tuple of float
        Largest |Q| of a single force family on (δx [N], δy [N], θ [N m]);
        NaN when not computed.
    error_estimate : dict or None
        Estimated final error of every generalized coordinate, {name: SI value}
        (``SimResult.errors``), if the run was checked.
    converged : bool or None
        Whether every coordinate's estimate is within its unit's bound
        (``tethersim.engine.result.CONVERGED_TOLERANCE``).
    units : dict
        {coordinate name: SI unit} of the model's generalized coordinates.
    drag_makeup : float
        Velocity per day that holds a circular orbit against the run's drag
        [m/s/day] (tethersim.analysis.orbit_life); NaN for a free orbit.
    reentry_time : float or None
        When a free orbit re-entered [s]; None if it did not (not in ``row()``).
    """

    status: str
    reason: str
    stability_class: int
    metrics: PitchMetrics | None
    trail_delta_x: float
    trail_delta_y: float
    max_force: tuple
    error_estimate: dict | None
    converged: bool | None
    drag_makeup: float = math.nan
    reentry_time: float | None = None
    units: dict = field(default_factory=dict)

    @property
    def class_name(self) -> str:
        """Name of the stability class (``stable``, ``offset`` ... ``failed``)."""
        return CLASSES[self.stability_class]

    @property
    def counts(self) -> bool:
        """True when the run finished and its class comes from its metrics."""
        return not self.reason

    def row(self) -> dict:
        """The outcome as one flat table row (keys are :data:`ROW_COLUMNS`)."""
        m = self.metrics
        err = self.error_estimate
        return {
            "status": self.status,
            "class": self.class_name,
            "mean_pitch": m.mean_pitch if m else math.nan,
            "steady_state_pitch": m.steady_state_pitch if m else math.nan,
            "settling_time_h": m.settling_time / 3600 if m else math.nan,
            "tumbled": bool(m.tumbled) if m else None,
            "upside_down": bool(m.upside_down) if m else None,
            "trail_delta_x": self.trail_delta_x,
            "trail_delta_y": self.trail_delta_y,
            "max_force_delta_x": self.max_force[0],
            "max_force_delta_y": self.max_force[1],
            "max_force_theta": self.max_force[2],
            "converged": self.converged,
            "error_theta": err["theta"] if err else math.nan,
            "error_position": self._largest_error("m"),
            "error_angle": self._largest_error("rad"),
            "error_largest_in": dominant_error(err, self.units)[0] if err else "",
        }

    def _largest_error(self, unit: str) -> float:
        """Largest estimated final error among the coordinates in ``unit`` (NaN: none)."""
        err = self.error_estimate or {}
        return max((e for k, e in err.items() if self.units.get(k) == unit), default=math.nan)

    def to_dict(self) -> dict:
        """All fields as plain Python values (metrics nested)."""
        d = asdict(self)
        d["class"] = self.class_name
        return d


# (key, header with unit) of Outcome.row(), in order: one layout for every table
ROW_COLUMNS = (
    ("status", "status"),
    ("class", "class"),
    ("mean_pitch", "mean pitch [rad]"),
    ("steady_state_pitch", "steady-state pitch [rad]"),
    ("settling_time_h", "settling time [h]"),
    ("tumbled", "tumbled"),
    ("upside_down", "upside down"),
    ("trail_delta_x", "trail delta_x [m]"),
    ("trail_delta_y", "trail delta_y [m]"),
    ("max_force_delta_x", "largest family force on delta_x [N]"),
    ("max_force_delta_y", "largest family force on delta_y [N]"),
    ("max_force_theta", "largest family torque on theta [N m]"),
    ("converged", "converged"),
    ("error_theta", "estimated final error theta [rad]"),
    ("error_position", "estimated final error position [m]"),
    ("error_angle", "estimated final error, largest angle [rad]"),
    ("error_largest_in", "estimated final error largest in"),
)


def finite_prefix(res: SimResult) -> int:
    """Number of leading samples whose state is finite."""
    bad = np.nonzero(~np.all(np.isfinite(res.states), axis=1))[0]
    return int(bad[0]) if bad.size else res.t.size


def run_orbits(res: SimResult) -> float:
    """Length of a run [orbits]: the length asked for (a run that counts ran all of it),
    as a sweep's compiled blocks take it, else the span of its samples."""
    if res.periods is not None:
        return float(res.periods)
    return float(res.t[-1] - res.t[0]) / res.satellite.period if res.t.size else 0.0


def outcome(res: SimResult, tol: float = SETTLING_TOL, forces: bool = True) -> Outcome:
    """The :class:`Outcome` of a run.

    Parameters
    ----------
    res : SimResult
        A finished (or stopped) run.
    tol : float, optional
        Settling band [rad] (thesis ±0.05 rad, p. 5-18): finite, in (0, π).
    forces : bool, optional
        Also find the largest force of a single family on each coordinate
        (evaluates the force kernels at every sample).

    Returns
    -------
    Outcome
        A run that counts but is shorter than
        :func:`tethersim.analysis.metrics.min_run_orbits` is ``undecided`` (or
        ``tumbling`` if θ passed ±π): :func:`run_orbits`.

    Examples
    --------
    >>> import tethersim as ts
    >>> res = ts.simulate(ts.load_preset("satI"), periods=1, progress=False)
    >>> ts.outcome(res).status
    'ok'
    """
    if not isinstance(res, SimResult):
        raise TypeError(f"res must be a SimResult (from simulate), got {type(res).__name__}")
    check_tol(tol)
    if res.fine_t is not None:  # metrics on the metrics grid, not the output sampling
        res = replace(res, t=res.fine_t, states=res.fine_states, fine_t=None, fine_states=None)
    n = finite_prefix(res)
    t, states = res.t[:n], res.states[:n]
    ix, iy, ith = (res.layout.state.index(s) for s in ("delta_x", "delta_y", "theta"))
    reason = ""
    if res.status != "ok":
        reason = res.message or res.status
    elif n < res.t.size:
        reason = f"non-finite state at t = {res.t[n]:.6g} s"
    elif n < 2:
        reason = "fewer than two samples"
    m, trail = None, (math.nan, math.nan)
    if n >= 2:
        m, trail = steady_metrics(t, states, ith, (ix, iy), tol=tol)
    cls = FAILED if reason else classify(m, tol=tol, run_orbits=run_orbits(res))
    peak = NAN3
    if forces and n >= 1:
        q = family_force_peaks(res.layout.index, res.air, t, states, res.parameters)
        peak = tuple(float(q[i]) for i in (ix, iy, ith))  # coordinates lead the state
    from tethersim.analysis.orbit_life import drag_makeup, lifetime
    with np.errstate(all="ignore"):
        makeup = drag_makeup(res) if n >= 2 else math.nan
    return Outcome(status=res.status, reason=reason, stability_class=int(cls), metrics=m,
                   trail_delta_x=trail[0], trail_delta_y=trail[1], max_force=peak,
                   error_estimate=res.errors, converged=res.converged,
                   drag_makeup=makeup, reentry_time=lifetime(res),
                   units=res.units)
