"""The thesis's headline results for SatI, rerun faithfully and converged (issue 5, item 5).

Each headline is a thesis claim (page cited) with the parameter change, the
run length and the thesis's step count.  For every case and model variant
(``derived``, ``printed``, ``objective-damper``) :func:`run_headlines` runs

* ``rk4-thesis``  fixed-step RK4 at the thesis's step, switches not located
  (the faithful scheme: 17.70 s for 5 orbits in 1500 steps, p. 5-1; 26.55 s for
  50 orbits in 10,000 steps, p. 5-7),
* ``rk4-half``, ``rk4-quarter``  the same at 1/2 and 1/4 of that step,
* ``dop853``  adaptive DOP853 (rtol 1e-10, switches located, convergence checked),

and records the pitch metrics (docs/metrics.md), the stability class
(tethersim.analysis.classify), the equilibria near θ = 0 (``eq0_*``), near θ = π
(``eqpi_*``) and near the converged run's mean pitch (``eqrun_*``) with their
eigenvalues, the RK4 amplification at the thesis's step and the largest
stable RK4 step.  :func:`verdicts` states per claim whether it survives a
converged integration, and whether the outcome depends on the step or on
the damper model.  Findings and figures: docs/headlines.md.

Units: SI inside (s, rad, m, N s/m); columns whose name ends in ``_h`` are
hours, ``_orbits`` orbits; E1, E2 factors multiply N/mm^2 values (p. 3-1).
"""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from tethersim.analysis.classify import CLASSES
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.metrics import wrap
from tethersim.analysis.outcome import finite_prefix, outcome
from tethersim.engine.linearise import rk4_amplification, rk4_max_step
from tethersim.engine.simulate import simulate
from tethersim.experiments.headlines.cases import (
    BY_NAME,
    HEADLINES,
    MODELS,
    NEAR,
    SCHEMES,
    STEP_DIVISORS,
    Headline,
    claim_holds,
)
from tethersim.model.satellite import Satellite


# --- equilibria -----------------------------------------------------------------------
def _equilibrium_fields(sat: Satellite, model: str, guess_theta: float, prefix: str) -> dict:
    """Equilibrium found from (δx0, δy0, guess_theta); NaN unless within NEAR of the guess."""
    nan = {f"{prefix}_theta": math.nan, f"{prefix}_stable": None,
           f"{prefix}_max_real": math.nan, f"{prefix}_slowest_decay_h": math.nan,
           f"{prefix}_predicted_settling_h": math.nan, f"{prefix}_taut": ""}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            eq = find_equilibrium(sat, model, guess=(sat.initial[0], sat.initial[1], guess_theta))
    except RuntimeError:
        return nan
    if abs(float(wrap(eq.theta - guess_theta))) > NEAR:
        return nan
    rate = -float(max(eq.eigenvalues.real))
    return {f"{prefix}_theta": eq.theta, f"{prefix}_stable": eq.stable,
            f"{prefix}_max_real": -rate,
            f"{prefix}_slowest_decay_h": (1 / rate / 3600) if rate > 0 else math.inf,
            f"{prefix}_predicted_settling_h":
                eq.predicted_settling_time(float(wrap(sat.initial[2] - eq.theta))) / 3600,
            f"{prefix}_taut": "".join("T" if t else "s" for t in eq.taut)}


def case_analysis(case: Headline, sat: Satellite, model: str) -> dict:
    """Equilibria near 0 and π (eigenvalues), RK4 amplification at the thesis step, max step."""
    s = case.satellite(sat)
    h = case.step(sat)
    out = {"step_thesis_s": h, "amp_thesis_step": rk4_amplification(s, h, model),
           "rk4_max_step_s": rk4_max_step(s, model)}
    out.update(_equilibrium_fields(s, model, 0.0, "eq0"))
    out.update(_equilibrium_fields(s, model, math.pi, "eqpi"))
    return out


# --- runs -----------------------------------------------------------------------------
def run_case(case: Headline, sat: Satellite, model: str, scheme: str, periods: float):
    steps = max(1, round(case.steps * periods / case.periods))
    if scheme == "dop853":
        return simulate(sat, periods=periods, model=model, samples=steps, check=True,
                        progress=False)
    return simulate(sat, periods=periods, steps=steps * STEP_DIVISORS[scheme], method="rk4",
                    model=model, locate_switches=False, step_warning=False, check=False,
                    progress=False)


