"""docs/speed.md from a full bench run's bench/results.json: the figures are never typed.

``python bench/run.py`` (``make bench``) writes results.json and then this page; run it
alone (``python bench/speedpage.py``) to rewrite the page from a results.json at hand.
The page names the machine, the versions and the load, then the targets (measured,
limit, PASS / MISS), every figure by section and the sanity checks.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
PAGE = HERE.parent / "docs" / "speed.md"
# figure-key prefix -> section title, in the page's order (a key's prefix is the part
# before its first "." or, for the heyoka figures, the word "heyoka")
SECTIONS = {
    "rhs": "Right-hand side, one call (numba against the C port)",
    "rk4": "RK4 loop, 50 orbits in 10,000 steps",
    "simulate": "`simulate()` with its defaults",
    "dop853": "DOP853 loop, rtol 1e-10, 50 orbits",
    "3d": "3-D model against its C port",
    "tools": "Baselines (sympy.lambdify, PyDy, solve_ivp)",
    "sweep": "Sweeps: one thread against all",
    "csweep": "Sweeps against a C+OpenMP driver (144 SatI points)",
    "lanes": "SIMD lanes against the scalar block",
    "heyoka": "heyoka.py at equal accuracy",
    "stiff": "Real (stiff) tethers: Radau IIA",
    "models": "Plans of the 3-D, free-orbit and MSIS-air models against bare runs",
    "derive": "`make derive`",
    "cli": "Command line: cold and warm runs",
    "report": "`tethersim report`",
}


def fmt(v, unit) -> str:
    """A figure's value in its unit (seconds scaled to ns, µs, ms)."""
    if v is None:
        return "-"
    if isinstance(v, dict):  # phases of one figure
        return "; ".join(f"{k}: {fmt(x, unit)}" for k, x in v.items())
    if unit == "s":
        if v < 1e-6:
            return f"{v * 1e9:.1f} ns"
        if v < 1e-3:
            return f"{v * 1e6:.2f} µs"
        if v < 1:
            return f"{v * 1e3:.2f} ms"
        return f"{v:.2f} s"
    if unit == "x":
        return f"{v:.2f}×" if v < 100 else f"{v:.0f}×"
    if unit == "count":
        return f"{int(v):,}"
    return f"{v:.4g} {unit}"


def _section(key: str) -> str:
    return "heyoka" if key.startswith("heyoka") else key.split(".")[0]


def _cell(text, width: int = 0) -> str:
    """Text for a table cell or list item: one line, "|" escaped, at most ``width``
    characters (0: all)."""
    text = " ".join(str(text).split())
    if width and len(text) > width:
        text = text[:width - 1] + "…"
    return text.replace("|", "\\|")


def render(doc: dict) -> str:
    """The page's Markdown from a results.json document."""
    m = doc["meta"]
    load = f"{m['loadavg_start'][0]:.2f} at the start, {m['loadavg_end'][0]:.2f} at the end"
    lines = [
        "# Speed: the last full bench run",
        "",
        "Written by `python bench/run.py` (`make bench`) from `bench/results.json`; do not "
        "edit by hand. Every ratio is measured in one process, the two sides interleaved, "
        "thread CPU time (wall time where several threads run), best or median of repeats as "
        "each label says. A ratio measured on one CPU may not hold on another: rerun "
        "`make bench` on yours. How the peers are built and why the targets are what they "
        "are: the README's *Speed* section.",
        "",
        f"- machine: {m['cpu']}, {m['cores']} cores; load average {load}",
        f"- run: {m['timestamp']}, {m['bench_wall_s']:.0f} s"
        f"{' (--quick)' if m.get('quick') else ''}",
        f"- python {m['python']}, numpy {m['numpy']}, numba {m['numba']}, scipy {m['scipy']}, "
        f"sympy {m['sympy']}; {m['gcc']}",
        "",
        "## Targets",
        "",
        "| target | measured | limit | status | note |",
        "|---|---|---|---|---|",
    ]
    for t in doc["targets"]:
        limit = "" if t["op"] == "info" else f"{t['op']} {fmt(t['limit'], t['unit'])}"
        lines.append(f"| {_cell(t['label'])} | {fmt(t['value'], t['unit'])} | {limit} | "
                     f"{t['status']} | {_cell(t.get('note', ''))} |")
    groups: dict = {}
    for key, f in doc["figures"].items():
        groups.setdefault(_section(key), []).append(f)
    for name in [*SECTIONS, *sorted(set(groups) - set(SECTIONS))]:
        if name not in groups:
            continue
        lines += ["", f"## {SECTIONS.get(name, name)}", "", "| figure | value | note |",
                  "|---|---|---|"]
        for f in groups[name]:
            spread = (f" (n = {f['n']}, ±{100 * f['spread']:.0f} %)"
                      if f.get("n", 0) >= 4 else "")
            lines.append(f"| {_cell(f['label'])} | {fmt(f['value'], f['unit'])}{spread} | "
                         f"{_cell(f.get('note', ''))} |")
    ok = sum(c["ok"] for c in doc["checks"])
    lines += ["", f"## Sanity checks: {ok} of {len(doc['checks'])} hold", ""]
    lines += [f"- {'ok' if c['ok'] else '**FAILED**'}: {_cell(c['label'])}"
              f"{': ' + _cell(c['detail'], 160) if c['detail'] else ''}"
              for c in doc["checks"]]
    if doc["notes"]:
        lines += ["", "## Notes", ""] + [f"- {_cell(n)}" for n in doc["notes"]]
    return "\n".join(lines) + "\n"


def write(results: Path = HERE / "results.json", page: Path = PAGE) -> Path:
    """Render ``results`` into ``page``; the page's path."""
    page.write_text(render(json.loads(Path(results).read_text())), encoding="utf-8")
    return page


if __name__ == "__main__":
    print(write(*map(Path, sys.argv[1:3])))
