"""Stability classes from metrics (tethersim.analysis.classify; definitions in docs/metrics.md)."""
from __future__ import annotations

import math

import pytest

from tethersim.analysis.classify import (
    FAILED,
    OFFSET,
    SETTLING_REQUIREMENT,
    STABLE,
    TUMBLING,
    UNSETTLED,
    UPSIDE_DOWN,
    classify,
)
from tethersim.analysis.metrics import PitchMetrics


def m(ss=0.0, settle=3600.0, tumbled=False, upside=False):
    return PitchMetrics(mean_pitch=ss, steady_state_pitch=ss, settling_time=settle,
                        tumbled=tumbled, upside_down=upside)


@pytest.mark.parametrize("metrics, expected", [
    (m(), STABLE),
    (m(ss=0.049), STABLE),
    (m(ss=-0.051), OFFSET),  # thesis band ±0.05 rad (p. 5-18)
    (m(ss=math.pi / 2), OFFSET),  # Fig 5.5
    (m(settle=math.nan), UNSETTLED),
    (m(settle=SETTLING_REQUIREMENT * 1.01), UNSETTLED),  # three days (p. 5-6)
    (m(ss=0.0, tumbled=True), TUMBLING),
    (m(ss=3.1, upside=True, tumbled=True), UPSIDE_DOWN),  # Fig 5.14: turned over, stays
    (None, FAILED),
])
def test_classes_follow_the_thesis_criteria_in_priority_order(metrics, expected):
    assert classify(metrics) == expected


def test_tolerance_is_a_parameter():
    assert classify(m(ss=0.08), tol=0.1) == STABLE
