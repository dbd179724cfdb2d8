"""deployment.png: what the catch at full length does, against the arrival speed.

Three panels over the starts of ``tethersim deploy``
(tethersim.experiments.deployment): the lines' tensions (the first catch's peak and the
run's largest) and the boom's pitch excursion against the arrival speed, log-log, the
free releases drawn at the speed they reach their lines; and the pitch of every start
against time.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.output.files import save_figure
from tethersim.output.plots.run import FAST_PNG

FILE = "deployment.png"


def plot_deployment(rows: list, pitch: list, period: float, out_dir, title: str,
                    breaking: float = 0.0) -> Path:
    """Write ``out_dir/deployment.png``; return its path.

    Parameters
    ----------
    rows : list of dict
        The deployment table's rows (tethersim.experiments.deployment.row).
    pitch : list of (ndarray, ndarray)
        Each start's (t [s], θ − θ(0) [rad]), in the order of ``rows``.
    period : float
        The orbital period [s] (the time axis is in orbits).
    out_dir : str or Path
        The folder.
    title : str
        The satellite and its lines.
    breaking : float, optional
        The lines' breaking load [N], drawn when given (> 0).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_t, ax_p, ax_th) = plt.subplots(1, 3, figsize=(15, 4.6))
    speed = np.array([r["catch_speed"] for r in rows])
    arrive = np.array([r["start"] == "arrival" for r in rows])
    for key, label, marker in (("first_peak", "first catch's peak", "o"),
                               ("peak", "largest over the run", "s")):
        y = np.array([r[key] if r[key] > 0 else math.nan for r in rows])
        ax_t.plot(speed[arrive], y[arrive], marker + "-", ms=4, label=f"{label} (arrival)")
        ax_t.plot(speed[~arrive], y[~arrive], marker, ms=8, mfc="none",
                  label=f"{label} (free release)")
    if breaking > 0:
        ax_t.axhline(breaking, color="tab:red", ls="--", lw=1, label="breaking load")
    # a log axis drops zeros (an arrival at rest): drawn as gaps
    excursion = np.array([r["excursion"] if r["excursion"] > 0 else math.nan for r in rows])
    ax_p.plot(speed[arrive], excursion[arrive], "o-", ms=4, label="arrival")
    ax_p.plot(speed[~arrive], excursion[~arrive], "o", ms=8, mfc="none", label="free release")
    ax_p.axhline(SETTLING_TOL, color="k", ls=":", lw=1, label=f"±{SETTLING_TOL:g} rad band")
    ax_p.axhline(math.pi / 2, color="tab:red", ls="--", lw=1, label="boom horizontal")
    for ax, what in ((ax_t, "tension [N]"), (ax_p, "largest |θ − θ(0)| [rad]")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("balloon's speed as its lines catch it [m/s]")
        ax.set_ylabel(what)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    for r, (t, dtheta) in zip(rows, pitch):
        unit = "m/s" if r["start"] == "arrival" else "m"
        ax_th.plot(t / period, dtheta, lw=0.8, label=f"{r['start']} {r['value']:g} {unit}")
    ax_th.set_xlabel("time [orbits]")
    ax_th.set_ylabel("θ − θ(0) [rad]")
    ax_th.grid(True, alpha=0.3)
    ax_th.legend(fontsize=6, ncol=2)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    path = save_figure(fig, Path(out_dir) / FILE, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path
