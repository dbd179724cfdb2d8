"""Force breakdown: the generalized force of each family on each coordinate.

The thesis plots, for SatI over 50 orbits, every force family's contribution to
each generalized coordinate (Figures 5.7-5.12, nominal damping, pp. 5-8 to 5-12;
Figures 5.15-5.20, damping x 10, pp. 5-14 to 5-17), with a "zoomed" figure for
the families too small to see beside the dominant ones, and quotes the largest
force on each coordinate.  This module computes that table from
``SimResult.forces`` (Q[i, f, k], families in ``generated.layout.FAMILIES``),
SI throughout: N on δx and δy, N m on θ.  Plots: ``tethersim.output.plots.forces``.

Thesis vs tethersim, SatI, 50 orbits (largest |Q| of one family; the thesis
quotes θ in "Newtons", but a generalized force on θ is a torque, N m):

    ===============  ========================  ==========================================
    coordinate       thesis (pp. 5-8, 5-9)     tethersim, satI preset, adaptive (runner-up)
    ===============  ========================  ==========================================
    δx, nominal c    ≈ 2 N (drag, spring 1)    0.1786 N drag3 (spring2 0.1673 N)
    δy, nominal c    ≈ 1.2 N (dampers)         0.005931 N spring2 (spring1 0.005674 N)
    θ,  nominal c    ≈ 102 (springs)           0.1639 N m spring1 (spring2 0.1635 N m)
    δx, c x 10       ≈ 1.9 N (p. 5-13)         0.1786 N drag3 (spring2 0.1673 N)
    δy, c x 10       ≈ 1.1 N (p. 5-14)         0.005678 N spring1 (spring2 0.005597 N)
    θ,  c x 10       ≈ 157 (p. 5-14)           0.1635 N m spring1 (spring2 0.1631 N m)
    ===============  ========================  ==========================================

The thesis's magnitudes are not reproduced, and no preset consistent with the
rest of the thesis can reproduce them: a tether pulls E (λ/l0 − 1) with E in
N/mm² × 1 mm² = N (p. 3-1), the thesis's moduli are ~0.01 N/mm² (its E2 sweep
stops at 0.06 N/mm², p. 5-18) and its balloon trails ~28 m behind 6 m tethers
(pp. 5-3, 5-19), so λ/l0 − 1 ≈ 3.7 and a tether pulls at most ~0.2 N.  A 2 N
spring force on δx would need E ≈ 0.5 N/mm² (or a 200 m stretch), and 102 N m
on θ a ~10 N tension at the 10.5 m tip-mass arm.  In steady state the tethers
carry the balloon's drag, 0.18 N at 200 km (docs/metrics.md); with damping
that settles the pitch in about two days (c ~ 3e-4 N s/m in our preset; the
thesis's values are lost) the damper families stay below 2e-4 N (N m on θ),
nowhere near the 1.2 N the thesis's dampers reach on δy.
The families that dominate also differ (our preset puts the drag load mostly on
tether 2, the stiffer one); the numbers above are what our model computes and
are kept as such.  The thesis's x 10 damping run also ends upside down (3.18
rad, p. 5-13); our satI preset with c x 10 does not.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tethersim.engine.result import SimResult
from tethersim.generated.layout import FAMILIES

# (name, symbol, SI unit) of each generalized coordinate of the planar models, in the order
# of Q[..., k]; any model's: coordinates(layout)
COORDINATES = (("delta_x", "δx", "N"), ("delta_y", "δy", "N"), ("theta", "θ", "N m"))
SYMBOLS = {"delta_x": "δx", "delta_y": "δy", "delta_z": "δz", "theta": "θ", "phi": "φ",
           "psi": "ψ", "r": "r", "nu": "ν"}
# a generalized force on a length is a force, on an angle a torque
FORCE_UNITS = {"m": "N", "rad": "N m"}
SMALL_FRACTION = 0.1  # a family is "small" below 10 % of the largest peak (zoomed panel)
# Samples per orbit of an adaptive run: ~5.3 s apart, >= 13 per tether period
# (~70-80 s, `tethersim equilibrium satI`), so the peaks of the tether modes are
# resolved; the RK4 run of --faithful keeps its own 200 steps per orbit (26.55 s).
SAMPLES_PER_PERIOD = 1000
def coordinates(layout) -> tuple:
    """(name, symbol, SI unit of its generalized force) of each coordinate of a model.

    Parameters
    ----------
    layout : tethersim.model.registry.Model
        The model (``SimResult.layout``): 3 coordinates planar, 6 in 3-D (δx, δy, δz,
        φ, θ, ψ), plus r and ν on a free orbit, in the order of ``Q[..., k]``.
    """
    n = layout.n_coordinates
    return tuple((name, SYMBOLS.get(name, name), FORCE_UNITS[unit])
                 for name, unit in zip(layout.state[:n], layout.state_units[:n]))


@dataclass(frozen=True)
class LargestForce:
    """The largest |Q| of one family on one coordinate (SI) and where it occurs.

    coordinate: a coordinate of the model ("delta_x", "theta", "phi", ...); unit: "N" or "N m";
    family: the family with the largest peak (None if every family is zero);
    peak: its max |Q| [unit]; time: when it occurs [s]; period: orbital period [s];
    runner_up, runner_up_peak: the family with the second largest peak and that peak.
    """

    coordinate: str
    symbol: str
    unit: str
    family: str | None
    peak: float
    time: float
    period: float
    runner_up: str | None
    runner_up_peak: float

    @property
    def time_orbits(self) -> float:
        return self.time / self.period


def peaks(Q: np.ndarray) -> np.ndarray:
    """max |Q| over the samples, (family, coordinate), ignoring non-finite samples."""
    Q = np.asarray(Q, dtype=float)
    if Q.ndim != 3 or Q.shape[1] != len(FAMILIES):
        raise ValueError(f"Q has shape {Q.shape}: expected (samples, {len(FAMILIES)}, "
                         f"coordinates)")
    finite = np.all(np.isfinite(Q), axis=(1, 2))
    if not finite.any():
        raise ValueError("no finite force sample: the run failed before its first output")
    return np.abs(Q[finite]).max(axis=0)


def small_families(Q: np.ndarray, k: int, fraction: float = SMALL_FRACTION) -> list:
    """Indices of the families whose peak on coordinate k is below ``fraction`` of the
    largest peak there: the ones the thesis's zoomed figures show (e.g. Fig 5.8)."""
    pk = peaks(Q)[:, k]
    return [f for f in range(len(FAMILIES)) if pk[f] < fraction * pk.max()]


