"""tethersim report: one HTML page whose figures exist and whose facts table covers the thesis."""
from __future__ import annotations

import contextlib
import html
import io
import os
import re
import shutil
import subprocess

import pytest

from tests.tiers import VARIANT_LOOP
from tethersim.experiments.sweep.plan import CLASS_RTOL
from tethersim.output.report import MAPS, build_report


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """(the report's index.html, what building it wrote to stderr)."""
    out = tmp_path_factory.mktemp("report")
    # the roll section compiles the 3-D kernels (minutes on a cold cache), the real-tether
    # section the implicit loop of objective-damper (~15 s): each is built and checked in the
    # slow tier, tests/output/test_roll_section.py and test_real_section.py; the headline
    # cases run the loops of the printed and objective-damper models, so every test of the
    # built page is slow-tier too (tests/tiers.py)
    err = io.StringIO()
    with contextlib.redirect_stderr(err):  # the progress bars' stream (tqdm)
        index = build_report(out, grid=3, periods=2.0, progress=False, log=lambda *a: None,
                             roll=False, real=False)
    return index, err.getvalue()


@pytest.fixture(scope="module")
def report(built):
    return built[0]


@VARIANT_LOOP
def test_report_without_progress_shows_no_progress_bar(built):
    # --quiet: the feasibility atlas's bar was left on (run_feasibility's default, a bar
    # after a second)
    err = built[1]
    assert "point/s" not in err and "s/point" not in err and "%|" not in err, err[-500:]


@VARIANT_LOOP
def test_report_links_only_figures_that_exist(report):
    text = report.read_text()
    srcs = re.findall(r'<img src="([^"]+)"', text)
    assert len(srcs) >= len(MAPS) + 3
    for s in srcs:
        assert (report.parent / s).is_file(), s


@VARIANT_LOOP
def test_report_sets_thesis_statements_beside_ours_with_a_verdict(report):
    text = report.read_text()
    rows = re.findall(r'<tr class="(yes|no|partly)">', text)
    assert len(rows) >= 15
    for needle in ("3.18", "two days", "28 m", "E2/E1", "26.55"):
        assert needle in text, needle
    assert "no" in rows, "the report must say where we disagree with the thesis"


@VARIANT_LOOP
def test_report_map_table_shows_the_classes_its_stores_hold(report):
    """The numbers on the page are those of the stored sweeps, not written-in text."""
    from tethersim.experiments.sweep import open_dataset
    from tethersim.experiments.sweep.analysis import class_counts
    text = report.read_text()
    stores = sorted((report.parent / "sweeps").glob("*_adaptive_*.zarr"))
    assert stores
    for store in stores:
        counts = class_counts(open_dataset(store))
        shown = ", ".join(f"{k} {v}" for k, v in counts.items() if v)
        assert f"<td>{shown}</td>" in text, (store.name, shown)


@VARIANT_LOOP
def test_report_sweeps_are_stored_and_resumable(report):
    entries = sorted(p.name for p in (report.parent / "sweeps").iterdir())
    stores = [s for s in entries if s.endswith(".zarr")]
    assert len(stores) == 2 * len(MAPS)  # converged + faithful per map
    # beside each store only its writer lock and the holder's name (sweep/lock.py)
    assert set(entries) - set(stores) <= {s + e for s in stores for e in (".lock", ".lock.json")}
    assert all(s.endswith(f"_3x3_2orbits_rtol{CLASS_RTOL:g}.zarr") for s in stores)


def test_report_refuses_a_bad_grid(tmp_path):
    with pytest.raises(ValueError, match="grid"):
        build_report(tmp_path, grid=1)


def _cells(table_html):
    rows = re.findall(r"<tr[^>]*>(.*?)</tr>", table_html, re.S)
    return [[html.unescape(re.sub(r"<[^>]+>", "", c)).strip()
             for c in re.findall(r"<t[dh]>(.*?)</t[dh]>", r, re.S)] for r in rows]


