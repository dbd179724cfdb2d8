"""The design search: NSGA-II (pymoo) over a resumable store, the Pareto set, re-verification.

Why pymoo's NSGA-II: the question has two objectives (settling margin, worst trim) and
hard constraints (the verdict), and a mission designer wants the trade-off front, not one
weighted optimum; NSGA-II gives the front with constraint domination, it is seeded and
deterministic, and its ask/tell interface lets each generation run as one plan of many.
Optuna's NSGA-II sampler would do too, but it draws one trial at a time, and its study
storage is a database where this needs a JSON line per design.

The store (``--out``/store): ``spec.json`` and ``evaluations.jsonl``, one line per design
as its generation finishes: its search vector (exact floats), row and (F, G).  A rerun with
the same spec replays the same seeded search; a design found in the store is read, not
run, so an interrupted search continues to the result of an uninterrupted one.
Re-verification lines (``"verify"``) are kept the same way.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from tethersim.analysis.feasibility import verdict
from tethersim.analysis.trail_bound import trail_bound
from tethersim.engine.result import STATUSES
from tethersim.experiments.design import (
    REFUSED,
    SOLAR_CASES,
    DesignSpec,
    evaluate,
    objectives,
)
from tethersim.experiments.sweep.lines import LineStore
from tethersim.experiments.sweep.point import outcome_of_record

EVALUATIONS_FILE = "evaluations.jsonl"


def _key(spec: DesignSpec, x) -> str:
    """A design's identity: its values in edge units (two search vectors that pick the same
    choices are one design, run once)."""
    return json.dumps([v for _, v in sorted(spec.values(x).items())])


class DesignStore:
    """The search's store: evaluations by search vector, verifications by the same key."""

    def __init__(self, path, spec: DesignSpec):
        self.path = Path(path)
        self.store = LineStore(self.path, EVALUATIONS_FILE, spec.to_json(), "a design search",
                               "use another --out or --force").__enter__()
        self.evaluated, self.verified = {}, {}
        for d in self.store.rows():
            (self.verified if "verify" in d else self.evaluated)[d["key"]] = d

    def put(self, entry: dict) -> None:
        self.store.put(entry)
        (self.verified if "verify" in entry else self.evaluated)[entry["key"]] = entry

    def close(self) -> None:
        self.store.__exit__(None, None, None)


def search(spec: DesignSpec, out, *, workers=None, scheduler=None, dask_workers=None,
           progress=None, stop_after=None) -> dict:
    """Run (or resume) the search into the store at ``out``; the result.

    Parameters
    ----------
    spec : DesignSpec
        What to search.
    out : path-like
        Store folder (created, or resumed when it holds the same spec).
    workers : int, optional
        Threads of the plans (default: every core); the result does not depend on it.
    scheduler, dask_workers : optional
        A Dask scheduler's address, or a local cluster of that many worker processes,
        opened once for the whole search (runner.executor); the same result.
    progress : bool or None, optional
        A progress bar over the evaluations (None: when slow; False: none).
    stop_after : int, optional
        Stop as if interrupted after that many generations (tests).

    Returns
    -------
    dict
        ``evaluations`` (rows in search order, each with ``F``, ``G``, ``key``), ``pareto``
        (the non-dominated feasible rows, the first ``spec.verify`` re-verified:
        ``verified`` (None past them), ``fine_verdict``, and
        the trail bound's ``bound_ratio``, ``settle_over_life``, ``respects_bound``),
        ``replayed`` (designs read from the store).
    """
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.problem import Problem
    from tqdm.auto import tqdm

    lo, hi = (np.array(b, dtype=float) for b in spec.bounds)
    problem = Problem(n_var=lo.size, n_obj=2, n_ieq_constr=3, xl=lo, xu=hi)
    algorithm = NSGA2(pop_size=spec.population, eliminate_duplicates=True)
    algorithm.setup(problem, termination=("n_gen", spec.generations), seed=spec.seed,
                    verbose=False)
    store = DesignStore(out, spec)
    rows, replayed = [], 0
    from tethersim.experiments.sweep.runner import executor
    try:
        with executor(workers, scheduler, dask_workers) as pool, \
                tqdm(total=spec.generations * spec.population, desc="design", unit="design",
                     disable=progress is False, delay=0 if progress else 1.0, leave=False) as bar:
            gen = 0
            while algorithm.has_next():
                pop = algorithm.ask()
                xs = [np.asarray(x, dtype=float) for x in pop.get("X")]
                keys = [_key(spec, x) for x in xs]
                first = {k: i for i, k in reversed(list(enumerate(keys)))}
                todo = [i for k, i in first.items() if k not in store.evaluated]
                todo.sort()
                stored = sum(k in store.evaluated for k in keys)
                replayed += stored
                bar.update(len(xs) - len(todo))
                new = evaluate(spec, [xs[i] for i in todo], pool=pool, progress=False)
                for i, row in zip(todo, new):
                    f, g = objectives(spec, row)
                    store.put({"key": keys[i], "x": [float(v) for v in xs[i]], "row": row,
                               "F": f, "G": g})
                    bar.update(1)
                entries = [store.evaluated[k] for k in keys]
                pop.set("F", np.array([e["F"] for e in entries], dtype=float))
                pop.set("G", np.array([e["G"] for e in entries], dtype=float))
                algorithm.tell(infills=pop)
                rows += [{**e["row"], "key": e["key"], "x": e["x"], "F": e["F"], "G": e["G"]}
                         for e in entries]
                gen += 1
                if stop_after is not None and gen >= stop_after:
                    raise KeyboardInterrupt
            front = pareto(rows)
            for i, r in enumerate(front):  # the first --verify designs of the front, in order
                r.update(verify_design(spec, store, r, pool=pool) if i < spec.verify
                         else {"verified": None, "fine_verdict": "not re-verified (--verify)",
                               **bound_columns(spec, r)})
    finally:
        store.close()
    return {"evaluations": rows, "pareto": front, "replayed": replayed}


