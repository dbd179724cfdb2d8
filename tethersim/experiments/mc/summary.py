"""What a Monte Carlo's rows say: probabilities, quantiles and Sobol' indices with their confidence.

From the random samples: P(settles) (class "stable": settled to within ±tol of a
trim inside ±tol within the three-day requirement), P(settles before the end of its
life), P(tumbles) (the settling run's pitch passed ±π), how lives end, with Wilson
intervals; P10/P50/P90 of the settling time and of the lifetime with distribution-free
intervals, where a run that never settled, or a life past the cap, is a right-censored
value (+inf: "beyond").  From the Sobol' design's rows: first-order and total indices
of each output on each input (docs/montecarlo.md).
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.uncertainty import proportion_ci, quantile_ci, sobol_indices
from tethersim.experiments.mc.spec import MCSpec

QUANTILES = (0.1, 0.5, 0.9)
# the events counted: name -> (what it means, the row's test)
EVENTS = {
    "settles": ("settling run stable (settled near zero pitch within 3 days)",
                lambda r: r["settles"]),
    "settles_in_life": ("settles before the free orbit re-enters or loses its balloon",
                        lambda r: r["settles_in_life"]),
    "tumbles": ("settling run's pitch passed +-pi", lambda r: r["tumbled"]),
    "balloon_lost": ("free run lost its balloon (tether beyond 20x stretch)",
                     lambda r: r["life_end"] == "balloon-lost"),
    "reenters": ("free run re-entered with its balloon", lambda r: r["life_end"] == "re-entry"),
    "capped": ("free run still flying at max_lifetime_h", lambda r: r["life_end"] == "capped"),
}


def _censored(rows, key: str, flag) -> np.ndarray:
    return np.array([math.inf if flag(r) or not math.isfinite(r[key]) else r[key] for r in rows])


def sobol_outputs(rows, spec: MCSpec) -> dict:
    """{output: values at the design's rows}: the outputs the indices are computed for.

    The indicator of settling in life (its variance is P(1 - P)), the lifetime [h]
    (a capped one at the cap), the settling time [h] (one that never settled at the run's
    length) and the trim θ_ss [rad] (left out if a run failed to give one).
    """
    run_h = spec.periods * spec.satellite.period / 3600
    out = {"settles_in_life": np.array([float(r["settles_in_life"]) for r in rows]),
           "lifetime_h": np.array([r["lifetime_s"] / 3600 for r in rows]),
           "settling_time_h": np.array([r["settling_time_s"] / 3600 if
                                        math.isfinite(r["settling_time_s"]) else run_h
                                        for r in rows])}
    theta = np.array([r["theta_ss_rad"] for r in rows])
    if np.isfinite(theta).all():
        out["theta_ss_rad"] = theta
    return out


def summarise(rows, spec: MCSpec) -> dict:
    """Statistics of a store's rows.

    Returns
    -------
    dict
        ``n``; ``probabilities``: [{event, meaning, k, n, estimate, low, high}];
        ``quantiles``: [{quantity, p, estimate, low, high}] in hours (inf: beyond the
        run or the cap); ``classes``: {class: count}; ``sobol``: {output: {input:
        {S1, S1_conf, ST, ST_conf}}} (empty without a design).
    """
    samples = [r for r in rows if r["part"] == "sample"]
    n = len(samples)
    probs = []
    for name, (meaning, test) in EVENTS.items():
        k = sum(bool(test(r)) for r in samples)
        est, lo, hi = proportion_ci(k, n)
        probs.append({"event": name, "meaning": meaning, "k": k, "n": n, "estimate": est,
                      "low": lo, "high": hi})
    settle = _censored(samples, "settling_time_s", lambda r: False) / 3600
    life = _censored(samples, "lifetime_s", lambda r: r["life_end"] == "capped") / 3600
    quants = [{"quantity": q, "p": p, **dict(zip(("estimate", "low", "high"),
                                                 quantile_ci(v, p)))}
              for q, v in (("settling_time_h", settle), ("lifetime_h", life)) for p in QUANTILES]
    classes = {}
    for r in samples:
        classes[r["class"]] = classes.get(r["class"], 0) + 1
    design = [r for r in rows if r["part"] == "sobol"]
    sobol = {}
    if design:
        for k, (name, y) in enumerate(sobol_outputs(design, spec).items()):
            sobol[name] = sobol_indices(spec.names, y, seed=spec.seed + k)
    return {"n": n, "probabilities": probs, "quantiles": quants, "classes": classes,
            "sobol": sobol}


def summary_rows(s: dict) -> list:
    """The summary as table rows (quantity, estimate, ci_low, ci_high, note)."""
    out = [{"quantity": f"P({p['event']})", "estimate": p["estimate"], "ci_low": p["low"],
            "ci_high": p["high"], "note": f"{p['k']} of {p['n']}: {p['meaning']}"}
           for p in s["probabilities"]]
    out += [{"quantity": f"P{round(q['p'] * 100)} {q['quantity']}", "estimate": q["estimate"],
             "ci_low": q["low"], "ci_high": q["high"],
             "note": "inf: beyond the run (never settled) or the lifetime cap"}
            for q in s["quantiles"]]
    for output, idx in s["sobol"].items():
        out += [{"quantity": f"{kind} {output} <- {name}", "estimate": v[kind],
                 "ci_low": v[kind] - v[f"{kind}_conf"], "ci_high": v[kind] + v[f"{kind}_conf"],
                 "note": "first-order" if kind == "S1" else "total"}
                for name, v in idx.items() for kind in ("S1", "ST")]
    return out