def largest_forces_from(t, Q, period: float, coords: tuple = COORDINATES) -> list:
    """Rows of the largest-force table from times t [s], forces Q (n, 7, coordinates),
    period [s]; ``coords`` names Q's coordinates (:func:`coordinates`; default planar)."""
    t = np.asarray(t, dtype=float)
    Q = np.asarray(Q, dtype=float)
    if t.shape != Q.shape[:1]:
        raise ValueError(f"t has {t.shape} samples, Q has {Q.shape[:1]}")
    pk = peaks(Q)
    if pk.shape[1] != len(coords):
        raise ValueError(f"Q has {pk.shape[1]} coordinates, {len(coords)} named")
    absQ = np.where(np.isfinite(Q), np.abs(Q), -np.inf)
    rows = []
    for k, (name, symbol, unit) in enumerate(coords):
        order = np.argsort(-pk[:, k], kind="stable")
        first, second = order[0], order[1]
        if pk[first, k] == 0.0:
            rows.append(LargestForce(name, symbol, unit, None, 0.0, math.nan, period, None, 0.0))
            continue
        i = int(np.argmax(absQ[:, first, k]))
        rows.append(LargestForce(
            name, symbol, unit, FAMILIES[first], float(pk[first, k]), float(t[i]), period,
            FAMILIES[second] if pk[second, k] > 0 else None, float(pk[second, k])))
    return rows


def in_plane_forces(res: SimResult) -> np.ndarray:
    """(n, families, 3): the run's generalized forces on δx, δy, θ only (a 3-D or
    free-orbit model also has roll, yaw, δz or r, ν coordinates)."""
    names = res.layout.state
    return res.forces[:, :, [names.index(c) for c, _, _ in COORDINATES]]


def largest_forces(res: SimResult) -> list:
    """The largest single-family generalized force on each coordinate of a run (thesis
    p. 5-8: δx, δy, θ; a 3-D model adds δz, φ, ψ, a free orbit r and ν)."""
    return largest_forces_from(res.t, res.forces, res.satellite.period, coordinates(res.layout))


def _fmt(value: float, unit: str) -> str:
    return f"{value:.4g} {unit}"


def format_table(rows) -> str:
    """The table as text: coordinate, family, max |Q| [unit], time [orbits], runner-up."""
    head = f"  {'coordinate':<11} {'family':<8} {'max |Q|':<13} {'at [orbits]':>11}   runner-up"
    lines = ["largest generalized force per coordinate (cf. thesis pp. 5-8, 5-9, 5-14):", head]
    for r in rows:
        runner = f"{r.runner_up} ({_fmt(r.runner_up_peak, r.unit)})" if r.runner_up else "-"
        lines.append(f"  {r.symbol + ' [' + r.unit + ']':<11} {r.family or '(none)':<8} "
                     f"{_fmt(r.peak, r.unit):<13} {r.time_orbits:>11.3f}   {runner}")
    return "\n".join(lines)


# (key, header) of the forces table: values in the SI unit named in column 'unit'
COLUMNS = (("coordinate", "coordinate"), ("unit", "unit"), ("family", "family"),
           ("peak", "max_abs_Q"), ("time", "time [s]"), ("time_orbits", "time [orbits]"),
           ("runner_up", "runner_up"), ("runner_up_peak", "runner_up_max_abs_Q"))


def table_rows(rows) -> list:
    """The largest-force records as plain dicts (keys of :data:`COLUMNS`)."""
    return [{k: getattr(r, k) for k, _ in COLUMNS} for r in rows]