def pareto(rows: list) -> list:
    """The non-dominated feasible rows (every G <= 0), one per design, in search order."""
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting
    seen, feasible = set(), []
    for r in rows:
        if r["key"] not in seen and max(r["G"]) <= 0:
            seen.add(r["key"])
            feasible.append(dict(r))
    if not feasible:
        return []
    front = NonDominatedSorting().do(np.array([r["F"] for r in feasible]),
                                     only_non_dominated_front=True)
    return [feasible[i] for i in sorted(int(i) for i in front)]


def verify_design(spec: DesignSpec, store: DesignStore, row: dict, workers=None,
                  pool=None) -> dict:
    """Re-verify one reported design by an independent finer run; the columns it adds.

    The finer run: free orbits in per-body NRLMSISE-00 air at solar minimum, mean and
    maximum (the feasibility atlas's, tethersim.experiments.feasibility.FeasibilitySpec.free)
    instead of Vallado's, and the nominal and trim runs again, all at the check tolerance
    (rtol / 100).  Its verdict takes the shortest of the three usable lives; the design is
    ``verified`` when that verdict is the search's.  Stored, so a resumed search does not
    rerun it.
    """
    if row["key"] in store.verified:
        return store.verified[row["key"]]["columns"]
    from tethersim.experiments.sweep.runner import run_plan
    sat = spec.design(row["x"])
    fs = spec.feasibility(sat)
    h, a3 = fs.points()[0]
    circ_plan, free_plan = spec.plans(fs.check_rtol)
    from tethersim.experiments.design import solar_scale_items
    circ = run_plan(circ_plan, [fs.circular(h, a3)] + [fs.circular(h, a3, k)
                                                        for _, k in solar_scale_items(h)],
                    workers=workers, pool=pool, progress=False)
    free = run_plan(free_plan, [fs.free(h, a3, c) for c in SOLAR_CASES], workers=workers,
                    pool=pool, progress=False)
    cap = spec.max_lifetime_h * 3600
    lives = []
    for c, r in zip(SOLAR_CASES, free):
        status = STATUSES[int(r["status"])]
        life = math.inf if status == "ok" or r["end_time"] > cap else float(r["end_time"])
        lives.append((life, status in ("left-domain", "tether-broke"), c))
    life, lost, worst = min(lives)
    period = fs.circular(h, a3).period
    fine = verdict(life, outcome_of_record(circ[0]), [outcome_of_record(r) for r in circ[1:]], spec.tol,
                   run_s=spec.periods * period, cap_s=cap, lost=lost and math.isfinite(life))
    columns = {"fine_verdict": fine, "verified": fine == row["verdict"],
               "fine_life_h": min(life, cap) / 3600, "fine_worst_case": worst,
               "check_rtol": fs.check_rtol, **bound_columns(spec, row),
               **tension_columns(spec, row)}
    store.put({"key": row["key"], "verify": True, "columns": columns})
    return columns


