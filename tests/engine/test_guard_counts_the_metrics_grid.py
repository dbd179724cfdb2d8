"""The output-size guard counts every array a run holds: the output, the adaptive method's
metrics grid (refined to 200 samples per orbit) and the convergence check's rerun.

10 output samples of 10^6 orbits used to pass the guard and allocate a 2 x 10^8-row
metrics grid (16 GiB). The counts are checked against the arrays a real run returns.
"""
from __future__ import annotations

import time

import pytest

from tethersim import load_preset, simulate
from tethersim.engine.guards import (
    SizeLimitError,
    check_simulation,
    metrics_rows,
    output_rows,
)

SAT = load_preset("satI")
ROW_BYTES = 11 * 8  # t and 10 states, float64


@pytest.mark.parametrize("periods, samples", [(1, 10), (2, 7), (0.5, 300)])
def test_guard_rows_are_the_arrays_a_run_returns(periods, samples):
    res = simulate(SAT, periods=periods, samples=samples, progress=False)
    assert output_rows(periods, None, "adaptive", samples) == res.t.size
    fine = 0 if res.fine_t is None else res.fine_t.size
    assert metrics_rows(periods, res.t.size) == fine


def test_a_few_samples_of_a_long_run_are_refused_for_their_metrics_grid():
    t0 = time.perf_counter()
    with pytest.raises(SizeLimitError) as info:
        simulate(SAT, periods=1e6, samples=10)
    assert time.perf_counter() - t0 < 1.0, "refused before allocating anything"
    msg = str(info.value)
    assert "metrics grid of 2e+08 samples" in msg and "allowed at most 2 GiB" in msg
    assert "\n" not in msg


def test_the_limit_counts_output_metrics_grid_and_check_exactly(monkeypatch):
    # 1 orbit, 10 samples: 11 output rows beside a 201-row metrics grid (the test above
    # checks both against a real run); the check reruns the 11-row output grid
    need = (11 + 201) * ROW_BYTES
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", str(need))
    check_simulation(1, samples=10, check=False)
    with pytest.raises(SizeLimitError, match="convergence check"):
        check_simulation(1, samples=10, check=True)
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", str(need - 1))
    with pytest.raises(SizeLimitError, match="metrics grid of 200 samples"):
        check_simulation(1, samples=10, check=False)


def test_rk4_counts_its_steps_and_the_check_at_twice_the_steps(monkeypatch):
    steps = 1000
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", str((steps + 1) * ROW_BYTES))
    check_simulation(1e6, steps, "rk4", check=False)  # RK4 has no metrics grid beside it
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", str((steps + 1 + 2 * steps + 1) * ROW_BYTES))
    check_simulation(1e6, steps, "rk4", check=True)
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", str((steps + 1 + 2 * steps + 1) * ROW_BYTES - 1))
    with pytest.raises(SizeLimitError, match="rerun of 2000 steps"):
        check_simulation(1e6, steps, "rk4", check=True)


def test_the_refusal_names_who_asked():
    with pytest.raises(SizeLimitError, match=r"^--max-lifetime: ") as info:
        check_simulation(1e9, subject="--max-lifetime")
    assert info.value.subject == "--max-lifetime"
    assert str(info.value.naming("--periods")).startswith("--periods: ")
