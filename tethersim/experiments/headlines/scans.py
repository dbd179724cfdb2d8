"""Scans around the damping x10 case: damping factor, RK4 step and initial trail."""
from __future__ import annotations

import math
import warnings

import numpy as np

from tethersim.analysis.classify import CLASSES
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.metrics import wrap
from tethersim.engine.linearise import rk4_amplification, rk4_max_step
from tethersim.experiments.headlines.cases import BY_NAME, CONTINUATION_JUMP, MODELS, Headline
from tethersim.experiments.headlines.runs import row_of, run_case
from tethersim.model.params import edge_value, with_values
from tethersim.model.satellite import Satellite

# --- scans ---------------------------------------------------------------------------------
DAMPING_FACTORS = (1, 2, 3, 5, 10, 20, 30, 50, 70, 80, 90, 100, 150, 200, 250, 270, 280, 290, 300,
                   400, 500, 1000, 3000, 10000)


def damping_scan(sat: Satellite | None = None, factors=DAMPING_FACTORS, models=MODELS,
                 periods: float = 50.0,
                 steps: int = 10_000, progress: bool = False) -> list:
    """c1, c2 x factor: converged and faithful (RK4, thesis step) outcomes, RK4
    amplification and largest stable step, and the equilibria near 0 and π
    followed by continuation in the factor (NaN once a branch is lost)."""
    from tethersim.model.presets import load_preset

    sat = load_preset("satI") if sat is None else sat
    rows = []
    h = periods * sat.period / steps
    for model in models:
        guesses = {"eq0": (sat.initial[0], sat.initial[1], 0.0),
                   "eqpi": (sat.initial[0], sat.initial[1], math.pi)}
        for f in factors:
            s = with_values(sat, {"c1": edge_value(sat, "c1") * f,
                                  "c2": edge_value(sat, "c2") * f})
            row = {"model": model, "factor": float(f), "c1_Ns_per_m": s.c1, "c2_Ns_per_m": s.c2,
                   "step_s": h, "amp_thesis_step": rk4_amplification(s, h, model),
                   "rk4_max_step_s": rk4_max_step(s, model)}
            for scheme in ("dop853", "rk4-thesis"):
                case = Headline("scan", "", "", "upside_down", periods=periods, steps=steps)
                r = row_of(run_case(case, s, model, scheme, periods), case, model, scheme)
                for k in ("class", "theta_ss", "mean_pitch", "settling_h", "status"):
                    row[f"{scheme}_{k}"] = r[k]
            for key, g in guesses.items():
                th = math.nan
                if g is not None:
                    try:
                        with warnings.catch_warnings():
                            warnings.simplefilter("ignore", RuntimeWarning)
                            eq = find_equilibrium(s, model, guess=g)
                        if abs(float(wrap(eq.theta - g[2]))) < CONTINUATION_JUMP:
                            th = eq.theta
                            row[f"{key}_stable"] = eq.stable
                            row[f"{key}_max_real"] = float(max(eq.eigenvalues.real))
                            guesses[key] = (eq.delta_x, eq.delta_y, eq.theta)
                    except RuntimeError:
                        pass
                if not math.isfinite(th):
                    guesses[key] = None
                    row[f"{key}_stable"] = None
                    row[f"{key}_max_real"] = math.nan
                row[f"{key}_theta"] = th
            rows.append(row)
            if progress:
                print(f"  damping x{f:<6g} {model:<17} converged {row['dop853_class']} "
                      f"({row['dop853_theta_ss']:+.3f}), RK4 {row['rk4-thesis_class']} "
                      f"({row['rk4-thesis_theta_ss']:+.3f}), amp {row['amp_thesis_step']:.3g}",
                      flush=True)
    return rows


def step_scan(sat: Satellite | None = None, case: str | Headline = "damping-x10", steps=None,
              models=MODELS, progress: bool = False) -> list:
    """Faithful RK4 (switches not located) of one headline case at each step count.

    steps: default from 70 % to 100 % of the thesis's count (the step from 1.43x
    the thesis's down to it), 150 points; step_s = periods x orbital period / steps.
    """
    from tethersim.model.presets import load_preset

    sat = load_preset("satI") if sat is None else sat
    case = BY_NAME[case] if isinstance(case, str) else case
    s = case.satellite(sat)
    if steps is None:
        steps = np.unique(np.linspace(0.7 * case.steps, case.steps, 150).round().astype(int))
    rows = []
    for model in models:
        for n in steps:
            c = Headline(case.name, case.page, case.claim, case.check, periods=case.periods,
                         steps=int(n))
            r = row_of(run_case(c, s, model, "rk4-thesis", case.periods), c, model, "rk4-thesis")
            h = case.periods * sat.period / n
            rows.append({"case": case.name, "model": model, "steps": int(n), "step_s": h,
                         "amp": rk4_amplification(s, h, model), "class": r["class"],
                         "status": r["status"], "theta_ss": r["theta_ss"],
                         "mean_pitch": r["mean_pitch"], "revolutions": r["revolutions"],
                         "claim_holds": r["claim_holds"]})
        if progress:
            mine = [r for r in rows if r["model"] == model]
            print(f"  step scan {case.name} {model}: " + ", ".join(
                f"{c} {sum(r['class'] == c for r in mine)}" for c in CLASSES), flush=True)
    return rows


def initial_scan(sat: Satellite | None = None, delta_x0=(0.0, 6.0, 12.0, 20.0, 29.0, 40.0),
                 cases=("nominal", "E1+50%", "damping-x10"),
                 models=("derived", "objective-damper")) -> list:
    """Converged (DOP853) outcome against the balloon's initial offset δx0 [m].

    Table 4.2's δx0 and δy0 were lost (docs/sources.md, "The thesis"); the preset starts
    the balloon near its trail (29 m).  This checks that no headline hinges on it.
    """
    from tethersim.model.presets import load_preset

    sat = load_preset("satI") if sat is None else sat
    rows = []
    for name in cases:
        case = BY_NAME[name]
        for x0 in delta_x0:
            s = case.satellite(sat)
            s = s.replace(initial=(float(x0),) + tuple(s.initial[1:]))
            for model in models:
                r = row_of(run_case(case, s, model, "dop853", case.periods), case, model, "dop853")
                rows.append({"case": name, "model": model, "delta_x0_m": float(x0),
                             "class": r["class"], "theta_ss": r["theta_ss"],
                             "mean_pitch": r["mean_pitch"], "revolutions": r["revolutions"],
                             "claim_holds": r["claim_holds"]})
    return rows


def damper_torque_at_rest(sat: Satellite, delta_x: float, delta_y: float, theta: float) -> float:
    """Q_θ [N m] of the thesis dampers (Eqs 3.43-3.44) with the formation at rest in the
    rotating frame: ω [c1 b² + c2 a² − (c1 b − c2 a)(δx sin θ + δy cos θ)].

    The relative inertial velocity of a tether's ends at rest is ω ẑ × (r3 − r_end),
    so the damper resists the formation's rigid rotation at the orbital rate; the
    objective (Kelvin-Voigt) damper gives zero here.
    """
    s = sat
    return s.omega * (s.c1 * s.b**2 + s.c2 * s.a**2 - (s.c1 * s.b - s.c2 * s.a)
                      * (delta_x * math.sin(theta) + delta_y * math.cos(theta)))
