"""Figures of the headline study (tethersim.experiments.headlines; docs/headlines.md).

plot_cases: one PNG per case, θ(t) [rad] against time [orbits], one panel per
model variant, the four schemes overlaid (DOP853 converged, RK4 at the
thesis's step, at 1/2 and 1/4 of it).  plot_damping_scan, plot_step_scan: the
scans over the damping factor and the RK4 step.  Matplotlib Agg, small PNGs.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from tethersim.analysis.classify import CLASS_COLORS, CLASSES
from tethersim.output.files import replacing

DPI = 90
STYLE = {"dop853": {"color": "k", "lw": 2.2, "alpha": 0.55, "label": "DOP853 (converged)"},
         "rk4-thesis": {"color": "#c62828", "lw": 0.9, "label": "RK4, thesis step"},
         "rk4-half": {"color": "#1565c0", "lw": 0.9, "ls": "--", "label": "RK4, 1/2 step"},
         "rk4-quarter": {"color": "#2e7d32", "lw": 0.9, "ls": ":", "label": "RK4, 1/4 step"}}
YLIM = 2 * math.pi + 0.6  # rad: a diverged run is drawn up to where it leaves this band


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _slug(name: str) -> str:
    """File-name form of a case name: "E1+50%" -> "e1p50pc", "damping-x10" -> "damping_x10"."""
    out = []
    for i, ch in enumerate(name):
        nxt = name[i + 1] if i + 1 < len(name) else ""
        out.append({"+": "p", "%": "pc", " ": "_"}.get(ch, "m" if ch == "-" and nxt.isdigit()
                                                        else "_" if ch == "-" else ch))
    return "".join(out).lower()


def _save(fig, path) -> Path:
    """Save at DPI as a 256-colour palette PNG (a third of the RGBA size)."""
    import io

    from PIL import Image

    plt = _plt()
    buf = io.BytesIO()
    fig.savefig(buf, dpi=DPI, format="png")
    plt.close(fig)
    buf.seek(0)
    path = Path(path)
    with Image.open(buf) as im, replacing(path) as tmp:
        im.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT).save(
            tmp, optimize=True)
    return path


def plot_case(rows: list, path) -> Path:
    """θ(t) of one case: a panel per model, the schemes overlaid."""
    plt = _plt()
    models = list(dict.fromkeys(r["model"] for r in rows))
    fig, axes = plt.subplots(1, len(models), figsize=(4.2 * len(models), 3.4), sharey=True,
                             squeeze=False)
    axes = axes[0]
    lo = min(min(r["theta_min"] for r in rows), -0.7)
    hi = max(max(r["theta_max"] for r in rows), 0.7)
    lo, hi = max(lo, -YLIM), min(hi, YLIM)
    for ax, model in zip(axes, models):
        mine = [r for r in rows if r["model"] == model]
        for r in sorted(mine, key=lambda r: r["scheme"] != "dop853"):
            t = r["_t"] / r["_period"]
            th = r["_theta"]
            keep = np.isfinite(th) & (np.abs(th) < YLIM)
            cut = np.argmin(keep) if not keep.all() else th.size
            st = STYLE.get(r["scheme"], {})
            ax.plot(t[:cut], th[:cut], **st)
            if cut < th.size:
                ax.plot(t[cut - 1], th[cut - 1], "x", color=st.get("color", "k"), ms=8)
        for y in (0.0, math.pi, -math.pi):
            ax.axhline(y, color="0.6", lw=0.6, ls="-" if y == 0 else "--")
        ax.set_ylim(lo - 0.2, hi + 0.2)
        ax.set_xlabel("time [orbits]")
        ax.grid(alpha=0.25)
        cls = {r["scheme"]: r["class"] for r in mine}
        ax.set_title(f"{model}\nDOP853: {cls.get('dop853', '?')}; RK4 thesis step: "
                     f"{cls.get('rk4-thesis', '?')}", fontsize=8.5)
    axes[0].set_ylabel("pitch θ [rad]")
    axes[0].legend(fontsize=7, loc="best")
    r0 = rows[0]
    fig.suptitle(f"SatI {r0['case']} (thesis p. {r0['page']}; {r0['change']}), "
                 f"thesis step {r0['step_thesis_s']:.2f} s", fontsize=9.5)
    fig.subplots_adjust(left=0.07, right=0.99, top=0.78, bottom=0.15, wspace=0.06)
    return _save(fig, path)


def plot_cases(rows: list, out_dir, prefix: str = "headlines_") -> list:
    """One PNG per case: ``{prefix}{case}.png`` in out_dir; returns the paths."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for case in dict.fromkeys(r["case"] for r in rows):
        paths.append(plot_case([r for r in rows if r["case"] == case],
                               out_dir / f"{prefix}{_slug(case)}.png"))
    return paths


MARK = {"derived": "o", "printed": "s", "objective-damper": "^"}


