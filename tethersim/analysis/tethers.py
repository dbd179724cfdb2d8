"""What a run asks of its tethers: tension series, peak and snap tensions, safety factor
to breaking and slack fraction (docs/tethers.md, "Tether outputs").

The tension is the model's own: ``SimResult.tether_tensions`` evaluates the
generated tether margins λ_j − l_j0 at each sample and takes the spring's
E_j (λ_j − l_j0) / l_j0 while taut, zero while slack (Eqs 3.35-3.36) — the
tension the breaking event ``tether-broke`` judges (engine/events.py; the
damper's share stands for the line's internal loss).  Everything here is on
the run's metrics grid (``fine_t``: at least 200 samples per orbit) or its
output grid when that is finer: a stiff line's axial bounce (period ~0.05 s
for 1 mm fibre on SatI) is seen only with samples finer than it (``--steps``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from tethersim.engine.result import SimResult


@dataclass(frozen=True)
class TetherLoads:
    """Loads of one tether over a run (SI).

    Attributes
    ----------
    tether : int
        1 (tip-mass) or 2 (bus).
    peak : float
        Largest tension [N].
    snap : float
        Largest tension in a taut interval that follows a slack one: the load on
        re-tautening [N]; NaN if the tether never went slack and taut again.
    snaps : int
        Number of re-tautenings (slack to taut switches) seen on the grid.
    safety_factor : float
        Breaking load / peak (Fb_j / peak); NaN when Fb_j is 0 (never breaks) or
        the tether never pulled.
    slack_fraction : float
        Fraction of the run's time the tether was slack (λ_j <= l_j0), the switch
        times interpolated linearly between samples.
    """

    tether: int
    peak: float
    snap: float
    snaps: int
    safety_factor: float
    slack_fraction: float


def segment_tensions(res: SimResult) -> np.ndarray:
    """Spring tension of every segment of a bead-chain run (n, 2, N + 1) [N], boom end
    first, zero while slack (tethersim.model.beads.tensions); (n, 2, 0) for any other run.

    A chain's ``tether_tensions`` (and so every load here) is its most stretched
    segment's: the line breaks, snaps and goes slack where that segment does.
    """
    from tethersim.model.beads import tensions
    from tethersim.model.registry import bead_split

    chain = bead_split(res.model)
    if chain is None:
        return np.zeros((res.t.size, 2, 0))
    out = np.zeros((res.t.size, 2, chain[1] + 1))
    p = res.parameters.copy()  # the kernels write their scratch into its tail
    for i, y in enumerate(res.states):
        tensions(np.ascontiguousarray(y), p, out[i])
    return out


def metrics_grid(res: SimResult) -> SimResult:
    """``res`` on its metrics grid (``fine_t``) when it has one, else itself."""
    if res.fine_t is None:
        return res
    return replace(res, t=res.fine_t, states=res.fine_states, fine_t=None, fine_states=None)


def slack_fraction(t, margin) -> float:
    """Fraction of [t0, t_end] with ``margin`` <= 0, crossings interpolated linearly.

    Parameters
    ----------
    t : numpy.ndarray
        Sample times [s], increasing.
    margin : numpy.ndarray
        λ − l0 [m] at each sample (taut when positive).

    Returns
    -------
    float
        Slack time / run time (NaN for fewer than two samples).
    """
    t, g = np.asarray(t, float), np.asarray(margin, float)
    if t.size < 2 or t[-1] <= t[0]:
        return math.nan
    g0, g1, dt = g[:-1], g[1:], np.diff(t)
    s0, s1 = g0 <= 0, g1 <= 0
    slack = np.where(s0 & s1, dt, 0.0)
    cross = s0 != s1
    # the share of a crossing interval on the slack side: |g_slack| / (|g0| + |g1|)
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(s0, np.abs(g0), np.abs(g1)) / (np.abs(g0) + np.abs(g1))
    slack = slack + np.where(cross, dt * np.nan_to_num(share, nan=0.5), 0.0)
    return float(slack.sum() / (t[-1] - t[0]))


def tether_loads(res: SimResult) -> tuple:
    """:class:`TetherLoads` of tethers 1 and 2 over the run (up to its last finite sample).

    Examples
    --------
    >>> import tethersim as ts
    >>> from tethersim.analysis.tethers import tether_loads
    >>> l1, l2 = tether_loads(ts.simulate(ts.load_preset("satI"), periods=1, progress=False))
    >>> l1.slack_fraction, l2.peak > l1.peak
    (0.0, True)
    """
    from tethersim.analysis.outcome import finite_prefix

    run = metrics_grid(res)
    n = max(1, finite_prefix(run))
    t = run.t[:n]
    g = run.tether_margins()[:n]
    tension = run.tether_tensions()[:n]
    sat = res.satellite
    out = []
    for j, fb in ((0, sat.Fb1), (1, sat.Fb2)):
        taut = g[:, j] > 0
        peak = float(tension[:, j].max())
        # re-tautening: a taut sample after a slack one starts a snap interval
        starts = np.flatnonzero(taut[1:] & ~taut[:-1]) + 1
        snap = math.nan
        for k in starts:
            end = k + int(np.argmin(taut[k:])) if not taut[k:].all() else n
            snap = max(float(tension[k:end, j].max()), 0.0 if math.isnan(snap) else snap)
        sf = fb / peak if fb > 0 and peak > 0 else math.nan
        out.append(TetherLoads(j + 1, peak, snap, int(starts.size), sf,
                               slack_fraction(t, g[:, j])))
    return tuple(out)


def loads_summary(res: SimResult) -> dict:
    """The summary lines of :func:`tether_loads` (keys carry units; NaN: none)."""
    run = metrics_grid(res)
    # what the loads could see: a bounce shorter than this is missed (module docstring)
    d = {"tether loads sampled every [s]": float(np.median(np.diff(run.t)))
         if run.t.size > 1 else math.nan}
    # the integrator's own count (both tethers), which sees every bounce the grid misses
    d["taut/slack switches located"] = res.n_switches
    for ld in tether_loads(res):
        j = ld.tether
        d[f"tether {j} peak tension [N]"] = ld.peak
        d[f"tether {j} snap tension [N]"] = ld.snap
        d[f"tether {j} safety factor to Fb{j}"] = ld.safety_factor
        d[f"tether {j} slack fraction"] = ld.slack_fraction
    return d


def line_vectors(sat, y) -> tuple:
    """Each line's vector [m] from its end to the balloon, (n, 2) for tether 1 (the
    tip-mass at +b along the boom, (sin θ, cos θ)) and tether 2 (the bus at −a), from
    planar states ``y`` (δx, δy, θ, ...; Eqs 3.10-3.11)."""
    s, c = np.sin(y[:, 2]), np.cos(y[:, 2])
    return tuple(np.stack([y[:, 0] - arm * s, y[:, 1] - arm * c], axis=1)
                 for arm in (sat.b, -sat.a))
