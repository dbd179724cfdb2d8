"""Run one satellite under several model variants and tabulate the outcomes.

The variants (tethersim.model.registry, docs/errata.md) share one derivation:

  derived           the clean derivation of Eqs 3.10-3.47 (default)
  printed           Eqs 3.48-3.50 as printed; differs from `derived` only by the
                    damper-2 θ term, erratum E1: printed − derived = c2 a (a+b)(θ̇ − ω)
  exact-gravity     point-mass gravity without the binomial expansion (note N2):
                    differs from `derived` by terms ~ offset/r0 ≈ 1e-5 relative
  objective-damper  Kelvin-Voigt tether dampers; equals `derived` when c1 = c2 = 0

:func:`compare` runs them with the same integrator settings;
:func:`comparison_table` gives one row per variant with the pitch metrics of
docs/metrics.md, the steady-state trail δx_ss, the convergence estimate and the
outcome class of :mod:`tethersim.analysis.classify`; :func:`outcome_differences` says
where two variants end in different classes.  SI throughout, except the
settling time, which the table gives in hours (labelled).
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.outcome import ROW_COLUMNS, outcome
from tethersim.engine.result import ADAPTIVE_SCHEMES, SimResult
from tethersim.model.registry import NAMES, THESIS_VARIANTS, model_for_orbit
from tethersim.model.satellite import Satellite

# (key, header with unit) of each table column, in order: the model, the one
# outcome row (tethersim.analysis.outcome.ROW_COLUMNS), the difference to the first model
COLUMNS = (("model", "model"), *ROW_COLUMNS,
           ("max_dtheta", "max |theta - theta_first| [rad]"))


def parse_models(models) -> tuple:
    """Model names from a sequence or a comma-separated string; clear error if unknown.

    Allowed values: tethersim.MODELS.  Order is kept (the first
    model is the reference of the θ differences); repeats are an error.
    """
    if isinstance(models, str):
        models = [m.strip() for m in models.split(",") if m.strip()]
    models = tuple(models)
    allowed = ", ".join(NAMES)
    if not models:
        raise ValueError(f"models: none given; allowed values {allowed}")
    for m in models:
        if m not in NAMES:
            raise ValueError(f"models: unknown model {m!r}; allowed values {allowed}")
    repeated = sorted({m for m in models if models.count(m) > 1})
    if repeated:
        raise ValueError(f"models: {', '.join(repeated)} given more than once")
    return models


def compare(sat: Satellite, models=THESIS_VARIANTS, **simulate_kwargs) -> list:
    """[(model, SimResult)] for each model, run with the same ``simulate`` arguments.

    ``simulate_kwargs`` go to :func:`tethersim.engine.simulate.simulate` (periods,
    steps, method, rtol, check, progress, ...); ``model`` is not allowed among
    them.  Every name is checked before the first run.  A run interrupted with
    Ctrl-C ends the comparison: the runs finished so far (and the interrupted
    one) are returned.
    """
    from tethersim.engine.simulate import simulate

    if not isinstance(sat, Satellite):
        raise TypeError(f"sat must be a tethersim Satellite (load_preset/load), "
                        f"got {type(sat).__name__}")
    if "model" in simulate_kwargs:
        raise TypeError("compare() takes the models as `models`, not `model`")
    models = parse_models(models)
    # on a free orbit a circular model runs its free twin: two names running one model
    # would be two identical rows under different labels; a free model on a circular
    # orbit is refused by model_for_orbit (one line)
    runs = {}
    for m in models:
        runs.setdefault(model_for_orbit(m, sat.orbit), []).append(m)
    same = next((names for names in runs.values() if len(names) > 1), None)
    if same:
        raise ValueError(f"models: {', '.join(same)} all run model "
                         f"{model_for_orbit(same[0], sat.orbit)!r} on orbit = {sat.orbit!r}; "
                         f"give each once")
    results = []
    for m in models:
        res = simulate(sat, model=m, **simulate_kwargs)
        results.append((res.model, res))  # the model that ran: its twin on a free orbit
        if res.status == "interrupted":
            break
    return results


def theta_difference(res: SimResult, ref: SimResult) -> tuple:
    """(t [s], θ_res − θ_ref [rad]) on ``ref``'s samples within both runs.

    Runs with the same settings share their output grid; a shorter run (failed,
    interrupted) or another grid is handled by linear interpolation of ``res``.
    """
    t_end = min(res.t[-1], ref.t[-1])
    keep = ref.t <= t_end
    t = ref.t[keep]
    if res.t.shape == ref.t.shape and np.array_equal(res.t, ref.t):
        th = res.theta[keep]
    else:
        th = np.interp(t, res.t, res.theta)
    return t, th - ref.theta[keep]


def describe_runs(results, overrides: str = "") -> str:
    """One line naming the satellite, its overrides, the run length and the integrator."""
    res = results[0][1]
    orbits = res.t[-1] / res.satellite.period if res.t.size else 0.0
    if res.method == "rk4":
        kind = f"RK4, fixed step {res.step:.4g} s" + (" (faithful)" if res.faithful
                                                      else ", switches located")
    else:
        kind = f"{ADAPTIVE_SCHEMES[res.method]}, rtol {res.rtol:g}"
    name = res.satellite.name + (f" ({overrides})" if overrides else "")
    return (f"{name}, {orbits:.4g} orbits, {kind}; models {', '.join(m for m, _ in results)}; "
            f"θ differences against {results[0][0]}")


def comparison_table(results) -> list:
    """One row per (model, SimResult): the model, its :class:`Outcome` row and
    max_dtheta, the largest |θ − θ_first| [rad] against the first model (0 for it).

    Keys as in :data:`COLUMNS` (SI; settling time in h).
    """
    results = list(results)
    if not results:
        raise ValueError("comparison_table: no results")
    ref = results[0][1]
    rows = []
    for model, res in results:
        _, dth = theta_difference(res, ref)
        rows.append({"model": model, **outcome(res, forces=False).row(),
                     "max_dtheta": float(np.max(np.abs(dth))) if dth.size else math.nan})
    return rows


def outcome_differences(rows) -> list:
    """Sentences naming the variants whose outcome classes differ (empty if all agree)."""
    by_class = {}
    for r in rows:
        by_class.setdefault(r["class"], []).append(r["model"])
    if len(by_class) < 2:
        return []
    groups = "; ".join(f"{', '.join(ms)}: {c}" for c, ms in by_class.items())
    lines = [f"outcome classes differ ({groups})"]
    first = rows[0]
    for r in rows[1:]:
        if r["class"] != first["class"]:
            lines.append(f"  {r['model']} ends {r['class']} where {first['model']} "
                         f"ends {first['class']}")
    return lines


def _fmt(key: str, value) -> str:
    if value is None:
        return "n/a"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        if math.isnan(value):
            return "never" if key == "settling_time_h" else "n/a"
        return f"{value:.4g}" if key.startswith("error") or key == "max_dtheta" else f"{value:.6g}"
    return str(value)


def format_table(rows) -> str:
    """The table transposed for the terminal: one row per quantity, one column per model."""
    labels = [header for _, header in COLUMNS[1:]]
    width = max(len(s) for s in labels) + 2
    cells = [[_fmt(key, r[key]) for r in rows] for key, _ in COLUMNS[1:]]
    col = max([len(r["model"]) for r in rows] + [len(c) for row in cells for c in row]) + 2
    lines = [" " * width + "".join(f"{r['model']:>{col}}" for r in rows)]
    for label, row in zip(labels, cells):
        lines.append(f"{label:<{width}}" + "".join(f"{c:>{col}}" for c in row))
    return "\n".join(lines)
