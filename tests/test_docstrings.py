"""The public API is documented in numpydoc form, and its examples run.

Every name in ``tethersim.__all__`` that is a function or class carries a
docstring with the numpydoc sections its signature calls for (Parameters when
it takes arguments, Returns for functions, Examples), and every Examples
section runs as a doctest.
"""
from __future__ import annotations

import doctest
import inspect

import pytest

import tethersim

PUBLIC = sorted(n for n in tethersim.__all__
                if inspect.isfunction(getattr(tethersim, n)) or inspect.isclass(getattr(tethersim, n)))
# classes whose fields are documented as Attributes (records), not Parameters
RECORDS = {"Satellite", "SimResult", "Outcome", "Equilibrium", "SweepSpec", "Plan"}
# exceptions and warnings are documented by a sentence
PLAIN = {"SatelliteError", "RK4StepWarning"}
# examples that compile a kernel no fast test needs (tests/tiers.py): the slow tier runs them
SLOW_EXAMPLES = {"find_equilibrium"}  # its 3-D example: the 3-D finite-difference Jacobian


def _sections(doc: str) -> set:
    lines = [s.strip() for s in doc.splitlines()]
    return {lines[i] for i in range(len(lines) - 1)
            if lines[i] and set(lines[i + 1]) == {"-"} and len(lines[i + 1]) >= len(lines[i])}


@pytest.mark.parametrize("name", PUBLIC)
def test_public_api_has_numpydoc_sections(name):
    obj = getattr(tethersim, name)
    doc = inspect.getdoc(obj)
    assert doc, f"{name} has no docstring"
    if name in PLAIN:
        return
    found = _sections(doc)
    if inspect.isclass(obj):
        assert ("Attributes" if name in RECORDS else "Parameters") in found, (name, found)
        return
    params = [p for p in inspect.signature(obj).parameters.values()
              if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    if params:
        assert "Parameters" in found, (name, found)
    assert "Returns" in found, (name, found)
    assert "Examples" in found, (name, found)


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW_EXAMPLES
                                  else n for n in PUBLIC if n not in PLAIN])
def test_public_api_examples_run(name):
    obj = getattr(tethersim, name)
    finder = doctest.DocTestFinder(recurse=False)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(obj, name, globs={"tethersim": tethersim}):
        runner.run(test)
    assert runner.failures == 0, f"{name}: {runner.failures} example(s) failed"
