"""PNG plots of the force breakdown (thesis Figures 5.7-5.20, pp. 5-8 to 5-17).

One figure per generalized coordinate: every family's generalized force against
time in orbits (hours on the top axis), and below it a "zoomed" panel with only
the small families (peak below 10 % of the largest on that coordinate) on their
own y-scale, as the thesis's zoomed figures (5.8, 5.10, 5.12, 5.16, 5.18, 5.20).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from tethersim.analysis.force_peaks import SMALL_FRACTION, coordinates, peaks, small_families
from tethersim.engine.result import SimResult
from tethersim.generated.layout import FAMILIES
from tethersim.output.files import save_figure
from tethersim.output.plots.run import FAST_PNG, _hours_on_top

# one colour per tether / body, solid drag, dashed spring, dotted damper
STYLE = {"drag1": ("tab:blue", "-"), "drag2": ("tab:orange", "-"), "drag3": ("tab:green", "-"),
         "spring1": ("tab:red", "--"), "spring2": ("tab:purple", "--"),
         "damper1": ("tab:red", ":"), "damper2": ("tab:purple", ":")}
THESIS_FIGURES = {"delta_x": "5.7-5.8, 5.15-5.16", "delta_y": "5.9-5.10, 5.17-5.18",
                  "theta": "5.11-5.12, 5.19-5.20"}


def file_name(coordinate: str) -> str:
    """The figure of one coordinate's forces: forces_delta_x.png, forces_theta.png, ..."""
    return f"forces_{coordinate}.png"


def plot_forces(res: SimResult, out_dir, Q: np.ndarray | None = None) -> list:
    """Write forces_<coordinate>.png for each coordinate of the run's model (delta_x,
    delta_y, theta; in 3-D also delta_z, phi, psi; on a free orbit r, nu); return the paths."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    Q = res.forces if Q is None else Q
    pk = peaks(Q)
    period = res.satellite.period
    orbits = res.t / period
    paths = []
    for k, (name, symbol, unit) in enumerate(coordinates(res.layout)):
        fig, (ax, zoom) = plt.subplots(2, 1, figsize=(11, 7), sharex=True)
        # fixed margins, no layout engine: one draw per savefig (as tethersim/output/plots/run.py)
        fig.subplots_adjust(left=0.1, right=0.76, top=0.86, bottom=0.08, hspace=0.1)
        small = small_families(Q, k)
        for f, fam in enumerate(FAMILIES):
            color, ls = STYLE[fam]
            zero = pk[f, k] == 0.0
            label = f"{fam} (≡ 0)" if zero else f"{fam} (max {pk[f, k]:.3g} {unit})"
            ax.plot(orbits, Q[:, f, k], color=color, ls=ls, lw=0.8, label=label)
            if f in small:  # matplotlib's path simplification keeps this fast at 50k samples
                zoom.plot(orbits, Q[:, f, k], color=color, ls=ls, lw=0.8, label=label)
        kind = "force" if unit == "N" else "torque"
        ax.set_ylabel(f"generalized {kind} on {symbol} [{unit}]")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
        ax.grid(alpha=0.3)
        if small:
            zoom.set_ylabel(f"zoomed: families < {SMALL_FRACTION:.0%} of peak [{unit}]")
            zoom.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
        else:
            zoom.text(0.5, 0.5, f"every family reaches {SMALL_FRACTION:.0%} of the peak: "
                      "nothing to zoom", transform=zoom.transAxes, ha="center", va="center")
        zoom.grid(alpha=0.3)
        zoom.set_xlabel("time [orbits]")
        _hours_on_top(ax, period)
        thesis = f" (cf. thesis Figs {THESIS_FIGURES[name]})" if name in THESIS_FIGURES else ""
        ax.set_title(f"{res.satellite.name}: forces on {symbol} by family{thesis}\n"
                     f"{res.label}", fontsize=9)
        p = out_dir / file_name(name)
        save_figure(fig, p, dpi=110, pil_kwargs=FAST_PNG)
        plt.close(fig)
        paths.append(p)
    return paths