def row_of(res, case: Headline, model: str, scheme: str) -> dict:
    if res.status == "interrupted":  # Ctrl-C: stop, do not record a truncated run as failed
        raise KeyboardInterrupt
    out = outcome(res, forces=False)  # one rule for failed and NaN runs (outcome.py)
    m, cls = out.metrics, out.stability_class
    th = res.theta[:finite_prefix(res)]
    period = res.satellite.period
    row = {"case": case.name, "page": case.page, "change": case.change, "model": model,
           "scheme": scheme, "periods": float(res.t[-1] / period) if res.t.size else 0.0,
           "step_s": res.step if res.step is not None else math.nan,
           "status": res.status, "class": CLASSES[cls],
           "mean_pitch": m.mean_pitch if m else math.nan,
           "theta_ss": m.steady_state_pitch if m else math.nan,
           "settling_h": m.settling_time / 3600 if m else math.nan,
           "tumbled": bool(m.tumbled) if m else False,
           "upside_down": bool(m.upside_down) if m else False,
           "theta_min": float(th.min()) if th.size else math.nan,
           "theta_max": float(th.max()) if th.size else math.nan,
           "revolutions": float((th.max() - th.min()) / (2 * math.pi)) if th.size else 0.0,
           "theta_end": float(th[-1]) if th.size else math.nan,
           "err_theta": res.errors["theta"] if res.errors else math.nan,
           "converged": res.converged, "wall_s": res.wall_time}
    row["claim_holds"] = claim_holds(case.check, row)
    # private: the series for plots (not written to CSV)
    row["_period"] = period
    row["_t"] = res.t.copy()
    row["_theta"] = res.theta.copy()
    return row


def _compare_with_reference(rows: list) -> None:
    """max |θ_scheme − θ_dop853| on the common grid [rad], per (case, model)."""
    ref = {(r["case"], r["model"]): r for r in rows if r["scheme"] == "dop853"}
    for r in rows:
        d = ref.get((r["case"], r["model"]))
        if d is None or r is d:
            r["max_dtheta_vs_dop853"] = 0.0 if r is d else math.nan
            continue
        k = STEP_DIVISORS[r["scheme"]]
        a = r["_theta"][::k]
        n = min(a.size, d["_theta"].size)
        diff = np.abs(a[:n] - d["_theta"][:n])
        r["max_dtheta_vs_dop853"] = (float(diff.max()) if r["status"] == "ok"
                                     and np.all(np.isfinite(diff)) else math.inf)


def run_headlines(sat: Satellite | None = None, models=MODELS, progress: bool = True,
                  cases=None, periods: float | None = None, schemes=SCHEMES) -> list:
    """Run every headline case x model x scheme; one dict per run (see module doc).

    sat: default the SatI preset; cases: names or Headline objects (default
    all of HEADLINES); periods: override every case's run length [orbits],
    keeping the thesis's step size (for quick checks).
    """
    from tethersim.model.presets import load_preset

    sat = load_preset("satI") if sat is None else sat
    chosen = [c if isinstance(c, Headline) else BY_NAME[c] for c in (cases or HEADLINES)]
    rows = []
    t0 = time.perf_counter()
    for case in chosen:
        s = case.satellite(sat)
        n = case.periods if periods is None else float(periods)
        for model in models:
            info = case_analysis(case, sat, model)
            mine = []
            for scheme in schemes:
                res = run_case(case, s, model, scheme, n)
                row = row_of(res, case, model, scheme)
                row.update(info)
                mine.append(row)
            ref = next((r for r in mine if r["scheme"] == "dop853"), None)
            if ref is not None and math.isfinite(ref["mean_pitch"]):
                # the equilibrium the converged run settles to or oscillates about
                found = _equilibrium_fields(s, model, float(wrap(ref["mean_pitch"])), "eqrun")
                for r in mine:
                    r.update(found)
            rows += mine
            if progress:
                done = [r for r in rows if r["case"] == case.name and r["model"] == model]
                print(f"  {case.name:<15} {model:<17} " + "  ".join(
                    f"{r['scheme']}: {r['class']} ({r['theta_ss']:+.3f})" for r in done)
                    + f"  [{time.perf_counter() - t0:.1f} s]", flush=True)
    _compare_with_reference(rows)
    return rows
