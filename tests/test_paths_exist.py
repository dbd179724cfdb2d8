"""Every repository path named in the docs and in the code's docstrings and comments exists.

Files move; a path in README.md, docs/ or a docstring that names the old place sends
a reader nowhere.  Paths are recognised by their first folder (the repository's
top-level folders); a ``*`` is a glob that must match at least one file.  Build
outputs that git ignores (``bench/_build/``, ``bench/results.json``) are named as
what a command writes, so they are exempt.
"""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TOP = ("tethersim", "derive", "generated", "docs", "tests", "bench", "tools")
PATH = re.compile(r"(?<![\w/.-])((?:" + "|".join(TOP) + r")/[\w./*-]*[\w/*])")
WRITTEN_BY_COMMANDS = ("bench/_build/", "bench/results.json")


def _named_paths():
    files = [ROOT / "README.md", *sorted(ROOT.glob("docs/**/*.md"))]
    files += sorted(p for d in ("tethersim", "derive", "tools", "bench", "tests")
                    for p in (ROOT / d).rglob("*.py"))
    for f in files:
        for m in PATH.finditer(f.read_text()):
            yield f.relative_to(ROOT), m.group(1).rstrip(".")


def _exists(path: str) -> bool:
    if "*" in path:
        try:
            return any(ROOT.glob(path))
        except ValueError:  # 'free*' style: ** only as a whole component
            return any(ROOT.glob(re.sub(r"\*+", "*", path)))
    # a dotted name after a module (bench/engine_bench.derivative_entry) is the module
    return (ROOT / path).exists() or (ROOT / (path.split(".")[0] + ".py")).exists()


def test_every_named_repository_path_exists():
    missing = sorted({f"{path} (named in {where})" for where, path in _named_paths()
                      if not path.startswith(WRITTEN_BY_COMMANDS) and not _exists(path)})
    assert missing == []


def test_the_docs_do_not_send_users_to_files_outside_the_project():
    # shared/ is the developers' material beside the checkout: users do not have it, so the
    # facts the project uses are carried into docs/sources.md
    outside = sorted({str(where) for where, text in
                      ((f.relative_to(ROOT), f.read_text()) for f in
                       [ROOT / "README.md", *ROOT.glob("docs/**/*.md"),
                        *ROOT.glob("tethersim/**/*.py"), *ROOT.glob("tethersim/**/*.toml"),
                        *ROOT.glob("derive/**/*.py")])
                      if "shared/" in text})
    assert outside == []
