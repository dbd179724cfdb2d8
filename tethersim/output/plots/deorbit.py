"""The de-orbit plot: lifetime against start altitude, with and without the balloon."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from tethersim.output.files import save_figure

YEAR = 365.25 * 86400.0


def plot_deorbit(result: dict, path, title: str = "") -> Path:
    """P50 lifetime [years] against altitude [km] with P10-P90 bands, with and without the
    balloon; the 5- and 25-year rules; the altitude band where the balloon turns from
    trailing to hanging.  A censored life (beyond the cap) is drawn at the cap."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = result["rows"]
    h = np.array([r["altitude"] for r in rows]) / 1e3
    cap = result["max_years"]
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for key, label, color in (("with", "with balloon", "#1565c0"),
                              ("without", "host alone", "#c62828")):
        q = {p: np.minimum(np.array([r[f"{key}_{p}"][0] for r in rows]) / YEAR, cap)
             for p in ("p10", "p50", "p90")}
        ax.plot(h, q["p50"], "o-", color=color, label=f"{label}: P50")
        ax.fill_between(h, q["p10"], q["p90"], color=color, alpha=0.2,
                        label=f"{label}: P10-P90 over epochs")
    for years, style in ((25, "--"), (5, ":")):
        ax.axhline(years, color="0.3", ls=style, lw=1, label=f"{years}-year rule")
    ax.axhline(cap, color="0.6", lw=0.8)
    t = result["trail"]
    ax.axvspan(min(t.values()) / 1e3, max(t.values()) / 1e3, color="#ffb300", alpha=0.15,
               label="trails below / hangs above (ε = 1, thin to dense air)")
    ax.axvline(t["median"] / 1e3, color="#ffb300", lw=1.2)
    ax.set_yscale("log")
    ax.set(xlabel="start altitude [km]", ylabel="time to re-entry [years]",
           title=title or "lifetime with and without the balloon")
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    out = save_figure(fig, path, dpi=120)
    plt.close(fig)
    return out
