"""The feasibility map: balloon lost, re-entry and settling time against altitude, by verdict."""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.analysis.feasibility import SENSITIVE, VERDICT_COLORS, VERDICTS
from tethersim.output.files import save_figure

_MARKERS = {SENSITIVE: "D"}


def usable_life_h(r: dict, case: str = "") -> float:
    """A row's usable life [h]: balloon lost, else re-entry (``case``: a solar case's)."""
    suffix = f"_{case}" if case else ""
    lost = r.get(f"balloon_lost{suffix}_h", math.nan)
    return lost if math.isfinite(lost) else r.get(f"reentry{suffix}_h", math.nan)


def _marker(r: dict) -> str:
    if r["verdict"] in _MARKERS:
        return _MARKERS[r["verdict"]]
    return "^" if r["reentry_capped"] and not math.isfinite(r["balloon_lost_h"]) else "o"


def plot_feasibility(rows, path, title: str = "") -> Path:
    """Draw balloon-lost, re-entry and settling times [h] against altitude; save a PNG.

    Parameters
    ----------
    rows : list of dict
        Rows of :func:`tethersim.experiments.feasibility.run_feasibility`.
    path : path-like
        PNG to write.
    title : str, optional
        Figure title.

    Returns
    -------
    Path
        The file written.

    Notes
    -----
    One line set per balloon area: when the free orbit loses its balloon (solid),
    when it re-enters (dotted; after the release, docs/feasibility.md) and the
    nominal settling time (dashed; absent where the run did not settle).  A marker
    at the end of each point's usable life (the first of the two) has the point's
    verdict colour: a triangle where the free run reached the cap, a diamond where
    the verdict is ``sensitive`` (it changed between the two tolerances), a hollow
    circle where it is ``undecided: run longer``.  The shaded band spans the usable
    lives in solar-minimum to solar-maximum air.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    areas = sorted({r["A3_m2"] for r in rows})
    for i, a3 in enumerate(areas):
        rs = sorted((r for r in rows if r["A3_m2"] == a3), key=lambda r: r["altitude_km"])
        h = [r["altitude_km"] for r in rs]
        color = f"C{i}"
        ax.plot(h, [r["balloon_lost_h"] for r in rs], "-", color=color, lw=1.2,
                label=f"balloon lost, A3 = {a3:g} m²")
        ax.plot(h, [r["reentry_h"] for r in rs], ":", color=color, lw=1.4,
                label=f"re-entry, A3 = {a3:g} m²")
        lives = [[usable_life_h(r, c) for c in ("min", "mean", "max")] for r in rs]
        ax.fill_between(h, [min(v) for v in lives], [max(v) for v in lives], color=color,
                        alpha=0.12, lw=0)
        settle = [r["settling_h"] if math.isfinite(r["settling_h"]) else math.nan for r in rs]
        ax.plot(h, settle, "--", color=color, lw=1.2, label=f"settling, A3 = {a3:g} m²")
        for r in rs:
            ax.plot(r["altitude_km"], usable_life_h(r), _marker(r), ms=8, mec="k", mew=0.8,
                    color=VERDICT_COLORS[r["verdict"]])
    ax.set_yscale("log")
    ax.set_xlabel("start altitude [km]")
    ax.set_ylabel("time [h]")
    ax.grid(True, which="both", alpha=0.3)
    seen = [v for v in VERDICTS if any(r["verdict"] == v for r in rows)]
    handles, labels = ax.get_legend_handles_labels()
    handles += [Line2D([], [], ls="", marker=_MARKERS.get(v, "o"), ms=8, mec="k", mew=0.8,
                       color=VERDICT_COLORS[v]) for v in seen]
    labels += seen
    ax.legend(handles, labels, fontsize=8, loc="best")
    ax.set_title(title or "Does the design work in a real orbit?", fontsize=10)
    fig.tight_layout()
    path = Path(path)
    save_figure(fig, path, dpi=110)
    plt.close(fig)
    return path
