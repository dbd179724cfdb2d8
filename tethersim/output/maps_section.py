"""The report's stability maps (thesis Figs 5.13, 5.21-5.23, 5.27-5.28).

Six 41 x 41 maps of 50-orbit runs, each converged (DOP853 at the class tolerance,
docs/tolerances.md), faithful (the thesis's RK4 step) and predicted from the eigenvalues
(tethersim.analysis.predict), with their agreement.  The runs are compiled sweeps that
release the GIL; the maps' Python (predicted maps, comparisons, plots) runs in one thread
beside the next map's runs.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tethersim.model import params
from tethersim.model.presets import load_preset
from tethersim.output.page import Page
from tethersim.output.page import cell as _g
from tethersim.output.page import table as _table


@dataclass(frozen=True)
class MapSpec:
    """One stability map: satellite, axes (edge units) and the thesis figure it redoes."""

    sat: str
    figure: str
    x: tuple  # (name, start, stop)
    y: tuple

    def grid(self, n: int) -> tuple:
        return ((self.x[0], np.linspace(self.x[1], self.x[2], n).tolist()),
                (self.y[0], np.linspace(self.y[1], self.y[2], n).tolist()))


# ranges: SatI's moduli as the thesis swept them (p. 5-18); the others (lost) span 0 to
# about 2.5x the preset, so that the band E2 ≈ (b/a) E1 crosses the map; damping from 0
# to 40-50x the preset, past the upper limit where the pitch trim is lost
MAPS = (
    MapSpec("satI", "5.21", ("E1", 0.0, 0.02), ("E2", 0.0, 0.06)),
    MapSpec("satI", "5.13", ("c1", 0.0, 0.012), ("c2", 0.0, 0.012)),
    MapSpec("satII", "5.22", ("E1", 0.0, 0.005), ("E2", 0.0, 0.12)),
    MapSpec("satII", "5.23", ("c1", 0.0, 0.012), ("c2", 0.0, 0.012)),
    MapSpec("dumbsat", "5.27", ("E1", 0.0, 0.06), ("E2", 0.0, 0.06)),
    MapSpec("dumbsat", "5.28", ("c1", 0.0, 0.06), ("c2", 0.0, 0.06)),
)


def section_maps(page: Page, grid: int, periods: float, workers, progress) -> list:
    from concurrent.futures import ThreadPoolExecutor

    from tethersim.analysis.predict import predicted_map
    from tethersim.experiments.sweep import SweepSpec, run_sweep
    from tethersim.experiments.sweep.plan import CLASS_RTOL

    # the maps' runs are compiled and release the GIL; their Python (the predicted maps,
    # the comparisons, the plots) runs in one thread beside the next map's runs, in order
    beside = ThreadPoolExecutor(1)
    try:
        predicted = []
        for ms in MAPS:
            (nx, vx), (ny, vy) = ms.grid(grid)
            predicted.append(beside.submit(predicted_map, load_preset(ms.sat), nx, vx, ny, vy,
                                           periods=periods, progress=False))
        rows = []
        for ms, pred in zip(MAPS, predicted):
            sat, axes = load_preset(ms.sat), ms.grid(grid)
            name = f"{ms.sat}_{axes[0][0]}_{axes[1][0]}"
            data = {}
            for method in ("adaptive", "faithful"):
                # a map asks for classes: the class tolerance (docs/tolerances.md)
                spec = SweepSpec(sat, axes, periods=periods, method=method, rtol=CLASS_RTOL)
                # the settings in the name: a report with another grid starts its own stores
                store = run_sweep(spec, page.out / "sweeps" / f"{name}_{method}_{grid}x{grid}"
                                  f"_{periods:g}orbits_rtol{CLASS_RTOL:g}.zarr",
                                  workers=workers, progress=progress)
                data[method] = store.dataset()
            rows.append(beside.submit(_map_row, page, ms, sat, axes, name, data, pred, periods))
            for done in (r for r in (*predicted, *rows) if r.done()):
                done.result()  # a failure in a finished map's Python stops the report now
        body, summary = zip(*(r.result() for r in rows))
    except BaseException:  # Ctrl-C: the finished stores stay; the queued work is dropped
        beside.shutdown(wait=False, cancel_futures=True)
        raise
    beside.shutdown()
    page.add("Stability maps (thesis Figs 5.13, 5.21-5.23, 5.27-5.28)",
             f"<p>{grid} x {grid} grids of {periods:g}-orbit runs (DOP853 at rtol {CLASS_RTOL:g}, "
             "the tolerance at which classes have converged: docs/tolerances.md); classes as "
             "docs/metrics.md. "
             "Predicted: from the equilibrium near θ = 0 and the eigenvalues of the generated "
             "Jacobian (tethersim.analysis.predict). Faithful: the thesis's fixed RK4 step (26.55 s).</p>"
             + _table(("satellite", "thesis figure", "axes", "classes (converged)",
                       "band slope E2/E1", "predicted vs simulated: same stable verdict",
                       "same class", "faithful differs at", "faithful vs converged: same class"),
                      summary, reasons={
                          "band slope E2/E1": "no stable band on these grids (c1 x c2 maps "
                                              "have none by construction)",
                          "faithful differs at": "the thesis's RK4 step gives the converged "
                                                 "class at every point"}) + "".join(body))
    return list(summary)


def _map_row(page: Page, ms, sat, axes, name: str, data: dict, pred, periods: float) -> tuple:
    """(figure, summary row) of one stability map, from its two stores' datasets and its
    predicted map (a future: the predicted maps run beside the runs)."""
    from tethersim.analysis.classify import agreement
    from tethersim.experiments.sweep.analysis import band_slope, class_counts, differences
    from tethersim.experiments.sweep.plan import CLASS_RTOL
    from tethersim.output.plots.sweep import plot_stability_map

    pred = pred.result()
    ds, fa = data["adaptive"], data["faithful"]
    agree = agreement(pred.predicted_class.values, ds.stability_class.values)
    agree_f = agreement(fa.stability_class.values, ds.stability_class.values)
    slope = band_slope(ds) if axes[0][0] == "E1" else float("nan")
    n_diff = int(differences(ds, fa).sum())
    nominal = {n: params.edge_value(sat, n) for n, _ in axes}
    path = plot_stability_map(
        ds, page.out / "img" / f"map_{name}.png", nominal=nominal,
        predicted=pred.predicted_class.values, other=fa.stability_class.values,
        other_label="faithful RK4 differs",
        band_slope=slope if math.isfinite(slope) else None,
        title=f"{sat.name}: {axes[1][0]} vs {axes[0][0]} (thesis Fig {ms.figure}), "
              f"{periods:g} orbits, DOP853 rtol {CLASS_RTOL:g}")
    counts = class_counts(ds)
    if axes[0][0] == "c1":
        nom = max(sat.c1, sat.c2)
        high = (ds.c1 > 10 * nom) & (ds.c2 > 10 * nom) & ds.done
        hc = ds.stability_class.where(high).values
        n_over = int(np.sum((hc == 3) | (hc == 4)))
        n_off = int(np.sum(hc == 2))
        page.fact(f"{sat.name}: an upper range of damping turns the satellite over", "5-11, 5-13",
                  f"above 10x nominal damping (both tethers): {n_over} points turn over "
                  f"(upside down or tumbling), {n_off} lose the trim (offset), of "
                  f"{int(high.sum())}", "yes" if n_over > n_off else "no",
                  "the thesis damper's torque at rest tilts the trim as damping grows "
                  "(docs/headlines.md); it does not turn the satellite over")
    row = (sat.name, f"Fig {ms.figure}", f"{axes[0][0]} x {axes[1][0]}",
           ", ".join(f"{k} {v}" for k, v in counts.items() if v),
           _g(slope, ".3g"), f"{agree['same_stability']:.3f}",
           f"{agree['same_class']:.3f}", f"{n_diff} of {ds.stability_class.size}",
           f"{agree_f['same_class']:.3f}")
    return (page.img(path, f"{sat.name} {axes[1][0]} vs {axes[0][0]}: classes (left, "
                           f"black line: predicted stable region), steady pitch (right)"), row)
