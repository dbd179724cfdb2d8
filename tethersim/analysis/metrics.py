"""Summary metrics of a pitch history (definitions: docs/metrics.md).

mean pitch         mean of θ over the whole run (thesis p. 5-2)
steady-state pitch mean of θ over the last ``ss_fraction`` of the run
settling time      first time after which |θ − θ_ss| stays within ``tol``; NaN
                   unless the whole steady-state window is within ``tol`` (thesis
                   criterion: ±0.05 rad, within three days ≈ 50 orbits, p. 5-6, 5-18)
tumbled            θ left the interval (−π, π): the boom went over the top
upside down        steady-state pitch within π/4 of ±π (tip-mass pointing down)
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

SETTLING_TOL = 0.05  # rad, thesis stability criterion (p. 5-18)
SS_FRACTION = 0.2  # last fifth of the run defines the steady state


@dataclass(frozen=True)
class PitchMetrics:
    mean_pitch: float  # rad
    steady_state_pitch: float  # rad, wrapped to (−π, π]
    settling_time: float  # s, NaN if it never settles
    tumbled: bool
    upside_down: bool

    def to_dict(self) -> dict:
        return asdict(self)


def wrap(angle):
    """Angle(s) wrapped to (−π, π]."""
    w = -np.remainder(-np.asarray(angle, dtype=float) + math.pi, 2 * math.pi) + math.pi
    # rounding can land exactly on −π (e.g. one ulp above π): map it to +π
    return np.where(w <= -math.pi, w + 2 * math.pi, w)


def steady_state_window(t, ss_fraction: float = SS_FRACTION) -> np.ndarray:
    """Boolean mask of the samples in the last ``ss_fraction`` of the run (times t [s])."""
    t = np.asarray(t, dtype=float)
    return t >= t[-1] - ss_fraction * (t[-1] - t[0])


def pitch_metrics(t, theta, tol: float = SETTLING_TOL,
                  ss_fraction: float = SS_FRACTION) -> PitchMetrics:
    """Metrics of θ(t) [rad] sampled at times t [s] (uniform or not)."""
    t = np.asarray(t, dtype=float)
    theta = np.asarray(theta, dtype=float)
    if t.size < 2:
        raise ValueError("pitch_metrics needs at least two samples")
    if not 0 < ss_fraction <= 1:
        raise ValueError(f"ss_fraction = {ss_fraction}: allowed range (0, 1]")
    tail = steady_state_window(t, ss_fraction)
    theta_ss = float(np.mean(theta[tail]))
    outside = np.nonzero(np.abs(theta - theta_ss) > tol)[0]
    if outside.size == 0:
        settling = float(t[0])
    elif np.any(tail[outside]):
        # a run is settled only if its whole steady-state window stays in the band
        settling = math.nan
    else:
        settling = float(t[outside[-1] + 1])
    return PitchMetrics(
        mean_pitch=float(np.mean(theta)),
        steady_state_pitch=float(wrap(theta_ss)),  # 0-d array -> float
        settling_time=settling,
        tumbled=bool(np.any(np.abs(theta) >= math.pi)),
        upside_down=bool(abs(wrap(theta_ss)) > 3 * math.pi / 4),
    )
