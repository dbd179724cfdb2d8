"""Run plots: the tether bounce as an envelope; stability maps: a colour scale that follows the data."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.output.plots.run import envelope
from tethersim.output.plots.sweep import pitch_scale


def test_envelope_of_a_fast_sine_is_its_amplitude_about_the_slow_mean():
    t = np.arange(0, 5000.0, 5.0)
    slow = 0.2 * np.sin(2 * np.pi * t / 30000)
    y = slow + 0.05 * np.sin(2 * np.pi * t / 70)
    lo, mean, hi = envelope(t, y, 140.0)
    assert np.all(lo <= y) and np.all(y <= hi)
    inner = slice(30, -30)
    assert np.allclose((hi - lo)[inner], 0.1, atol=0.012)
    assert np.max(np.abs(mean - slow)[inner]) < 0.01


def test_envelope_takes_at_least_three_samples():
    t = np.arange(10.0)
    y = (-1.0) ** np.arange(10)
    lo, _, hi = envelope(t, y, 0.1)
    assert np.all(lo[1:-1] == -1) and np.all(hi[1:-1] == 1)


def test_pitch_scale_is_linear_and_tight_for_a_map_inside_a_few_bands():
    from matplotlib.colors import SymLogNorm
    ss = np.linspace(-0.066, 0.064, 81)
    norm, label, extend = pitch_scale(ss)
    assert not isinstance(norm, SymLogNorm) and "linear" in label
    assert 0.05 <= norm.vmax < 0.07 and norm.vmin == -norm.vmax
    assert extend == "both"  # the outermost 2 % are clipped, and the bar says so


def test_pitch_scale_is_a_symmetric_log_when_the_map_spans_decades():
    from matplotlib.colors import SymLogNorm
    ss = np.r_[np.full(70, math.pi / 2), [0.16, 1.02, -0.01, 0.02], np.full(7, np.nan)]
    norm, label, _ = pitch_scale(ss)
    assert isinstance(norm, SymLogNorm) and f"±{SETTLING_TOL:g}" in label
    assert norm.vmax == pytest.approx(math.pi / 2)
    # the band and the π/2 offsets get visibly different colours
    assert norm(0.02) < 0.6 < norm(0.16) < norm(1.02) < norm(math.pi / 2) + 1e-12


def test_pitch_scale_of_an_empty_map_is_the_band():
    norm, _, extend = pitch_scale(np.full(4, np.nan))
    assert norm.vmax == SETTLING_TOL and extend == "neither"
