"""PNG of several model variants of one satellite: θ, δx, δy and θ − θ(first model).

Four stacked panels share the time axis (orbits below, hours on top, as in
tethersim/output/plots/run.py).  The last panel shows each variant's pitch difference
from the first model; the differences span many decades (exact-gravity ~1e-5
relative, the printed erratum E1 up to radians, docs/errata.md), so it uses a
symlog scale whenever the largest differences of the variants differ by more
than two decades, and a linear scale otherwise.
"""
from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np

from tethersim.experiments.compare import theta_difference
from tethersim.output.files import save_figure
from tethersim.output.plots.run import FAST_PNG, PANELS, _hours_on_top

STYLES = ("-", "--", "-.", ":")


def _diff_scale(ax, peaks) -> str:
    """Set the Δθ axis scale from the variants' largest |Δθ| [rad]; return its name."""
    from matplotlib.ticker import SymmetricalLogLocator

    peaks = [p for p in peaks if np.isfinite(p) and p > 0]
    if len(peaks) >= 2 and max(peaks) / min(peaks) > 100:
        # linear below the decade under a tenth of the smallest peak, logarithmic beyond
        linthresh = 10.0 ** np.floor(np.log10(min(peaks) / 10))
        ax.set_yscale("symlog", linthresh=linthresh, linscale=1.0)
        locator = SymmetricalLogLocator(linthresh=linthresh, base=10)
        locator.set_params(numticks=8)  # at most ~8 decades labelled per side
        ax.yaxis.set_major_locator(locator)
        return "symlog"
    return "linear"


def plot_compare(results, out_dir, name: str = "compare.png", title: str = "") -> Path:
    """Write ``out_dir/name`` for [(model, SimResult)] (first model = reference); return its path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    results = list(results)
    if not results:
        raise ValueError("plot_compare: no results")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    ref_model, ref = results[0]
    period = ref.satellite.period
    fig, axes = plt.subplots(4, 1, figsize=(10, 11), sharex=True)
    fig.subplots_adjust(left=0.1, right=0.97, top=0.885, bottom=0.05, hspace=0.12)
    for k, (model, res) in enumerate(results):
        style = {"lw": 0.9 if k == 0 else 0.8, "ls": STYLES[k % len(STYLES)], "color": f"C{k}"}
        for (attr, _), ax in zip(PANELS, axes[:3]):
            ax.plot(res.t / period, getattr(res, attr), label=model, **style)
    peaks = []
    for k, (model, res) in enumerate(results[1:], start=1):
        t, dth = theta_difference(res, ref)
        peaks.append(float(np.max(np.abs(dth))) if dth.size else np.nan)
        axes[3].plot(t / period, dth, lw=0.8, ls=STYLES[k % len(STYLES)], color=f"C{k}",
                     label=f"{model} − {ref_model}")
    scale = _diff_scale(axes[3], peaks)
    for (_, label), ax in zip(PANELS, axes[:3]):
        ax.set_ylabel(label)
    axes[3].set_ylabel(f"θ − θ({ref_model}) [rad]" + (" (symlog)" if scale == "symlog" else ""))
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    if len(results) > 1:
        axes[3].legend(loc="upper left", fontsize=8)
    _hours_on_top(axes[0], period)
    axes[-1].set_xlabel("time [orbits]")
    title = title or f"{ref.satellite.name}: model variants"
    title = "\n".join(textwrap.fill(line, 120) for line in title.splitlines())
    fig.suptitle(title, fontsize=9)
    path = out_dir / name
    save_figure(fig, path, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path
