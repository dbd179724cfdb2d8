"""The sweep's check of every grid point shows a bar (a million points take most of a
minute) where it was asked for, and never in a worker's copy of the spec."""
from __future__ import annotations

import pytest
import tqdm.auto

from tethersim import load_preset
from tethersim.experiments.sweep import SweepSpec

SAT = load_preset("satI")
AXES = (("E1", (0.003, 0.004, 0.005)),)


@pytest.fixture
def bars(monkeypatch):
    made = []

    class Recorder:
        def __init__(self, total, disable=False, delay=0.0, **kwargs):
            made.append(dict(total=total, disable=disable, delay=delay))

        def update(self, k):
            pass

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return False

    monkeypatch.setattr(tqdm.auto, "tqdm", Recorder)
    return made


@pytest.mark.parametrize("progress, disable, delay", [(None, False, 1.0), (True, False, 0.0),
                                                      (False, True, 1.0)])
def test_the_bar_follows_progress(bars, progress, disable, delay):
    SweepSpec(SAT, AXES, periods=1, progress=progress)
    assert bars == [dict(total=3, disable=disable, delay=delay)]


def test_a_workers_copy_checks_its_points_without_a_bar(bars):
    spec = SweepSpec(SAT, AXES, periods=1, progress=True)
    copy = SweepSpec.from_json(spec.to_json())
    assert copy == spec
    assert bars[-1]["disable"] is True
