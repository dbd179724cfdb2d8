"""Stability maps of a 2-D sweep (thesis Figures 5.13, 5.21-5.23, 5.27-5.28).

The steady-pitch panel's colour scale follows the data: symmetric about 0 up
to the larger of the 2nd and 98th percentiles of |θ_ss| (values beyond are
clipped, the colour bar's arrows say so), linear when that is within a few
times the ±0.05 rad band and a symmetric log (linear inside the band) when the
map spans decades; the band's edges are marked on the colour bar.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tethersim.analysis.classify import CLASS_COLORS, CLASSES, STABLE, UNDECIDED
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.experiments.sweep.store import status_names
from tethersim.output.files import save_figure
from tethersim.output.plots.run import FAST_PNG

# a marker per status other than ok (tethersim.engine.result.STATUSES) on the class map
STATUS_MARKERS = {"diverged": "^", "failed": "X", "re-entered": "v", "left-domain": "s",
                  "tether-broke": "*"}


def _edges(v):
    v = np.asarray(v, float)
    if v.size == 1:
        return np.array([v[0] - 0.5, v[0] + 0.5])
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate([[2 * v[0] - mid[0]], mid, [2 * v[-1] - mid[-1]]])


def pitch_scale(ss) -> tuple:
    """Colour norm, colour-bar label and clipping of a steady-pitch map.

    Parameters
    ----------
    ss : ndarray
        Steady-state pitch [rad]; NaN where there is none.

    Returns
    -------
    tuple of (matplotlib.colors.Normalize, str, str)
        The norm, the colour-bar label, and the colour bar's ``extend`` ("neither",
        "both", ...).
    """
    from matplotlib.colors import Normalize, SymLogNorm

    v = np.asarray(ss, float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return Normalize(-SETTLING_TOL, SETTLING_TOL), "steady-state pitch θ_ss [rad]", "neither"
    lim = float(max(abs(np.percentile(v, 2)), abs(np.percentile(v, 98))))
    lim = min(max(lim, SETTLING_TOL), math.pi)
    clipped = bool(np.any(np.abs(v) > lim * (1 + 1e-9)))
    extend = "both" if clipped else "neither"
    if lim > 4 * SETTLING_TOL:
        norm = SymLogNorm(linthresh=SETTLING_TOL, linscale=1.0, vmin=-lim, vmax=lim, base=10)
        scale = f"symmetric log, linear within ±{SETTLING_TOL:g}"
    else:
        norm, scale = Normalize(-lim, lim), "linear"
    label = scale + (f"; clipped at ±{lim:.3g} rad (2-98 % of |θ_ss|)" if clipped else "")
    return norm, label, extend


def _pitch_ticks(norm) -> list:
    """Plain ticks for the steady-pitch colour bar, within its range."""
    lim = norm.vmax
    from matplotlib.ticker import MaxNLocator

    cand = [0.0, SETTLING_TOL, 0.1, 0.3, 1.0, 3.0] if lim > 4 * SETTLING_TOL else \
        [abs(v) for v in MaxNLocator(6, symmetric=True).tick_values(-lim, lim)]
    pos = sorted({round(c, 6) for c in cand if c <= lim * (1 + 1e-9)})
    return sorted({-c for c in pos} | set(pos))


def plot_stability_map(ds, path, *, title: str = "", nominal: dict | None = None,
                       predicted=None, other=None, other_label: str = "",
                       band_slope: float | None = None) -> Path:
    """Draw the classes of ``ds`` (a 2-D sweep) and save a PNG.

    nominal: {name: edge value} marked with a star.  predicted: an array of
      predicted classes on the same grid; its stable region is outlined.
    other: another sweep's classes on the same grid (e.g. faithful RK4);
      points where it differs are crossed.  band_slope: draws y = slope·x.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch
    from matplotlib.ticker import MaxNLocator

    yname, xname = ds.stability_class.dims
    x, y = ds[xname].values, ds[yname].values
    cls = np.where(ds.done.values, ds.stability_class.values, -1).astype(float)
    cls[cls < 0] = np.nan
    cmap = ListedColormap(CLASS_COLORS)
    norm = BoundaryNorm(np.arange(len(CLASSES) + 1) - 0.5, cmap.N)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    fig.subplots_adjust(left=0.07, right=0.97, top=0.9, bottom=0.27, wspace=0.2)
    ax.pcolormesh(_edges(x), _edges(y), cls, cmap=cmap, norm=norm)
    # the steady pitch itself shows the band even where it is narrower than the grid
    # an undecided point's θ_ss is a moment of the first libration, not a steady pitch
    shown = ds.done.values & (ds.tumbled.values == 0) & (ds.stability_class.values != UNDECIDED)
    ss = np.where(shown, ds.steady_state_pitch.values, np.nan)
    norm, label, extend = pitch_scale(ss)
    im = ax2.pcolormesh(_edges(x), _edges(y), ss, cmap="coolwarm", norm=norm)
    cbar = fig.colorbar(im, ax=ax2, extend=extend, ticks=_pitch_ticks(norm))
    cbar.ax.set_yticklabels([f"{v:+.3g}" if v else "0" for v in cbar.get_ticks()], fontsize=8)
    cbar.set_label("steady-state pitch θ_ss [rad]")
    for edge in (-SETTLING_TOL, SETTLING_TOL):
        cbar.ax.axhline(edge, color="k", lw=1.5)
    if np.nanmin(ss, initial=np.inf) < 0 < np.nanmax(ss, initial=-np.inf) and min(x.size, y.size) > 1:
        ax2.contour(x, y, np.nan_to_num(ss, nan=np.pi), levels=[0.0], colors="k", linewidths=1.0)
    ax2.set_title(f"steady-state pitch (blank: tumbled or undecided); black line: θ_ss = 0\n"
                  f"colours: {label}; bar lines: the ±{SETTLING_TOL:g} rad band", fontsize=8)
    handles = [Patch(color=c, label=n.replace("_", " ")) for n, c in zip(CLASSES, CLASS_COLORS)]
    if predicted is not None:
        pred = (np.asarray(predicted) == STABLE).astype(float)
        if 0 < pred.sum() < pred.size:
            ax.contour(x, y, pred, levels=[0.5], colors="k", linewidths=1.5)
        handles.append(plt.Line2D([], [], color="k", lw=1.5, label="predicted stable\n(eigenvalues)"))
    if other is not None:
        diff = (np.asarray(other) != ds.stability_class.values) & ds.done.values
        iy, ix = np.nonzero(diff)
        ax.plot(x[ix], y[iy], "x", color="k", ms=4, mew=0.8)
        handles.append(plt.Line2D([], [], marker="x", color="k", ls="", label=other_label or "differs"))
    # a point that did not finish ok: why, by the engine's status (its class is "failed")
    names = status_names(ds)
    for status, marker in STATUS_MARKERS.items():
        iy, ix = np.nonzero(names == status)
        if ix.size:
            ax.plot(x[ix], y[iy], marker, color="w", mec="k", ms=5, ls="")
            handles.append(plt.Line2D([], [], marker=marker, color="w", mec="k", ls="",
                                      label=status))
    if band_slope is not None and np.isfinite(band_slope):
        xs = np.linspace(x.min(), x.max(), 50)
        ax.plot(xs, band_slope * xs, "w--", lw=1.2)
        handles.append(plt.Line2D([], [], color="w", ls="--", label=f"y = {band_slope:.3g} x",
                                  markeredgecolor="k"))
    if nominal:
        ax.plot(nominal.get(xname), nominal.get(yname), "*", color="w", mec="k", ms=14)
        handles.append(plt.Line2D([], [], marker="*", color="w", mec="k", ms=12, ls="",
                                  label="preset"))
    for a in (ax, ax2):
        a.xaxis.set_major_locator(MaxNLocator(5))
        a.set_xlim(_edges(x)[[0, -1]])
        a.set_ylim(_edges(y)[[0, -1]])
        a.set_xlabel(f"{xname} [{ds[xname].attrs.get('units', '')}]")
        a.set_ylabel(f"{yname} [{ds[yname].attrs.get('units', '')}]")
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=8,
              facecolor="0.85", ncol=4)
    ax.set_title(title or ds.attrs.get("title", ""), fontsize=9)
    path = Path(path)
    save_figure(fig, path, dpi=110, pil_kwargs=FAST_PNG)
    plt.close(fig)
    return path
