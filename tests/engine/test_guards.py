"""Size guards and Ctrl-C: refused at once with the estimate, never an OOM kill or a traceback."""
from __future__ import annotations

import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.messages import one_line
from tests.terminal import sigint_as_in_a_terminal
from tethersim import load_preset, simulate
from tethersim.cli.main import main
from tethersim.engine.guards import SizeLimitError, check_simulation, check_sweep
from tethersim.experiments.sweep import SweepSpec

SAT = load_preset("satI")
ROOT = Path(__file__).parents[2]



@pytest.mark.parametrize("method, steps, check, estimate", [
    ("adaptive", 10**8, False, "8.2 GiB"),  # t + 10 states x 8 bytes, one integration
    ("adaptive", 10**8, True, "16.4 GiB"),  # x2 with the convergence check
    ("rk4", 10**8, True, "24.6 GiB"),  # the check reruns at twice the steps
])
def test_simulate_refuses_an_output_that_would_not_fit(method, steps, check, estimate):
    t0 = time.perf_counter()
    with pytest.raises(SizeLimitError, match=estimate) as info:
        simulate(SAT, periods=1, steps=steps, method=method, check=check)
    assert time.perf_counter() - t0 < 1.0, "refused before allocating anything"
    msg = str(info.value)
    # the API names its own arguments; a command names its options (tests/cli)
    assert msg.startswith("periods/steps/samples: ") and "--" not in msg
    assert "2 GiB" in msg and "TETHERSIM_MAX_OUTPUT_BYTES" in msg


def test_output_limit_is_configurable_and_counts_the_check(monkeypatch):
    # 0.1 orbit at 200 samples/orbit: 21 rows x 11 columns x 8 bytes = 1848 bytes per run
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", "2000")
    check_simulation(0.1, check=False)
    with pytest.raises(SizeLimitError, match="3.61 KiB"):
        check_simulation(0.1, check=True)
    monkeypatch.setenv("TETHERSIM_MAX_OUTPUT_BYTES", "lots")
    with pytest.raises(SizeLimitError, match="TETHERSIM_MAX_OUTPUT_BYTES = 'lots': must be a number"):
        check_simulation(0.1)


def test_malformed_requests_are_left_to_simulates_own_checks():
    check_simulation("many")  # no guess at a size: simulate() names the field
    with pytest.raises(ValueError, match="periods = 'many'"):
        simulate(SAT, periods="many")


def test_a_sweep_points_bytes_are_its_records_and_the_docs_say_so():
    """SWEEP_POINT_BYTES (engine/guards.py, below the sweep package) is the record's
    fields (sweep.point.VARIABLES) plus the done flag and the checksum, and docs/limits.md
    prints it and the 10^12-point grid's size from it."""
    import numpy as np

    from tethersim.engine.guards import SWEEP_POINT_BYTES
    from tethersim.experiments.sweep.point import VARIABLES
    assert SWEEP_POINT_BYTES == sum(np.dtype(d).itemsize for _, d, *_ in VARIABLES) + 1 + 8
    doc = (Path(__file__).parents[2] / "docs" / "limits.md").read_text()
    assert f"sweep store (~{SWEEP_POINT_BYTES} bytes per point)" in doc
    assert f"(10¹² points, ~{10**12 * SWEEP_POINT_BYTES / 1024**4:.0f} TiB)" in doc


def test_sweep_grid_over_the_point_limit_is_refused_with_its_size():
    with pytest.raises(SizeLimitError, match=r"1000000 E1 x 1000000 E2 = 1e\+12 points "
                                             r"\(store about 99.1 TiB\)"):
        check_sweep([10**6, 10**6], ["E1", "E2"])
    check_sweep([1000, 1000], ["E1", "E2"])  # exactly the default limit


def test_sweep_spec_checks_its_size_before_validating_points(monkeypatch):
    monkeypatch.setenv("TETHERSIM_MAX_SWEEP_POINTS", "5")
    with pytest.raises(SizeLimitError, match="3 E1 x 2 E2 = 6 points"):
        SweepSpec(SAT, (("E1", [0.003, 0.004, 0.005]), ("E2", [0.04, 0.05])), periods=1)
    monkeypatch.setenv("TETHERSIM_MAX_STORE_BYTES", "100")
    with pytest.raises(SizeLimitError, match="TETHERSIM_MAX_STORE_BYTES"):
        SweepSpec(SAT, (("E1", [0.003, 0.004]),), periods=1)


def test_cli_huge_steps_is_one_line_not_an_oom_kill(tmp_path, capsys):
    rc = main(["run", "satI", "--steps", "100000000", "--out", str(tmp_path), "--quiet"])
    assert rc == 2
    line = one_line(capsys.readouterr().err)
    assert "--steps" in line and "GiB" in line and "allowed at most 2 GiB" in line


def test_cli_huge_sweep_grid_returns_at_once(tmp_path, capsys):
    t0 = time.perf_counter()
    rc = main(["sweep", "satI", "--E1", "0:1:1000000", "--E2", "0:1:1000000",
               "--out", str(tmp_path / "s"), "--quiet"])
    assert time.perf_counter() - t0 < 5.0
    assert rc == 2
    line = one_line(capsys.readouterr().err)
    assert "1e+12 points" in line and "allowed at most 1e+06 points" in line
    assert not (tmp_path / "s").exists(), "nothing created"


def test_ctrl_c_anywhere_in_the_cli_isone_line(monkeypatch, capsys):
    import tethersim.model.presets

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(tethersim.model.presets, "resolve", interrupted)
    assert main(["equilibrium", "satI"]) == 130
    assert one_line(capsys.readouterr().err) == "tethersim: interrupted"


def test_sigint_to_a_running_cli_prints_no_traceback(tmp_path):
    """A real SIGINT to `tethersim run` mid-integration: output so far kept, exit 130, one line."""
    import re
    import threading

    proc = subprocess.Popen([sys.executable, "-m", "tethersim", "run", "satI", "--periods", "20000",
                             "--steps", "2000", "--no-plots", "--no-check", "--out", str(tmp_path / "run")],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=sigint_as_in_a_terminal)
    err = []
    reader = threading.Thread(target=lambda: err.extend(iter(lambda: proc.stderr.read(1), "")))
    reader.start()
    try:
        # wait for the progress bar to count orbits: past imports and the JIT compile
        deadline = time.monotonic() + 120
        while not re.search(r"[1-9][\d.]*/20000\.0 orbits", "".join(err)):
            assert time.monotonic() < deadline and proc.poll() is None, "".join(err)
            time.sleep(0.05)
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
        reader.join(timeout=10)
        proc.stdout.close()
        proc.stderr.close()
    text = "".join(err)
    assert proc.returncode == 130, text
    assert "Traceback" not in text
    assert "interrupted: the output holds the run up to t = " in text
