"""PNG plots of a result: θ, δx, δy against time (orbits below, hours above)."""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.analysis.outcome import outcome
from tethersim.engine.result import SimResult

FAST_PNG = {"compress_level": 1}  # zlib level 1: a third of the encode time, ~1.3x the bytes
PANELS = (("theta", "pitch θ [rad]"), ("x", "balloon δx [m] (+x: wake)"),
          ("y", "balloon δy [m] (+y: up)"))


def _hours_on_top(ax, period):
    top = ax.secondary_xaxis("top", functions=(lambda o: o * period / 3600,
                                               lambda h: h * 3600 / period))
    top.set_xlabel("time [hours]")


def plot_result(res: SimResult, out_dir, prefix: str = "") -> list:
    """Write theta.png, delta_x.png, delta_y.png and overview.png; return the paths."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    period = res.satellite.period
    orbits = res.t / period
    paths = []
    fig_all, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
    # fixed margins instead of a layout engine: one draw per savefig, half the time
    fig_all.subplots_adjust(left=0.09, right=0.97, top=0.9, bottom=0.06, hspace=0.12)
    for (attr, label), ax_all in zip(PANELS, axes):
        fig, ax = plt.subplots(figsize=(10, 4))
        fig.subplots_adjust(left=0.09, right=0.97, top=0.78, bottom=0.13)
        for a in (ax, ax_all):
            a.plot(orbits, getattr(res, attr), lw=0.8)
            a.set_ylabel(label)
            a.grid(alpha=0.3)
        if attr == "theta":
            m = outcome(res, forces=False).metrics
            for a in (ax, ax_all) if m is not None else ():
                a.axhline(m.steady_state_pitch, color="k", ls="--", lw=0.7,
                          label=f"steady state {m.steady_state_pitch:.3f} rad")
                # the thesis's stability band (±0.05 rad about θ_ss, p. 5-18) and settling
                a.axhspan(m.steady_state_pitch - SETTLING_TOL, m.steady_state_pitch + SETTLING_TOL,
                          color="tab:green", alpha=0.15, lw=0,
                          label=f"±{SETTLING_TOL:g} rad band")
                if math.isfinite(m.settling_time):
                    a.axvline(m.settling_time / period, color="tab:green", lw=1.0,
                              label=f"settled at {m.settling_time / 3600:.1f} h")
                a.legend(loc="upper right", fontsize=8)
        ax.set_xlabel("time [orbits]")
        _hours_on_top(ax, period)
        ax.set_title(f"{res.satellite.name}: {label.split(' [')[0]}\n{res.label}", fontsize=9)
        name = {"theta": "theta", "x": "delta_x", "y": "delta_y"}[attr]
        p = out_dir / f"{prefix}{name}.png"
        fig.savefig(p, dpi=120, pil_kwargs=FAST_PNG)
        plt.close(fig)
        paths.append(p)
    _hours_on_top(axes[0], period)
    axes[-1].set_xlabel("time [orbits]")
    fig_all.suptitle(res.label, fontsize=9)
    p = out_dir / f"{prefix}overview.png"
    fig_all.savefig(p, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig_all)
    paths.append(p)
    return paths
