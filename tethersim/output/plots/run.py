"""PNG plots of a result: θ, δx, δy against time (orbits below, hours above);
for a 3-D model also roll φ, yaw ψ and the balloon's out-of-plane δz; for a free orbit the
altitude; for every run the tethers' tensions (tensions.png).

The pitch panel marks θ_ss, the thesis's ±0.05 rad band about it and the settling
time.  The balloon's taut-tether bounce (period ~70-80 s) is far faster than the
plot's resolution and often than the sampling, so δx and δy are drawn as their
range (rolling min-max) and mean over two tether periods, with an inset zoom of
the first two orbits, where that oscillation is large.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.analysis.outcome import outcome
from tethersim.engine.result import SimResult
from tethersim.output.files import save_figure

FAST_PNG = {"compress_level": 1}  # zlib level 1: a third of the encode time, ~1.3x the bytes
PANELS = (("theta", "pitch θ [rad]"), ("x", "balloon δx [m] (+x: wake)"),
          ("y", "balloon δy [m] (+y: up)"))
# drawn when the model has these states (3-D models; docs/roll.md)
PANELS_3D = (("phi", "roll φ [rad]"), ("psi", "yaw ψ [rad] (about the boom)"),
             ("delta_z", "balloon δz [m] (+z: orbit normal)"))
FILE_NAMES = {"theta": "theta", "x": "delta_x", "y": "delta_y", "phi": "roll", "psi": "yaw",
              "delta_z": "delta_z"}


ZOOM_ORBITS = 2.0  # inset: the first orbits, where the tether bounce is large


def tether_period(res: SimResult) -> float:
    """Period [s] of the fastest taut-tether mode of the run's satellite (NaN if none)."""
    from tethersim.engine.linearise import taut_tether_modes

    w = float(np.max(np.abs(np.imag(taut_tether_modes(res.satellite)))))
    return 2 * math.pi / w if w > 0 else math.nan


