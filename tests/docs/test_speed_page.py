"""docs/speed.md is rendered from a bench run's results (bench/speedpage.py), not typed."""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).parents[2]
sys.path.insert(0, str(ROOT / "bench"))
import speedpage  # noqa: E402

DOC = {
    "meta": {"cpu": "Test CPU", "cores": 2, "loadavg_start": [0.5], "loadavg_end": [0.7],
             "timestamp": "2026-12-05T13:38:29+0000", "bench_wall_s": 703.2, "quick": False,
             "python": "3.11", "numpy": "2", "numba": "0.68", "scipy": "1.17",
             "sympy": "1.14", "gcc": "gcc 12"},
    "targets": [{"key": "T2", "label": "RK4 loop <= 1.2x C", "value": 1.01, "op": "<=",
                 "limit": 1.2, "unit": "x", "status": "PASS", "note": ""},
                {"key": "h", "label": "ahead of heyoka | single", "value": 0.52, "op": ">=",
                 "limit": 1.0, "unit": "x", "status": "MISS", "note": "see docs"}],
    "figures": {"rk4.numba": {"label": "numba rk4", "value": 2.4e-3, "unit": "s", "n": 15,
                              "spread": 0.02},
                "heyoka_sweep_1": {"label": "sweep ratio", "value": 0.9, "unit": "x",
                                   "note": ">1: tethersim faster"},
                "cli.phases": {"label": "phases", "value": {"import": 0.05, "run": 0.3},
                               "unit": "s"},
                "newsection.x": {"label": "a figure of a new section", "value": 3,
                                 "unit": "count"}},
    "checks": [{"label": "same steps", "ok": True, "detail": ""},
               {"label": "C rhs == numba rhs", "ok": False, "detail": "diff 1e-3"}],
    "notes": ["PyDy skipped"],
}


def test_the_page_names_the_machine_and_every_target_with_its_status():
    page = speedpage.render(DOC)
    assert "Test CPU, 2 cores" in page and "703 s" in page
    assert "| RK4 loop <= 1.2x C | 1.01× | <= 1.20× | PASS |" in page
    # a "|" inside a label is escaped, not a new table column
    assert "| ahead of heyoka \\| single | 0.52× | >= 1.00× | MISS | see docs |" in page


def test_every_figure_lands_in_its_section_in_its_unit():
    page = speedpage.render(DOC)
    rk4, hey = page.index("## RK4 loop"), page.index("## heyoka.py")
    assert rk4 < page.index("2.40 ms (n = 15, ±2 %)") < hey < page.index("| sweep ratio | 0.90× |")
    assert "import: 50.00 ms; run: 300.00 ms" in page  # a figure of several phases
    assert "## newsection" in page and "| a figure of a new section | 3 |" in page


def test_a_failed_sanity_check_is_shown_as_failed():
    page = speedpage.render(DOC)
    assert "1 of 2 hold" in page and "- **FAILED**: C rhs == numba rhs: diff 1e-3" in page


def test_the_committed_page_is_the_renderers_output():
    page = (ROOT / "docs" / "speed.md").read_text(encoding="utf-8")
    assert page.startswith("# Speed: the last full bench run\n\nWritten by `python bench/run.py`")
    assert "## Targets" in page and "## Sanity checks:" in page
