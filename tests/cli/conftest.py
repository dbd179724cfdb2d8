"""Shared helpers of the CLI tests: call ``tethersim.cli.main.main`` in-process."""
from __future__ import annotations

import contextlib
import io

import pytest

from tethersim.cli.main import main

# fast runs for tests: 0.05 orbit is 10 faithful RK4 steps of 26.55 s
QUICK = ["--periods", "0.05", "--quiet"]


def call(argv):
    """(exit code, stdout, stderr) of ``main(argv)``, captured by hand (any fixture scope)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def cli():
    """cli(argv) -> (exit code, stdout, stderr) of the tethersim command line."""
    return call


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Run in an empty folder, so default output folders land under tmp_path/results."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
