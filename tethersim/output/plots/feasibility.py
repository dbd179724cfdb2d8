"""The feasibility map: lifetime and settling time against altitude, coloured by verdict."""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.analysis.feasibility import VERDICT_COLORS, VERDICTS
from tethersim.output.files import save_figure


def plot_feasibility(rows, path, title: str = "") -> Path:
    """Draw lifetime and settling time [h] against altitude and save a PNG.

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
    One line pair per balloon area: the free orbit's lifetime (solid; a triangle
    where it reached the cap) and the nominal settling time (dashed; absent where
    the run did not settle).  Each lifetime marker has the point's verdict colour;
    the shaded band spans the lifetimes in solar-minimum to solar-maximum air.
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
        ax.plot(h, [r["lifetime_h"] for r in rs], "-", color=color, lw=1.2,
                label=f"lifetime, A3 = {a3:g} m²")
        lo = [min(r.get(f"lifetime_{c}_h", r["lifetime_h"]) for c in ("min", "mean", "max"))
              for r in rs]
        hi = [max(r.get(f"lifetime_{c}_h", r["lifetime_h"]) for c in ("min", "mean", "max"))
              for r in rs]
        ax.fill_between(h, lo, hi, color=color, alpha=0.12, lw=0)
        settle = [r["settling_h"] if math.isfinite(r["settling_h"]) else math.nan for r in rs]
        ax.plot(h, settle, "--", color=color, lw=1.2, label=f"settling, A3 = {a3:g} m²")
        for r in rs:
            ax.plot(r["altitude_km"], r["lifetime_h"], "^" if r["lifetime_capped"] else "o",
                    ms=8, mec="k", mew=0.5, color=VERDICT_COLORS[r["verdict"]])
    ax.set_yscale("log")
    ax.set_xlabel("start altitude [km]")
    ax.set_ylabel("time [h]")
    ax.grid(True, which="both", alpha=0.3)
    seen = [v for v in VERDICTS if any(r["verdict"] == v for r in rows)]
    handles, labels = ax.get_legend_handles_labels()
    handles += [Line2D([], [], ls="", marker="o", ms=8, mec="k", mew=0.5,
                       color=VERDICT_COLORS[v]) for v in seen]
    labels += seen
    ax.legend(handles, labels, fontsize=8, loc="best")
    ax.set_title(title or "Does the design work in a real orbit?", fontsize=10)
    fig.tight_layout()
    path = Path(path)
    save_figure(fig, path, dpi=110)
    plt.close(fig)
    return path
