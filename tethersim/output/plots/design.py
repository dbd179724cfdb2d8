"""The design search's map: every design's settling margin against its worst trim, by verdict."""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.analysis.feasibility import VERDICT_COLORS
from tethersim.output.files import save_figure

REFUSED_COLOR = "#000000"


def plot_design(rows, pareto, path, tol: float, title: str = "") -> Path:
    """Draw margin (usable life − settling [h]) against worst |θ_ss| [rad]; save a PNG.

    Parameters
    ----------
    rows : list of dict
        Every evaluated design (tethersim.experiments.design_search.search).
    pareto : list of dict
        The Pareto set (re-verified rows).
    path : path-like
        PNG to write.
    tol : float
        The trim band [rad] (a dashed line).
    title : str, optional
        Figure title.

    Returns
    -------
    Path
        The file written.

    Notes
    -----
    The good corner is bottom right: a long margin, a small trim.  Each point is a design
    in its verdict's colour (designs the plan refused are not drawn: they have no runs;
    the legend counts them); the Pareto set is joined by a line, filled where the finer
    run reproduced the verdict (verified) and hollow where it did not.  Left of the
    vertical line the design does not settle before its usable life ends; above the
    dashed line its trim leaves the band.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    by_verdict = {}
    for r in rows:
        by_verdict.setdefault(r["verdict"], []).append(r)
    for v, rs in by_verdict.items():
        pts = [(r["margin_h"], r["worst_theta_ss_rad"]) for r in rs
               if math.isfinite(r.get("margin_h", math.nan))]
        label = f"{v} ({len(rs)})"
        if pts:
            ax.scatter(*zip(*pts), s=18, color=VERDICT_COLORS.get(v, REFUSED_COLOR),
                       edgecolor="#424242", linewidth=0.4, label=label, zorder=2)
        else:
            ax.scatter([], [], color=REFUSED_COLOR, label=label)
    if pareto:
        front = sorted(pareto, key=lambda r: r["margin_h"])
        ax.plot([r["margin_h"] for r in front], [r["worst_theta_ss_rad"] for r in front],
                color="#1565c0", linewidth=1.2, zorder=3,
                label="Pareto set (filled: verified by the finer run)")
        for r in front:
            ax.scatter(r["margin_h"], r["worst_theta_ss_rad"], s=60, zorder=4,
                       facecolor="#1565c0" if r.get("verified") else "none",
                       edgecolor="#1565c0", linewidth=1.4)
    ax.axhline(tol, color="#616161", linestyle="--", linewidth=0.8,
               label=f"trim band {tol:g} rad")
    ax.axvline(0.0, color="#616161", linewidth=0.8)
    ax.set_xlabel("margin: usable life − settling time [h]")
    ax.set_ylabel("worst |θ_ss| over solar min/mean/max [rad]")
    ax.set_yscale("log")
    ax.set_title(title or "design search")
    ax.legend(fontsize=7, loc="best")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    out = save_figure(fig, path, dpi=120)
    plt.close(fig)
    return out
