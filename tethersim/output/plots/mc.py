"""Monte Carlo plots: the distributions of settling time and lifetime, and the Sobol' indices."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tethersim.output.files import save_figure


def _ecdf(ax, hours, censored_at: float, label: str, color: str) -> None:
    """Step ECDF of ``hours`` (inf: censored, drawn as the curve staying below 1 at the cap)."""
    x = np.sort(np.asarray(hours, dtype=float))
    n = x.size
    finite = x[np.isfinite(x)]
    censored = finite.size < n
    if finite.size:  # with censored samples the curve runs on flat to the censoring line
        ends = np.r_[finite, censored_at] if censored else finite
        ax.step(ends, np.r_[np.arange(1, finite.size + 1), finite.size][:ends.size] / n,
                where="post", color=color, label=label)
    if censored or not finite.size:
        ax.axvline(censored_at, color="0.6", ls=":", lw=1)


def plot_distributions(rows, path, *, run_h: float, cap_h: float, title: str = "") -> Path:
    """ECDFs and histograms of settling time and lifetime [h] of the random samples.

    A run that never settled within ``run_h``, or a life past ``cap_h``, is censored:
    the ECDF stops below 1 at the dotted line and the histogram leaves it out (the
    title of each panel says how many).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    samples = [r for r in rows if r["part"] == "sample"]
    settle = np.array([r["settling_time_s"] / 3600 if math.isfinite(r["settling_time_s"])
                       else math.inf for r in samples])
    life = np.array([math.inf if r["life_end"] == "capped" else r["lifetime_s"] / 3600
                     for r in samples])
    fig, axes = plt.subplots(2, 2, figsize=(9, 6.4))
    for col, (values, cap, name, color) in enumerate(
            ((settle, run_h, "settling time", "#1565c0"), (life, cap_h, "lifetime", "#c62828"))):
        finite = values[np.isfinite(values)]
        _ecdf(axes[0, col], values, cap, name, color)
        axes[0, col].set(xlabel=f"{name} [h]", ylabel="fraction of samples <= x", ylim=(0, 1.02),
                         title=f"{name}: {values.size - finite.size} of {values.size} beyond "
                               f"{cap:.3g} h")
        if finite.size:
            axes[1, col].hist(finite, bins=max(5, min(40, int(np.sqrt(finite.size)) + 1)),
                              color=color, alpha=0.8)
        axes[1, col].set(xlabel=f"{name} [h]", ylabel="samples")
    ends = {}
    for r in samples:
        ends[r["life_end"]] = ends.get(r["life_end"], 0) + 1
    axes[1, 1].set_title("life ends: " + ", ".join(f"{k} {v}" for k, v in sorted(ends.items())),
                         fontsize=9)
    fig.suptitle(title)
    fig.tight_layout()
    out = save_figure(fig, path, dpi=120)
    plt.close(fig)
    return out


def plot_sobol(sobol: dict, path, title: str = "") -> Path:
    """Bars of the first-order (S1) and total (ST) Sobol' indices of each output on each
    input, with their bootstrap 95 % intervals."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    outputs = list(sobol)
    fig, axes = plt.subplots(len(outputs), 1, figsize=(8, 2.4 * len(outputs) + 0.6),
                             squeeze=False)
    for ax, output in zip(axes[:, 0], outputs):
        names = list(sobol[output])
        x = np.arange(len(names))
        for off, kind, color in ((-0.2, "S1", "#1565c0"), (0.2, "ST", "#ef6c00")):
            v = np.array([sobol[output][k][kind] for k in names])
            err = np.array([sobol[output][k][f"{kind}_conf"] for k in names])
            ax.bar(x + off, np.nan_to_num(v), 0.4, yerr=np.nan_to_num(err), color=color,
                   label="first-order S1" if kind == "S1" else "total ST", capsize=2)
        ax.set_xticks(x, names, fontsize=8, rotation=20)
        ax.axhline(0, color="0.4", lw=0.6)
        ax.set_ylabel("index")
        ax.set_title(output + ("" if np.isfinite([sobol[output][k]["S1"] for k in names]).any()
                               else " (no variance: no indices)"), fontsize=9)
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    out = save_figure(fig, path, dpi=120)
    plt.close(fig)
    return out