def envelope(t, y, window: float) -> tuple:
    """Rolling (min, mean, max) of ``y`` over ``window`` seconds, centred.

    Parameters
    ----------
    t, y : ndarray
        Sample times [s] (uniform or not) and values.
    window : float
        Width of the window [s]; at least three samples are taken.

    Returns
    -------
    tuple of ndarray
        Lower envelope, rolling mean and upper envelope, each the size of ``y``.
    """
    y = np.asarray(y, float)
    dt = float(np.median(np.diff(t))) if len(t) > 1 else window
    n = max(3, int(math.ceil(window / dt)) | 1)  # odd, so the window is centred
    if y.size < n:
        return y, y, y
    pad = np.pad(y, n // 2, mode="edge")
    win = np.lib.stride_tricks.sliding_window_view(pad, n)
    return win.min(axis=1), win.mean(axis=1), win.max(axis=1)


def _draw_fast(ax, res, orbits, y, label, zoom: bool):
    """δx or δy as a min-max band and a mean over two tether periods (+ an inset zoom)."""
    tp = tether_period(res)
    if not math.isfinite(tp) or res.t.size < 10:
        ax.plot(orbits, y, lw=0.8)
        return
    lo, mean, hi = envelope(res.t, y, 2 * tp)
    ax.fill_between(orbits, lo, hi, color="tab:blue", alpha=0.3, lw=0,
                    label=f"range over 2 tether periods (2 × {tp:.0f} s)")
    ax.plot(orbits, mean, lw=0.9, color="tab:blue", label="mean over 2 tether periods")
    ax.legend(loc="lower right", fontsize=8)
    if not zoom or orbits[-1] < 3 * ZOOM_ORBITS:
        return
    first = orbits <= ZOOM_ORBITS
    # room for the inset: the data right of mid-axis stay in the lower 45 %
    right = orbits >= orbits[0] + 0.5 * (orbits[-1] - orbits[0])
    y0, y1 = ax.get_ylim()
    ax.set_ylim(y0, max(y1, y0 + (float(np.nanmax(hi[right])) - y0) / 0.45))
    ins = ax.inset_axes([0.55, 0.6, 0.43, 0.32])
    ins.fill_between(orbits[first], lo[first], hi[first], color="tab:blue", alpha=0.3, lw=0)
    ins.plot(orbits[first], y[first], lw=0.5, color="tab:blue", alpha=0.8)
    ins.plot(orbits[first], mean[first], lw=0.9, color="k")
    ins.set_title(f"first {ZOOM_ORBITS:g} orbits (samples every "
                  f"{float(np.median(np.diff(res.t))):.0f} s)", fontsize=7)
    ins.tick_params(labelsize=7)
    ins.grid(alpha=0.3)


def _hours_on_top(ax, period):
    top = ax.secondary_xaxis("top", functions=(lambda o: o * period / 3600,
                                               lambda h: h * 3600 / period))
    top.set_xlabel("time [hours]")


def plot_result(res: SimResult, out_dir, prefix: str = "") -> list:
    """Write theta.png, delta_x.png, delta_y.png, overview.png and tensions.png; return
    the paths.

    A 3-D model adds roll.png, yaw.png and delta_z.png (and their overview panels);
    a free-orbit model adds altitude.png (:func:`plot_altitude`).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    period = res.satellite.period
    orbits = res.t / period
    paths = []
    panels = PANELS + tuple(pn for pn in PANELS_3D if pn[0] in res.layout.state)
    fig_all, axes = plt.subplots(len(panels), 1, figsize=(10, 3 * len(panels)), sharex=True)
    # fixed margins instead of a layout engine: one draw per savefig, half the time
    top, bottom = (0.9, 0.06) if len(panels) == 3 else (0.95, 0.03)
    fig_all.subplots_adjust(left=0.09, right=0.97, top=top, bottom=bottom, hspace=0.12)
    for (attr, label), ax_all in zip(panels, axes):
        fig, ax = plt.subplots(figsize=(10, 4))
        fig.subplots_adjust(left=0.09, right=0.97, top=0.78, bottom=0.13)
        for a in (ax, ax_all):
            if attr == "theta":
                a.plot(orbits, res.theta, lw=0.8)
            elif attr in ("phi", "psi"):
                a.plot(orbits, res.series(attr), lw=0.8)
            elif attr == "delta_z":
                _draw_fast(a, res, orbits, res.series(attr), label, zoom=True)
            else:
                _draw_fast(a, res, orbits, getattr(res, attr), label, zoom=True)
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
        name = FILE_NAMES[attr]
        p = out_dir / f"{prefix}{name}.png"
        save_figure(fig, p, dpi=120, pil_kwargs=FAST_PNG)
        plt.close(fig)
        paths.append(p)
    _hours_on_top(axes[0], period)
    axes[-1].set_xlabel("time [orbits]")
    fig_all.suptitle(res.label, fontsize=9)
    p = out_dir / f"{prefix}overview.png"
    save_figure(fig_all, p, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig_all)
    paths.append(p)
    paths.append(plot_tensions(res, out_dir / f"{prefix}{TENSIONS_FILE}"))
    if res.layout.orbit == "free":
        paths.append(plot_altitude(res, out_dir / f"{prefix}altitude.png"))
    return paths


TENSIONS_FILE = "tensions.png"


def plot_tensions(res: SimResult, path) -> Path:
    """Write the tethers' tensions [N] against time, with each breaking load that is set,
    peak and snap tension and slack fraction in the legend (analysis/tethers.py); return
    the path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from tethersim.analysis.tethers import metrics_grid, tether_loads

    run = metrics_grid(res)
    sat, period = res.satellite, res.satellite.period
    tension = run.tether_tensions()
    fig, ax = plt.subplots(figsize=(10, 4))
    fig.subplots_adjust(left=0.09, right=0.97, top=0.78, bottom=0.13)
    for ld, color, fb in zip(tether_loads(res), ("tab:blue", "tab:orange"), (sat.Fb1, sat.Fb2)):
        j = ld.tether
        snap = f", snap {ld.snap:.3g} N" if math.isfinite(ld.snap) else ""
        ax.plot(run.t / period, tension[:, j - 1], lw=0.8, color=color,
                label=f"tether {j}: peak {ld.peak:.3g} N{snap}, slack "
                      f"{100 * ld.slack_fraction:.3g} % of the time")
        if fb > 0:
            ax.axhline(fb, color=color, ls="--", lw=0.8,
                       label=f"Fb{j} = {fb:.4g} N (safety factor {ld.safety_factor:.3g})")
    ax.set_xlabel("time [orbits]")
    ax.set_ylabel("tension [N]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    _hours_on_top(ax, period)
    ax.set_title(f"{sat.name}: tether tensions ({run.t.size} samples)\n{res.label}", fontsize=9)
    path = Path(path)
    save_figure(fig, path, dpi=120, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path


def plot_altitude(res: SimResult, path) -> Path:
    """Write the boom COM's altitude [km] against time of a free-orbit run, with the
    re-entry altitude; return the path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    period = res.satellite.period
    fig, ax = plt.subplots(figsize=(10, 4))
    fig.subplots_adjust(left=0.09, right=0.97, top=0.78, bottom=0.13)
    ax.plot(res.t / period, res.altitude / 1e3, lw=0.8, label="boom COM")
    ax.axhline(res.satellite.reentry_altitude / 1e3, color="tab:red", ls="--", lw=0.8,
               label=f"re-entry altitude {res.satellite.reentry_altitude / 1e3:g} km")
    ax.set_xlabel("time [orbits]")
    ax.set_ylabel("altitude [km]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8)
    _hours_on_top(ax, period)
    ax.set_title(f"{res.satellite.name}: altitude ({res.status})\n{res.label}", fontsize=9)
    path = Path(path)
    fig.savefig(path, dpi=120, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path
