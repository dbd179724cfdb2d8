"""The report's real-tether section (tethersim/output/real_section.py): its table holds the
trim of each configuration as tethersim.experiments.real_tethers computes it afresh, and
its run's loads are the run's own; its real-line atlas table is the atlas's rows."""
from __future__ import annotations

import html
import math
import re

import pytest

from tethersim.analysis.tethers import tether_loads
from tethersim.experiments.real_tethers import trim
from tethersim.output.page import Page, write_html
from tethersim.output.real_section import ATLAS_KM, section_real

# the implicit loop of objective-damper (~15 s to compile cold): the slow tier (CI runs it)
pytestmark = pytest.mark.slow
PERIODS = 2.0


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("real_report")
    (out / "img").mkdir()
    page = Page(out)
    nums = section_real(page, PERIODS)
    return page, nums, write_html(page).read_text()


def _tables(text: str) -> list:
    return [[[html.unescape(c) for c in re.findall(r"<t[dh]>(.*?)</t[dh]>", r)]
             for r in re.findall(r"<tr>(.*?)</tr>", t, re.S)]
            for t in re.findall(r"<table.*?</table>", text, re.S)]


def test_the_trim_table_is_each_configurations_trim_computed_afresh(built):
    page, nums, text = built
    rows = {r[0]: r for r in next(t for t in _tables(text) if t[0][0] == "tethers")[1:]}
    assert len(rows) == 3
    for label, (sat, _) in nums["rows"].items():
        t = trim(sat)
        assert rows[label][3] == f"{t['theta']:+.4f}"
        assert rows[label][6] == f"{t['slowest_decay_h']:.3g}"
    # the stretched real lines hold the trim band over the air's range, the thesis's do not
    verdicts = [r[5] for r in rows.values()]
    assert verdicts[0] == "no" and verdicts[-1] == "yes"


def test_the_loads_table_is_the_runs_own_and_the_figure_exists(built):
    page, nums, text = built
    loads = tether_loads(nums["run"])
    table = next(t for t in _tables(text) if t[0][0] == "tether")
    assert [r[1] for r in table[1:]] == [f"{ld.peak:.4g}" for ld in loads]
    assert nums["run"].t[-1] == pytest.approx(PERIODS * nums["run"].satellite.period)
    assert (page.out / "img" / "real_tensions.png").is_file()
    assert "And on real tethers?" in text


def test_the_real_line_atlas_table_is_the_atlas_rows(built):
    """One row per start altitude, each verdict the atlas's own; a real line does not
    stretch, so the balloon is never lost (docs/real-tethers.md)."""
    page, nums, text = built
    table = next(t for t in _tables(text) if t[0][0] == "start altitude [km]")
    assert [r[0] for r in table[1:]] == [f"{h:g}" for h in ATLAS_KM]
    assert [r[-1] for r in table[1:]] == [r["verdict"] for r in nums["atlas"]]
    assert not any(math.isfinite(r["balloon_lost_h"]) for r in nums["atlas"])
    assert (page.out / "feasibility-real").is_dir()


def test_the_single_line_reach_is_the_satellites_own(built):
    """The one-line paragraph prints s_c of the report's satellite, in centimetres."""
    from tethersim.experiments.real_tethers import single_line_reach
    from tethersim.model.presets import load_preset
    _, _, text = built
    reach = single_line_reach(load_preset("satI"))
    assert f"s_c = 3 ω² I / D = {100 * reach:.3g} cm" in html.unescape(text)


def test_the_deployment_table_is_the_deployments_own(built):
    from tethersim.experiments.deployment import arrival, deploy
    from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
    from tethersim.model.presets import load_preset
    from tethersim.output.real_section import ARRIVAL

    page, nums, text = built
    table = next(t for t in _tables(text) if t[0][0] == "end of the deployment")
    rows = {r[0]: r for r in table[1:]}
    assert len(rows) == 2
    braked = deploy(arrival(real_lines(load_preset("satI"), STRETCHED_LENGTHS), ARRIVAL))
    first = rows[f"braked arrival at {ARRIVAL:g} m/s"]
    assert first[1:3] == [f"{braked.first_peak:.4g}", f"{braked.safety_factor:.4g}"]
    # a braked arrival keeps the boom upright; a free release turns it over
    assert [r[4] for r in rows.values()] == ["no", "yes"]
