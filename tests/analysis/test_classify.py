"""Stability classes from metrics (tethersim.analysis.classify; definitions in docs/metrics.md)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.analysis.classify import (
    CLASSES,
    FAILED,
    OFFSET,
    SETTLING_REQUIREMENT,
    STABLE,
    TUMBLING,
    UNSETTLED,
    UPSIDE_DOWN,
    agreement,
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


def test_agreement_counts_hand_made_maps():
    predicted = np.array([[0, 0, 2], [1, 2, 4]], dtype=np.int8)
    simulated = np.array([[0, 1, 2], [1, 3, 4]], dtype=np.int8)
    r = agreement(predicted, simulated)
    assert r["n"] == 6 and r["n_missing"] == 0
    assert r["same_class"] == pytest.approx(4 / 6)  # (0,0), (0,2), (1,0), (1,2)
    assert r["same_stability"] == pytest.approx(5 / 6)  # only (0,1): stable vs unsettled
    expected = np.zeros((len(CLASSES), len(CLASSES)), dtype=int)
    for p, s in [(0, 0), (0, 1), (2, 2), (1, 1), (2, 3), (4, 4)]:
        expected[p, s] += 1
    np.testing.assert_array_equal(r["confusion"], expected)
    # the sweep store's fill (-1: not computed) is left out
    simulated[0, 0] = -1
    r = agreement(predicted, simulated)
    assert r["n"] == 5 and r["n_missing"] == 1 and r["same_class"] == pytest.approx(3 / 5)
    assert r["confusion"].sum() == 5
    with pytest.raises(ValueError, match="shape"):
        agreement(predicted, simulated[:, :2])
    with pytest.raises(ValueError, match="not a class"):
        agreement(predicted, np.full((2, 3), len(CLASSES)))
