"""Roll and yaw after an out-of-plane disturbance, one line per damper model (docs/roll.md)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from tethersim.output.files import save_figure


def plot_roll_responses(responses: dict, path, title: str = "") -> Path:
    """Draw roll φ and yaw ψ [deg] against time [orbits] and save a PNG.

    Parameters
    ----------
    responses : dict
        {label: :class:`tethersim.analysis.roll.RollResponse`}, one line each.
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
    Roll (top) with each run's per-orbit roll peaks as markers; yaw (bottom)
    wrapped to ±180°, since a boom that keeps the spin the start gave it advances
    in yaw steadily (no torque about the boom axis).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from tethersim.output.plots.run import FAST_PNG

    fig, (ax_r, ax_y) = plt.subplots(2, 1, figsize=(8.0, 5.6), sharex=True)
    for i, (label, r) in enumerate(responses.items()):
        res = r.result
        P = res.satellite.period
        orbits = res.t / P
        color, z = f"C{i}", len(responses) - i  # the first on top
        ax_r.plot(orbits, np.degrees(res.series("phi")), color=color, lw=0.6, alpha=0.8,
                  label=label, zorder=z)
        peaks = np.degrees(r.orbit_peaks["phi"])
        ax_r.plot(np.arange(peaks.size) + 0.5, peaks, "o", ms=3, color=color, zorder=z + 10)
        psi = np.degrees(np.angle(np.exp(1j * res.series("psi"))))
        ax_y.plot(orbits, psi, ".", ms=1, color=color, label=label, zorder=z)
    ax_r.set_ylabel("roll φ [deg]")
    ax_y.set_ylabel("yaw ψ [deg], wrapped")
    ax_y.set_xlabel("time [orbits]")
    ax_y.set_ylim(-180, 180)
    for ax in (ax_r, ax_y):
        ax.grid(True, alpha=0.3)
    ax_r.legend(fontsize=8, loc="upper right")
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    save_figure(fig, path, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path
