"""Headlines, tune and compare on runs too short to decide a class (issue 19): "undecided",
never "claim holds", a band or "all variants end offset"."""
from __future__ import annotations

import pytest

import tethersim as ts
from tests.tiers import VARIANT_LOOP
from tethersim.analysis.metrics import min_run_orbits
from tethersim.experiments import headlines as hl

SAT = ts.load_preset("satI")


def _row(case, cls="undecided", decided=False, revolutions=0.0, tumbled=False, mean=0.0):
    r = {"case": case, "page": hl.BY_NAME[case].page, "change": hl.BY_NAME[case].change,
         "model": "derived", "scheme": "dop853", "class": cls, "status": "ok",
         "theta_ss": mean, "mean_pitch": mean, "settling_h": 40.0, "theta_min": -0.5,
         "theta_max": 0.5, "revolutions": revolutions, "tumbled": tumbled,
         "amp_thesis_step": 0.9, "decided": decided}
    r["claim_holds"] = hl.claim_holds(hl.BY_NAME[case].check, r)
    return r


def test_no_claim_is_decided_on_a_run_too_short_to_show_it():
    for name, case in hl.BY_NAME.items():
        assert hl.claim_holds(case.check, _row(name)) is None, name


def test_what_a_short_run_already_shows_decides_its_claim():
    full_turn = _row("E1+50%", cls="tumbling", revolutions=1.2, tumbled=True)
    assert hl.claim_holds("tumbles", full_turn) is True
    assert hl.claim_holds("bounded", full_turn) is False


def test_a_short_headline_run_is_undecided_not_claim_holds():
    """Issue 19: `headlines satI --periods 0.01` said "claim holds"."""
    rows = hl.run_headlines(SAT, models=("derived",), cases=["nominal"], periods=0.01,
                            progress=False, schemes=("dop853",))
    assert rows and all(r["class"] == "undecided" and r["claim_holds"] is None for r in rows)
    v = hl.verdicts([{**r, "amp_thesis_step": 0.9} for r in rows])[0]
    assert v["verdict"] == "undecided: run longer"
    assert "derived undecided" in hl.format_verdicts([v])


def test_a_trend_between_short_runs_is_undecided():
    rows = []
    for name, mean in (("E1-10%", 1.0), ("E1+10%", -1.0)):
        for scheme in hl.SCHEMES:
            rows.append({**_row(name, mean=mean), "scheme": scheme})
    trend = {v["case"]: v for v in hl.verdicts(rows)}["E1 trend"]
    assert trend["verdict"] == "undecided: run longer"


def test_tune_refuses_runs_too_short_to_decide_before_running_anything():
    from tethersim.experiments.tune import stable_band_E2, tune
    for f in (stable_band_E2, tune):
        with pytest.raises(ValueError, match=r"^periods = 0.05: too short") as e:
            f(SAT, periods=0.05)
        assert "\n" not in str(e.value) and f"{min_run_orbits():.4g}" in str(e.value)


@VARIANT_LOOP
def test_compare_of_short_runs_reports_undecided_variants():
    from tethersim.experiments.compare import compare, comparison_table, outcome_differences
    rows = comparison_table(compare(SAT, ("derived", "printed"), periods=0.1, progress=False))
    assert [r["class"] for r in rows] == ["undecided", "undecided"]
    assert outcome_differences(rows) == []
