"""The tether-shape plot of a bead-chain run (docs/beads.md): each line's nodes (its
point on the boom, beads, balloon) in the orbit frame L at a few times, boom drawn between
its ends."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from tethersim.engine.result import SimResult
from tethersim.output.files import save_figure

SHAPE_FILE = "tether_shape.png"
SHAPE_TIMES = 5  # snapshots, evenly spread over the run, first and last included


def chain_nodes(res: SimResult, i: int) -> tuple:
    """(tether 1, tether 2) node positions (N + 2, 2) [m] in L at sample i, the point on the
    boom first (tethersim.model.bead_layout.attachment_points)."""
    from tethersim.model.bead_layout import attachment_points
    from tethersim.model.registry import bead_split

    n = bead_split(res.model)[1]
    y = res.states[i]
    th = y[2]
    lines = []
    for j, arm in enumerate(attachment_points(res.satellite)):
        beads = y[3 + 2 * j * n:3 + 2 * (j + 1) * n].reshape(n, 2)
        lines.append(np.vstack([(arm * np.sin(th), arm * np.cos(th)), beads, y[:2]]))
    return tuple(lines)


def boom_ends(res: SimResult, i: int) -> np.ndarray:
    """The boom's ends (bus at −a, tip-mass at b) in L at sample i, (2, 2) [m]."""
    s, th = res.satellite, res.states[i][2]
    return np.array([(arm * np.sin(th), arm * np.cos(th)) for arm in (-s.a, s.b)])


def plot_shape(res: SimResult, out_dir) -> Path:
    """Write tether_shape.png: the two lines' nodes at SHAPE_TIMES times; return its path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 7))
    idx = np.unique(np.linspace(0, res.t.size - 1, SHAPE_TIMES).round().astype(int))
    for k, i in enumerate(idx):
        colour = plt.cm.viridis(k / max(len(idx) - 1, 1))
        l1, l2 = chain_nodes(res, i)
        orbit = res.t[i] / res.satellite.period
        boom = boom_ends(res, i)
        ax.plot(boom[:, 0], boom[:, 1], color=colour, lw=2.5)
        ax.plot(l1[:, 0], l1[:, 1], "o-", color=colour, ms=3, lw=0.8,
                label=f"{orbit:.3g} orbits")
        ax.plot(l2[:, 0], l2[:, 1], "o-", color=colour, ms=3, lw=0.8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m] (+x: wake)")
    ax.set_ylabel("y [m] (+y: up)")
    ax.set_title(f"{res.satellite.name}: tethers as {res.model} (boom thick)")
    ax.legend(fontsize=8)
    path = Path(out_dir) / SHAPE_FILE
    save_figure(fig, path)
    plt.close(fig)
    return path
