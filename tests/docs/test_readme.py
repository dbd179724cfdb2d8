"""The README runs as written (issue 19): its command and Python blocks, in order.

Every ``sh`` block's ``tethersim`` lines and every ``python`` block of README.md
run, top to bottom, in one fresh folder, as a user following the README would.
A command must exit 0, or 1 where its comment says the run ends outside the
model's domain ("exit 1"); it must print no traceback.  ``make`` lines are the
set-up, which CI has just run.  Slow tier: the whole README is several minutes of
simulation (CI runs it).
"""
from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"
BLOCK = re.compile(r"^```(\w+)\n(.*?)^```", re.S | re.M)


def blocks(text: str) -> list:
    """[(language, code)] of the fenced blocks, in order."""
    return [(m.group(1), m.group(2)) for m in BLOCK.finditer(text)]


def commands(code: str) -> list:
    """[(argv, expected exit code, line)] of an sh block's tethersim commands."""
    out = []
    for line in code.replace("\\\n", " ").splitlines():
        command, _, comment = line.partition(" #")
        for part in command.split(";"):
            argv = shlex.split(part)
            if not argv or argv[0] != "tethersim":
                if argv and argv[0] != "make":
                    raise AssertionError(f"README line neither tethersim nor make: {line}")
                continue
            out.append((argv[1:], 1 if "exit 1" in comment else 0, line.strip()))
    return out


def test_the_readme_blocks_are_understood():
    # the parser itself: every sh block line is a tethersim or make command, and there is
    # a Python block (a renamed fence would otherwise silently test nothing)
    found = blocks(README.read_text())
    assert sum(lang == "python" for lang, _ in found) >= 1
    assert sum(len(commands(code)) for lang, code in found if lang == "sh") >= 20


@pytest.mark.slow
def test_the_readme_runs_as_written(tmp_path):
    env = dict(os.environ, PYTHONWARNINGS="error::DeprecationWarning")
    for lang, code in blocks(README.read_text()):
        if lang == "sh":
            for argv, expected, line in commands(code):
                done = subprocess.run([sys.executable, "-m", "tethersim", *argv], cwd=tmp_path,
                                      env=env, capture_output=True, text=True,
                                      stdin=subprocess.DEVNULL, check=False)
                said = done.stdout + done.stderr
                assert "Traceback" not in said, f"{line}\n{said[-3000:]}"
                assert done.returncode == expected, (
                    f"{line}: exit {done.returncode}, README expects {expected}\n{said[-3000:]}")
        elif lang == "python":
            done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                                  capture_output=True, text=True, check=False)
            assert done.returncode == 0, f"README Python block:\n{code}\n{done.stderr[-3000:]}"
