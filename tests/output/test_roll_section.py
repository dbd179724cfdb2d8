"""The report's roll section (tethersim/output/roll_section.py): its numbers are the roll
analysis's (tethersim.analysis.roll), computed afresh here, and its figure exists."""
from __future__ import annotations

import html
import math
import re

import pytest

import tethersim
from tethersim.analysis.roll import roll_case, roll_response, roll_yaw_quartic
from tethersim.output.page import Page, write_html
from tethersim.output.roll_section import DAMPS, ROWS, START, section_roll

# compiles and runs the 3-D kernels: the slow tier (make test-slow, CI)
pytestmark = pytest.mark.slow
PERIODS = 6.0


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("roll_report")
    (out / "img").mkdir()
    page = Page(out)
    nums = section_roll(page, PERIODS)
    return page, nums, write_html(page).read_text()


def _rows(text: str, first_header: str) -> dict:
    """{first cell: [cells]} of the table whose first header is ``first_header``."""
    for t in re.findall(r"<table.*?</table>", text, re.S):
        cells = [[html.unescape(c) for c in re.findall(r"<t[dh]>(.*?)</t[dh]>", r)]
                 for r in re.findall(r"<tr>(.*?)</tr>", t, re.S)]
        if cells and cells[0][0] == first_header:
            return {r[0]: r for r in cells[1:]}
    raise AssertionError(f"no table headed {first_header!r}")


def test_roll_section_is_on_the_page_with_its_figure(built):
    page, _, text = built
    assert "Does the balloon make the satellite resist rolling?" in text
    assert (page.out / "img" / "roll.png").stat().st_size > 10_000
    assert 'src="img/roll.png"' in text


def test_linear_mode_table_is_the_roll_analysis_of_each_case(built):
    _, nums, text = built
    sat = tethersim.load_preset("satI")
    n = sat.omega
    rows = _rows(text, "case")
    assert set(rows) == {label for label, _, _ in ROWS}
    for label, case, model in ROWS:
        c = roll_case(sat, case, model)  # afresh, not the section's objects
        roll = c.mode("roll")
        assert rows[label][2] == f"{roll.frequency / n:.4f}"
        hours = roll.decay_time / 3600
        assert rows[label][3] == (f"{hours:,.0f}" if hours >= 1e4 else f"{hours:.4g}")
        assert rows[label][4] == f"{c.pitch.frequency / n:.4f}"
        assert nums["cases"][label].mode("roll").eigenvalue == roll.eigenvalue
    assert f"= {math.sqrt(-roll_yaw_quartic(sat)[0]):.4f} n" in text


def test_run_table_is_the_roll_response_of_each_damper(built):
    _, nums, text = built
    sat = tethersim.load_preset("satI")
    rows = _rows(text, "damper")
    for label, model in (("thesis damper", "3d"), ("objective damper", "3d-objective-damper")):
        r = roll_response(sat, model, periods=PERIODS, **START)
        assert rows[label][1] == r.result.status == "ok"
        assert rows[label][2] == f"{1 / r.roll_decay_rate / 3600:.4g}"
        assert rows[label][3] == f"{math.degrees(r.orbit_peaks['phi'][-1]):.3g}"
        assert nums["responses"][label].roll_decay_rate == r.roll_decay_rate


def test_the_facts_row_answers_the_abstract_with_the_computed_verdict(built):
    page, nums, text = built
    (statement, pg, ours, verdict, why), = [f for f in page.facts if "rolling" in f[0]]
    assert pg == "iv, 1-1"
    tau = {label: nums["cases"][label].mode("roll").decay_time for label, _, _ in ROWS[:3]}
    thesis, objective, boom = tau.values()
    # the thesis damper damps roll far faster than the boom alone; an along-tether one does not
    assert thesis * DAMPS < boom and not objective * DAMPS < boom
    assert verdict == nums["verdict"] == "partly" and "thesis's own model" in why
    assert f"{thesis / 3600:.4g} h with the thesis damper" in ours
    assert nums["stiffening"] < 0.01  # the balloon adds no roll stiffness to speak of


def test_roll_section_does_not_overflow_the_page_in_headless_chromium(built, tmp_path):
    from tests.output.test_report import _measure

    page, _, text = built
    window, scroll, client, wide = _measure(text, page.out, 800, tmp_path)
    assert window == 800 and scroll <= client, f"{scroll} px wide in {client} px: {wide}"
