"""Summary metrics of a pitch history (definitions: docs/metrics.md).

mean pitch         mean of θ over the whole run (thesis p. 5-2)
steady-state pitch mean of θ over the last ``ss_fraction`` of the run
settling time      first time after which |θ − θ_ss| stays within ``tol``; NaN
                   unless the whole steady-state window is within ``tol`` (thesis
                   criterion: ±0.05 rad, within three days ≈ 50 orbits, p. 5-6, 5-18)
tumbled            θ left the interval (−π, π): the boom went over the top
upside down        steady-state pitch within π/4 of ±π (tip-mass pointing down)

How long a run must be for these to mean anything (:func:`long_enough`): the
steady-state window must hold at least one pitch libration period, else θ_ss is a
point on the initial libration and "settled" a moment of it.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from tethersim.analysis.metrics_kernel import N_PITCH, pitch_metrics_of, window_mean_of

SETTLING_TOL = 0.05  # rad, thesis stability criterion (p. 5-18)
SS_FRACTION = 0.2  # last fifth of the run defines the steady state
# The gravity-gradient pitch librates at √3 ω (thesis Eq 4.5 with point masses,
# tethersim.analysis.validation): its period is 1/√3 of an orbit.
LIBRATION_ORBITS = 1 / math.sqrt(3)


@dataclass(frozen=True)
class PitchMetrics:
    mean_pitch: float  # rad
    steady_state_pitch: float  # rad, wrapped to (−π, π]
    settling_time: float  # s, NaN if it never settles
    tumbled: bool
    upside_down: bool

    def to_dict(self) -> dict:
        return asdict(self)


def check_tol(tol) -> float:
    """The settling band ``tol`` [rad] if it is a finite number in (0, π); else ValueError."""
    if isinstance(tol, bool) or not isinstance(tol, (int, float, np.floating, np.integer)) \
            or not (0 < tol < math.pi):
        raise ValueError(f"tol = {tol!r}: the settling band must be a finite number of "
                         f"radians in (0, pi)")
    return float(tol)


def min_run_orbits(ss_fraction: float = SS_FRACTION) -> float:
    """Fewest orbits whose steady-state window holds one pitch libration period.

    The window is the last ``ss_fraction`` of the run, so the run needs
    ``LIBRATION_ORBITS / ss_fraction`` orbits (≈ 2.89 with the last fifth).
    """
    return LIBRATION_ORBITS / ss_fraction


def long_enough(run_orbits: float, ss_fraction: float = SS_FRACTION) -> bool:
    """Whether a run of ``run_orbits`` orbits is long enough to decide its class.

    The one test of run length, used by :func:`tethersim.analysis.outcome.outcome`
    and the compiled sweep blocks (tethersim.experiments.sweep.batch) alike.
    """
    return run_orbits >= min_run_orbits(ss_fraction)


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
    """Metrics of θ(t) [rad] sampled at times t [s] (uniform or not).

    Parameters
    ----------
    t, theta : array_like
        Sample times [s] (increasing) and pitch [rad], at least two samples.
    tol : float, optional
        Settling band [rad] (default the thesis's 0.05).
    ss_fraction : float, optional
        The steady-state window: the last ``ss_fraction`` of the run (default 0.2).

    Returns
    -------
    PitchMetrics
    """
    theta = np.asarray(theta, dtype=float)
    return steady_metrics(t, theta.reshape(-1, 1), 0, (), tol, ss_fraction)[0]


def steady_state_mean(t, values, ss_fraction: float = SS_FRACTION) -> float:
    """Mean of ``values`` over the last ``ss_fraction`` of the run (the steady-state
    window of the pitch metrics, docs/metrics.md; the same compiled mean); units of
    ``values``."""
    t = np.ascontiguousarray(t, dtype=float)
    v = np.ascontiguousarray(values, dtype=float).reshape(-1, 1)
    n = t.size
    return float(window_mean_of(t, v, n, 0, t[-1] - ss_fraction * (t[-1] - t[0]), np.empty(n)))


def steady_metrics(t, Y, col: int, trail: tuple = (), tol: float = SETTLING_TOL,
                   ss_fraction: float = SS_FRACTION) -> tuple:
    """The pitch metrics of θ = Y[:, col] and the steady-state means of columns ``trail``.

    One compiled implementation (analysis.metrics_kernel) serves this function,
    :func:`pitch_metrics`, ``outcome()`` and a sweep's compiled blocks.

    Parameters
    ----------
    t : array_like
        Sample times [s], increasing, at least two.
    Y : array_like
        Samples (n, columns).
    col : int
        The pitch column.
    trail : tuple of int, optional
        Columns averaged over the steady-state window (outcome's trail δx, δy).
    tol, ss_fraction : float, optional
        As :func:`pitch_metrics`.

    Returns
    -------
    tuple
        (PitchMetrics, tuple of the trail columns' window means).
    """
    t = np.ascontiguousarray(t, dtype=float)
    Y = np.ascontiguousarray(Y, dtype=float)
    if t.size < 2:
        raise ValueError("pitch_metrics needs at least two samples")
    tol = check_tol(tol)
    if not 0 < ss_fraction <= 1:
        raise ValueError(f"ss_fraction = {ss_fraction}: allowed range (0, 1]")
    n = t.size
    buf, out = np.empty(n), np.empty(N_PITCH)
    threshold = pitch_metrics_of(t, Y, n, col, tol, float(ss_fraction), buf, out)
    means = tuple(float(window_mean_of(t, Y, n, c, threshold, buf)) for c in trail)
    return PitchMetrics(mean_pitch=float(out[0]), steady_state_pitch=float(out[1]),
                        settling_time=float(out[2]), tumbled=bool(out[3]),
                        upside_down=bool(out[4])), means
