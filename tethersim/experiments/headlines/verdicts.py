"""Verdicts: does each headline claim survive converged integration, and why not."""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis.classify import CLASSES, FAILED
from tethersim.analysis.metrics import wrap
from tethersim.experiments.headlines.cases import (
    AGREE_TOL,
    BY_NAME,
    SCHEMES,
    STEP_DIVISORS,
    TRENDS,
    VERDICTS,
    yes_no,
)

UNDECIDED = VERDICTS[-1]


# --- verdicts ---------------------------------------------------------------------------
def _outcome(row: dict) -> str:
    if row["class"] == CLASSES[FAILED]:
        return f"failed ({row['status']})"
    txt = (f"{row['class']}, θ_ss {row['theta_ss']:+.3f} rad, mean {row['mean_pitch']:+.3f} rad, "
           f"θ in [{row['theta_min']:+.2f}, {row['theta_max']:+.2f}]")
    if row["class"] == "stable":
        txt += f", settled {row['settling_h']:.0f} h"
    if row["revolutions"] >= 1:
        txt += f", {row['revolutions']:.1f} revolutions"
    return txt


def _decide(converged: dict, faithful: dict, step_dependent: bool) -> str:
    """converged/faithful: {model: claim holds (None: the run was too short to decide)}."""
    if any(v is None for v in converged.values()):
        return UNDECIDED
    if step_dependent and any(faithful.values()) and not any(converged.values()):
        return "artefact of the step"
    if converged and all(converged.values()):
        return "survives"
    if any(converged.values()):
        return "depends on the damper model"
    return "does not survive"


def verdicts(rows: list) -> list:
    """One dict per claim: thesis claim, our converged outcome, whether the faithful
    scheme reproduces the claim, whether outcomes depend on the step or the model,
    and the verdict (one of VERDICTS).

    step_dependent: for some model the RK4 amplification at the thesis's step
    exceeds 1, or a run at the thesis's, half or quarter step differs from the
    converged DOP853 run in class, in the claim, or in θ_ss by AGREE_TOL or more.
    model_dependent: the converged runs of the models disagree on the claim.
    """
    out = []
    for name in dict.fromkeys(r["case"] for r in rows):
        rs = [r for r in rows if r["case"] == name]
        case = BY_NAME.get(name)
        by = {(r["model"], r["scheme"]): r for r in rs}
        models = list(dict.fromkeys(r["model"] for r in rs))
        conv = {m: by[(m, "dop853")]["claim_holds"] for m in models if (m, "dop853") in by}
        faith = {m: by[(m, "rk4-thesis")]["claim_holds"] for m in models
                 if (m, "rk4-thesis") in by}
        step_dep, why = False, []
        for m in models:
            amp = max(r["amp_thesis_step"] for r in rs if r["model"] == m)
            if amp > 1.0:
                step_dep = True
                why.append(f"{m}: RK4 amplification {amp:.3g} > 1 at the thesis step")
            ref = by.get((m, "dop853"))
            if ref is None:
                continue
            for sch in STEP_DIVISORS:
                r = by.get((m, sch))
                if r is None:
                    continue
                if r["class"] != ref["class"] or r["claim_holds"] != ref["claim_holds"]:
                    step_dep = True
                    why.append(f"{m}/{sch}: {r['class']} vs converged {ref['class']}")
                elif not abs(float(wrap(r["theta_ss"] - ref["theta_ss"]))) < AGREE_TOL:
                    step_dep = True
                    why.append(f"{m}/{sch}: θ_ss off by "
                               f"{abs(float(wrap(r['theta_ss'] - ref['theta_ss']))):.3g} rad")
        model_dep = len(set(conv.values())) > 1
        main = by.get(("derived", "dop853")) or next(
            (r for r in rs if r["scheme"] == "dop853"), rs[0])
        out.append({
            "case": name, "page": case.page if case else rs[0]["page"],
            "claim": case.claim if case else "", "change": rs[0]["change"],
            "converged_outcome": _outcome(main), "converged_model": main["model"],
            "converged_claim_holds": conv, "faithful_reproduces": faith,
            "faithful_outcome": {m: _outcome(by[(m, "rk4-thesis")]) for m in faith},
            "step_dependent": step_dep, "step_notes": "; ".join(why),
            "model_dependent": model_dep,
            "verdict": _decide(conv, faith, step_dep),
        })
    out += _trend_verdicts(rows)
    return out


def _trend_verdicts(rows: list) -> list:
    out = []
    by = {(r["case"], r["model"], r["scheme"]): r for r in rows}
    models = list(dict.fromkeys(r["model"] for r in rows))
    for name, page, claim, lo, hi, sign in TRENDS:
        res = {}
        for m in models:
            for sch in SCHEMES:
                a, b = by.get((lo, m, sch)), by.get((hi, m, sch))
                if a is None or b is None:
                    continue
                d = b["mean_pitch"] - a["mean_pitch"]
                holds = bool(math.isfinite(d) and np.sign(d) == sign)
                if not (a.get("decided", True) and b.get("decided", True)):
                    holds = None  # the mean pitch of a run too short to decide
                res[(m, sch)] = (d, holds)
        if not res:
            continue
        conv = {m: v[1] for (m, sch), v in res.items() if sch == "dop853"}
        faith = {m: v[1] for (m, sch), v in res.items() if sch == "rk4-thesis"}
        step_dep = any(v[1] != conv.get(m, v[1]) for (m, sch), v in res.items())
        d_main = res.get(("derived", "dop853"), next(iter(res.values())))[0]
        out.append({
            "case": name, "page": page, "claim": claim, "change": f"{lo} -> {hi}",
            "converged_outcome": f"mean pitch changes by {d_main:+.3f} rad from {lo} to {hi}",
            "converged_model": "derived", "converged_claim_holds": conv,
            "faithful_reproduces": faith, "faithful_outcome": {},
            "step_dependent": step_dep, "step_notes": "",
            "model_dependent": len(set(conv.values())) > 1,
            "verdict": _decide(conv, faith, step_dep),
        })
    return out


def format_verdicts(vs: list) -> str:
    lines = []
    for v in vs:
        conv = yes_no(v["converged_claim_holds"])
        faith = yes_no(v["faithful_reproduces"])
        lines += [f"{v['case']} (p. {v['page']}; {v['change']}): {v['verdict'].upper()}",
                  f"    thesis:    {v['claim']}",
                  f"    converged: {v['converged_outcome']} ({v['converged_model']})",
                  f"    claim holds, converged: {conv}",
                  f"    claim holds, thesis's RK4 step: {faith}",
                  f"    step-dependent: {'yes' if v['step_dependent'] else 'no'}"
                  + (f" ({v['step_notes']})" if v["step_notes"] else "")
                  + f"; model-dependent: {'yes' if v['model_dependent'] else 'no'}"]
    return "\n".join(lines)