def tension_columns(spec: DesignSpec, row: dict) -> dict:
    """Peak tether tensions [N] of a design over its circular runs (nominal and the three
    solar airs) and its tension margin, 1 − peak / breaking load (the real load, not the
    one divided by ``safety`` the search runs with); NaN where no breaking load is set.

    The plan's records carry no tension, so the reported designs are run again with their
    trajectories (simulate(), the search's scheme and tolerance).
    """
    from tethersim.engine.simulate import simulate
    from tethersim.experiments.design import solar_scale_items
    from tethersim.experiments.sweep.plan import ATOL_PER_RTOL, SCHEMES
    from tethersim.model import params
    strong = params.with_values(spec.satellite, spec.values(row["x"]))
    loads = (strong.Fb1, strong.Fb2)
    if not any(loads):
        return {"peak_tension_1_N": math.nan, "peak_tension_2_N": math.nan,
                "tension_margin": math.nan}
    fs = spec.feasibility(spec.design(row["x"]))
    h, a3 = fs.points()[0]
    peak = np.zeros(2)
    for sat in [fs.circular(h, a3)] + [fs.circular(h, a3, k) for _, k in solar_scale_items(h)]:
        res = simulate(sat, spec.periods, method=SCHEMES[spec.method], model=spec.model,
                       rtol=spec.rtol, atol=spec.rtol * ATOL_PER_RTOL, progress=False)
        if res.status == "interrupted":  # Ctrl-C: not a result
            raise KeyboardInterrupt
        peak = np.maximum(peak, res.tether_tensions().max(axis=0))
    margin = min(1 - p / fb for p, fb in zip(peak, loads) if fb)
    return {"peak_tension_1_N": float(peak[0]), "peak_tension_2_N": float(peak[1]),
            "tension_margin": float(margin)}


def bound_columns(spec: DesignSpec, row: dict) -> dict:
    """The trail bound of a design (tethersim.analysis.trail_bound) and whether its
    runs respect it: settling / life >= the bound's ratio."""
    if row["verdict"] == REFUSED or not row["trail_m"] > 0:
        return {"bound_ratio": math.nan, "epsilon": math.nan, "settle_over_life": math.nan,
                "respects_bound": None}
    b = trail_bound(spec.design(row["x"]), row["trail_m"], spec.tol)
    ratio = row["settling_h"] / row["life_h"] if row["life_h"] > 0 else math.inf
    return {"bound_ratio": b.ratio, "epsilon": b.epsilon, "decay_life_h": b.decay_life / 3600,
            "settle_min_h": b.settle_min / 3600, "settle_over_life": ratio,
            "respects_bound": bool(ratio >= b.ratio) if math.isfinite(ratio) else None}


def no_design_reason(spec: DesignSpec, rows: list) -> str:
    """Why no design qualified: the verdicts' tally, what the trail bound says of them, and
    the measured shortfall of the commonest failures (one line)."""
    tally = {}
    for r in rows:
        tally[r["verdict"]] = tally.get(r["verdict"], 0) + 1
    parts = ", ".join(f"{n} {v}" for v, n in sorted(tally.items(), key=lambda t: -t[1]))
    ratios = [bound_columns(spec, r)["bound_ratio"] for r in rows
              if r["verdict"] != REFUSED and r.get("trail_m", 0) > 0]
    ratios = [q for q in ratios if math.isfinite(q)]
    if not ratios:
        return f"no design qualifies ({parts}); none ran far enough for the trail bound"
    over = sum(q >= 1 for q in ratios)
    if over == len(ratios):
        why = ("every design's trail bound is >= 1: the drag that trails its balloon lowers "
               "the orbit faster than that trail can settle the boom (docs/design.md)")
    else:
        why = (f"the trail bound (settling / life >= {min(ratios):.3g} .. {max(ratios):.3g}) "
               f"forbids {over} of {len(ratios)}; the others fail on their damping and trim, "
               f"not on the orbit's momentum (docs/design.md)")
    return f"no design qualifies ({parts}): {why}{_shortfall(spec, rows)}"


def _shortfall(spec: DesignSpec, rows: list) -> str:
    """Medians of what the failed designs missed by: the trim and its swing over the solar
    cycle, or the usable life against the settling time."""
    from tethersim.analysis.feasibility import LOST, REENTERS, TRIM_LOST
    out = []
    trim = [r for r in rows if r["verdict"] == TRIM_LOST]
    if trim:
        worst = _median([r["worst_theta_ss_rad"] for r in trim])
        swing = _median([abs(r["theta_ss_max_rad"] - r["theta_ss_min_rad"]) for r in trim])
        out.append(f"trim: worst |theta_ss| median {worst:.3g} rad against the {spec.tol:g} rad "
                   f"band, moving {swing:.3g} rad from solar min to max")
    early = [r for r in rows if r["verdict"] in (LOST, REENTERS)]
    if early:
        life = _median([r["life_h"] for r in early])
        settle = _median([r["settling_h"] for r in early])
        out.append(f"life median {life:.3g} h against settling median {settle:.3g} h")
    return "; " + "; ".join(out) if out else ""


def _median(values) -> float:
    """Median of the finite values (NaN if none: a run that never settled has no time)."""
    finite = [v for v in values if math.isfinite(v)]
    return float(np.median(finite)) if finite else math.nan