@VARIANT_LOOP
def test_report_fact_rows_are_distinct_statements(report):
    text = report.read_text()
    facts = _cells(re.search(r"<table class='facts'>.*?</table>", text, re.S).group(0))[1:]
    rendered = ["|".join(r) for r in facts]
    assert len(set(rendered)) == len(rendered), "two fact rows render identically"
    statements = [(r[0], r[1]) for r in facts]
    assert len(set(statements)) == len(statements), "two fact rows make the same statement"


@VARIANT_LOOP
def test_report_has_no_column_that_is_all_zero_or_empty(report):
    from tethersim.output.page import is_blank
    text = report.read_text()
    for tab in re.findall(r"<table.*?</table>", text, re.S):
        rows = _cells(tab)
        header, body = rows[0], rows[1:]
        for i, name in enumerate(header):
            assert not all(is_blank(r[i]) for r in body if i < len(r)), name


def test_report_states_why_it_leaves_a_column_out():
    from tethersim.output.page import table
    out = table(("a", "b"), [(1, "—"), (2, "0")], reasons={"b": "nothing to show"})
    assert "<th>b</th>" not in out and "nothing to show" in out and "<th>a</th>" in out


@VARIANT_LOOP
def test_report_headline_results_are_a_table(report):
    text = report.read_text()
    heads = [t for t in re.findall(r"<table.*?</table>", text, re.S) if "<th>verdict</th>" in t]
    assert len(heads) == 1
    rows = _cells(heads[0])[1:]
    assert {"nominal", "damping-x10", "E1+50%"} <= {r[0] for r in rows}


def _chromium():
    return shutil.which("chromium") or shutil.which("chromium-browser")


MEASURE = """<script>window.addEventListener('load', function () {
  var vw = document.documentElement.clientWidth, wide = [];
  document.querySelectorAll('body *').forEach(function (e) {
    var r = e.getBoundingClientRect();
    if (r.right > vw + 0.5) wide.push(e.tagName + ':' + Math.round(r.right));
  });
  var p = document.createElement('pre'); p.id = 'measure';
  p.textContent = 'window=' + window.innerWidth + ' scroll=' +
                  document.documentElement.scrollWidth + ' client=' + vw +
                  ' wide=' + wide.slice(0, 5).join(',');
  document.body.appendChild(p);
});</script>"""


def _measure(html_text, folder, width, profile):
    """Render ``html_text`` (written into ``folder``) at ``width`` px in headless Chromium;
    return (window width, document scroll width, layout width, the overflowing elements)."""
    exe = _chromium()
    if exe is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is not installed, and CI must render the report (.ci/run)")
        pytest.skip("chromium is not installed (apt-get install chromium); CI installs it")
    page = folder / f"measure_{width}.html"
    page.write_text(html_text.replace("</body>", MEASURE + "</body>"), encoding="utf-8")
    proc = subprocess.run(
        [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--no-first-run", f"--user-data-dir={profile}",
         f"--window-size={width},900", "--virtual-time-budget=10000", "--dump-dom",
         page.as_uri()], capture_output=True, text=True, timeout=120)
    m = re.search(r"window=(\d+) scroll=(\d+) client=(\d+) wide=([^<]*)", proc.stdout)
    assert m, proc.stderr[-2000:]
    return int(m.group(1)), int(m.group(2)), int(m.group(3)), m.group(4)


@VARIANT_LOOP
@pytest.mark.parametrize("width", [1280, 800])
def test_report_does_not_overflow_the_page_in_headless_chromium(report, tmp_path, width):
    window, scroll, client, wide = _measure(report.read_text(), report.parent, width, tmp_path)
    assert window == width
    assert scroll <= client, f"page is {scroll} px wide in a {client} px layout: {wide}"


def test_the_overflow_measure_sees_a_page_that_overflows(tmp_path):
    """The measure is not vacuous: a 3000 px line in an unwrapped block is found."""
    text = "<html><body><pre style='white-space:pre'>" + "x" * 400 + "</pre></body></html>"
    window, scroll, client, wide = _measure(text, tmp_path, 800, tmp_path / "profile")
    assert scroll > client, (scroll, client, wide)