def plot_damping_scan(rows: list, path) -> Path:
    """θ_ss vs damping factor (converged, faithful RK4), equilibria, RK4 limits."""
    plt = _plt()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 3.9))
    models = list(dict.fromkeys(r["model"] for r in rows))
    for m in models:
        rs = [r for r in rows if r["model"] == m]
        f = np.array([r["factor"] for r in rs])
        a1.plot(f, [r["eq0_theta"] for r in rs], "-", color="0.4", lw=0.8)
        a1.plot(f, [(r["eqpi_theta"] % (2 * math.pi)) for r in rs], "-", color="0.4", lw=0.8)
        a1.plot(f, [r["dop853_theta_ss"] for r in rs], MARK.get(m, "o"), mfc="none",
                color="k", ms=6, label=f"{m}: converged θ_ss")
        for r in rs:
            code = CLASSES.index(r["rk4-thesis_class"])
            y = r["rk4-thesis_theta_ss"] if code != 5 else 3.9
            if code != 5 and y < -math.pi / 2:
                y += 2 * math.pi
            a1.plot(r["factor"], y, "x" if code == 5 else MARK.get(m, "o"),
                    color=CLASS_COLORS[code], ms=4)
        a2.plot(f, [r["rk4_max_step_s"] for r in rs], MARK.get(m, "o") + "-", ms=3, lw=0.8,
                label=m)
    a1.axhline(math.pi, color="0.6", ls="--", lw=0.6)
    a1.plot(10, 3.18, "*", color="#c62828", ms=11, label="thesis p. 5-13: x10 -> 3.18 rad")
    a1.text(1.05, 3.9, "× RK4 failed", fontsize=7, va="center")
    a1.set_xscale("log")
    a1.set_ylim(-0.6, 4.1)
    a1.set_xlabel("damping factor (c1, c2 × factor of the preset's 3e-4 N s/m)")
    a1.set_ylabel("θ [rad] (θ < −π/2 shown + 2π)")
    a1.set_title("hollow: converged θ_ss; filled: thesis RK4 (26.55 s), colour = class;\n"
                 "grey lines: equilibria near 0 and near π (continued in the factor)", fontsize=8)
    a1.legend(fontsize=7, loc="center left")
    a1.grid(alpha=0.25)
    h = rows[0]["step_s"]
    a2.axhline(h, color="#c62828", lw=1, label=f"thesis step {h:.2f} s")
    a2.set_xscale("log")
    a2.set_xlabel("damping factor")
    a2.set_ylabel("largest stable RK4 step [s]")
    a2.set_title("linear RK4 stability limit (tether modes included)", fontsize=8)
    a2.legend(fontsize=7)
    a2.grid(alpha=0.25)
    handles = [plt.Line2D([], [], ls="", marker="o", color=c, label=n)
               for n, c in zip(CLASSES, CLASS_COLORS)]
    fig.legend(handles=handles, loc="lower center", ncol=len(CLASSES), fontsize=7, frameon=False)
    fig.subplots_adjust(left=0.07, right=0.99, top=0.86, bottom=0.25, wspace=0.22)
    return _save(fig, path)


def plot_step_scan(rows: list, path) -> Path:
    """Class of the faithful RK4 run against its step, one row of dots per model."""
    plt = _plt()
    models = list(dict.fromkeys(r["model"] for r in rows))
    fig, ax = plt.subplots(figsize=(9, 1.2 + 0.55 * len(models)))
    for i, m in enumerate(models):
        rs = [r for r in rows if r["model"] == m]
        ax.scatter([r["step_s"] for r in rs], [i] * len(rs), s=22, marker="s",
                   c=[CLASS_COLORS[CLASSES.index(r["class"])] for r in rs])
        unstable = [r["step_s"] for r in rs if r["amp"] > 1]
        if unstable:
            ax.plot([min(unstable)] * 2, [i - 0.35, i + 0.35], color="k", lw=1.5)
        thesis = max(rs, key=lambda r: r["steps"])
        ax.plot(thesis["step_s"], i + 0.3, "v", color="#c62828", ms=6)
    ax.set_yticks(range(len(models)), models, fontsize=8)
    ax.set_ylim(-0.6, len(models) - 0.4)
    ax.set_xlabel("RK4 step [s]  (red triangle: the thesis's step; black tick: first step "
                  "with RK4 amplification > 1)")
    r0 = rows[0]
    ax.set_title(f"{r0['case']}: class of the faithful RK4 run against its step", fontsize=9)
    handles = [plt.Line2D([], [], ls="", marker="s", color=c, label=n)
               for n, c in zip(CLASSES, CLASS_COLORS)]
    ax.legend(handles=handles, fontsize=7, ncol=len(CLASSES), loc="upper center",
              bbox_to_anchor=(0.5, -0.45 - 0.1 / len(models)), frameon=False)
    fig.subplots_adjust(left=0.16, right=0.98, top=0.85, bottom=0.45 if len(models) < 3 else 0.36)
    return _save(fig, path)


def make_doc_figures(out_dir="docs/img", sat=None) -> list:
    """Every figure of docs/headlines.md (about a minute): the cases, the damping
    scan, and step scans of the nominal, damping x10 and E1 +50 % runs."""
    from tethersim.experiments import headlines as hl

    out_dir = Path(out_dir)
    rows = hl.run_headlines(sat, progress=False)
    paths = plot_cases(rows, out_dir)
    paths.append(plot_damping_scan(hl.damping_scan(sat), out_dir / "headlines_scan_damping.png"))
    for case, steps in (("nominal", None), ("damping-x10", None),
                        ("E1+50%", np.arange(700, 1501, 5))):
        paths.append(plot_step_scan(hl.step_scan(sat, case, steps=steps),
                                    out_dir / f"headlines_scan_step_{_slug(case)}.png"))
    return paths


if __name__ == "__main__":  # python -m tethersim.output.plots.headlines [OUT_DIR]
    import sys

    for p in make_doc_figures(*(sys.argv[1:2] or ["docs/img"])):
        print(p)
