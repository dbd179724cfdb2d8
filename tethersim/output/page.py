"""The HTML page of ``tethersim report``: sections, figures, tables and the facts table.

Every table goes through :func:`table`, which leaves out a column whose every
cell is empty, ``—`` or zero and says so under the table with the reason; the
CSS lets cells wrap anywhere and images shrink, so the page never scrolls
sideways (tests/output/test_report.py renders it in headless Chromium).
"""
from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from tethersim.output.files import write_text

FACTS_SOURCE = "docs/sources.md, The thesis: what survives"
_ZERO = re.compile(r"^[+-]?(0(\.0*)?|—|nan|none|)( of \d+)?( ?%)?$", re.I)
CSS = ("*{box-sizing:border-box}"
       "body{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em}"
       "table{border-collapse:collapse;margin:1em 0;max-width:100%;table-layout:auto}"
       "td,th{border:1px solid #bbb;padding:3px 6px;font-size:13px;vertical-align:top;"
       "overflow-wrap:anywhere}th{background:#eee;overflow-wrap:normal}"
       # the facts table's page and verdict columns: short words, never split inside one
       ".facts td:nth-child(2){overflow-wrap:normal}"
       ".facts td:nth-child(4){overflow-wrap:normal;white-space:nowrap}"
       "pre{background:#f6f6f6;padding:8px;font-size:12px;white-space:pre-wrap;"
       "overflow-wrap:anywhere}"
       "img{max-width:100%;height:auto}figure{margin:1em 0}"
       "figcaption,.note{font-size:12px;color:#555}"
       ".yes{background:#e8f5e9}.no{background:#ffebee}.partly{background:#fff8e1}")


@dataclass
class Page:
    """HTML fragments, figures and the facts table, filled in section by section."""

    out: Path
    sections: list = field(default_factory=list)
    facts: list = field(default_factory=list)  # (statement, page, ours, agrees, why)
    timings: list = field(default_factory=list)

    def img(self, path: Path, caption: str) -> str:
        """An ``<img>`` of ``path`` (relative to the page) with its caption."""
        rel = Path(path).relative_to(self.out)
        return (f'<figure><img src="{html.escape(str(rel))}">'
                f"<figcaption>{html.escape(caption)}</figcaption></figure>")

    def add(self, title: str, body: str) -> None:
        """Append a section."""
        self.sections.append((title, body))

    def fact(self, statement, page, ours, agrees, why="") -> None:
        """Add a row to the facts table.

        Raises
        ------
        ValueError
            When a row with the same statement and page is already there: each row
            must be a distinct statement of the thesis.
        """
        if any((s, p) == (statement, page) for s, p, *_ in self.facts):
            raise ValueError(f"facts table: {statement!r} (p. {page}) is already a row")
        self.facts.append((statement, page, ours, agrees, why))


def pre(text: str) -> str:
    """Preformatted text (wraps rather than overflows)."""
    return f"<pre>{html.escape(text)}</pre>"


def cell(v, fmt=".3g") -> str:
    """A number formatted for a table cell; ``—`` for None or a non-finite float."""
    return "—" if v is None or (isinstance(v, float) and not math.isfinite(v)) else format(v, fmt)


def is_blank(cell) -> bool:
    """True for an empty, ``—``, NaN or zero cell (``0``, ``0.000``, ``0 of 9``, ``0 %``)."""
    if isinstance(cell, float) and not math.isfinite(cell):
        return True
    return bool(_ZERO.match(str(cell).strip()))


def table(header, rows, reasons: dict | None = None, caption: str = "") -> str:
    """An HTML table; a column with nothing but blanks is left out, with its reason below.

    Parameters
    ----------
    header : sequence of str
        Column titles.
    rows : sequence of sequence
        Cells (converted with ``str``).
    reasons : dict, optional
        Column title -> why that column can be empty (said when it is left out).
    caption : str, optional
        A note printed under the table.

    Returns
    -------
    str
        The HTML.
    """
    rows = [tuple(r) for r in rows]
    keep = [i for i in range(len(header)) if not rows or not all(is_blank(r[i]) for r in rows)]
    notes = [f"column “{header[i]}” left out: every value is 0 or none"
             + (f" ({reasons[header[i]]})" if reasons and header[i] in reasons else "")
             for i in range(len(header)) if i not in keep]
    h = "".join(f"<th>{html.escape(str(header[i]))}</th>" for i in keep)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(r[i]))}</td>" for i in keep)
                   + "</tr>" for r in rows)
    foot = "".join(f'<p class="note">{html.escape(n)}.</p>' for n in [caption] + notes if n)
    return f"<table><tr>{h}</tr>{body}</table>{foot}"


def write_html(page: Page) -> Path:
    """Write OUT/index.html: the facts table first, then the sections; return its path."""
    facts = "".join(
        f'<tr class="{html.escape(a)}"><td>{html.escape(s)}</td><td>{html.escape(str(p))}</td>'
        f"<td>{html.escape(o)}</td><td>{html.escape(a)}</td><td>{html.escape(w)}</td></tr>"
        for s, p, o, a, w in page.facts)
    toc = "".join(f'<li><a href="#s{i}">{html.escape(t)}</a></li>'
                  for i, (t, _) in enumerate(page.sections))
    secs = "".join(f'<h2 id="s{i}">{html.escape(t)}</h2>{b}'
                   for i, (t, b) in enumerate(page.sections))
    timing = ", ".join(f"{t} {s:.0f} s" for t, s in page.timings)
    doc = (f"<!doctype html><html><head><meta charset='utf-8'>"
           f"<meta name='viewport' content='width=device-width'><title>tethersim report</title>"
           f"<style>{CSS}</style></head><body><h1>tethersim: thesis chapter 5, recomputed</h1>"
           f"<p>Maramba (AFIT 2005), rebuilt. Conventions: docs/conventions.md; errata of the "
           f"printed equations: docs/errata.md; metrics: docs/metrics.md. Presets are "
           f"reconstructions (the thesis's Table 4.1 was lost): see their comments.</p>"
           f"<h2>The thesis's statements beside ours ({FACTS_SOURCE})</h2>"
           f"<table class='facts'><tr><th>thesis</th><th>page</th><th>tethersim</th>"
           f"<th>agrees</th><th>why / notes</th></tr>{facts}</table><ul>{toc}</ul>{secs}"
           f"<p class='note'>Section wall times: {timing}.</p></body></html>")
    path = page.out / "index.html"
    return write_text(path, doc)
