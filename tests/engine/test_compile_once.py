"""A time loop is compiled once per model (and scheme), whoever calls it.

Numba compiles a function again for every new tuple of argument types.  Two ways to
get a second copy of a loop without any change of arithmetic, each seen in the kernel
cache before they were removed (cold fast tier 174 -> 164 s):

* a literal argument (``0``, ``True``) where other callers pass a run-time value: numba
  types a variable first assigned a constant as that literal while it infers the loop,
  and compiles the callee for it too;
* plain arrays from Python against borrowed views (integrators/borrow.py) from a compiled
  block: the sweeps' blocks called the DOP853 and RK4 loops, the metrics and the force
  peaks with borrowed arrays, simulate() and outcome() with plain ones; the force series
  (SimResult.forces) called the forces loop with plain arrays, the force peaks with
  borrowed ones;
* an array's length where the other caller passes the model's constant state size (the
  lanes' dense output), and a writable table from Python where compiled code sees the
  module's global as read-only (Vallado's density).

The drag make-up (outcome() from Python, a plan's records from its block) is held to the
same rule.

One process runs what a user runs (simulate, outcome, a one-point and a 16-point sweep of
each scheme) and counts the signatures of each loop per leading literal (the model, and
the method of the event location): one each.  Slow tier: it compiles in a subprocess.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[2]
SCRIPT = r'''
import json
from numba import types
import tethersim as ts
from tethersim.experiments.sweep import Plan, run_plan
from tethersim.analysis import makeup_kernel, metrics_kernel as mk
from tethersim.engine import evaluate
from tethersim.engine.integrators import dop853, rk4, steps, switching
from tethersim.model import atmosphere
from tethersim.experiments.sweep import lanes853, lanes_dense

sat = ts.load_preset("satI")
for method in ("adaptive", "rk4"):
    res = ts.simulate(sat, 0.2, method=method, progress=False)
    ts.outcome(res)
    res.forces  # the force series of the CLI's plots, beside outcome()'s force peaks
many = [sat.replace(E2=sat.E2 * (1 + 0.01 * i)) for i in range(16)]
for method in ("adaptive", "faithful"):
    for sats in ([sat], many):  # the scalar block, then the lanes
        run_plan(Plan(periods=0.2, method=method), sats, workers=1, progress=False)
loops = {"dop853_run": dop853.dop853_run, "_dop853_loop": dop853._dop853_loop,
         "rk4_run": rk4.rk4_run, "_rk4_loop": rk4._rk4_loop,
         "rk4_advance": rk4.rk4_advance, "locate": switching.locate,
         "_load": lanes853._load, "flush": lanes_dense.flush,
         "pitch_metrics_into": mk.pitch_metrics_into, "window_mean": mk.window_mean,
         "_family_force_peaks": evaluate._family_force_peaks,
         "_forces_loop": evaluate._forces_loop,
         "drag_makeup_kernel": makeup_kernel.drag_makeup_kernel,
         "dop853_interpolate": steps.dop853_interpolate, "copy_into": steps.copy_into,
         "density_kernel": atmosphere.density_kernel}


def leading_literals(sig):
    out = []
    for a in sig:
        if not isinstance(a, types.IntegerLiteral):
            break
        out.append(a.literal_value)
    return str(out)


print(json.dumps({name: [leading_literals(s) for s in f.signatures]
                  for name, f in loops.items()}))
'''


ONE_SIGNATURE = ("dop853_interpolate", "copy_into", "density_kernel")


@pytest.mark.slow
def test_each_loop_is_compiled_once_per_model_whoever_calls_it(tmp_path):
    env = {**os.environ, "TETHERSIM_CACHE_DIR": str(tmp_path / "cache")}
    out = subprocess.run([sys.executable, "-c", SCRIPT], cwd=ROOT, env=env, text=True,
                         capture_output=True, timeout=900)
    assert out.returncode == 0, out.stderr[-2000:]
    sigs = json.loads(out.stdout.strip().splitlines()[-1])
    assert all(sigs.values()), sigs  # every loop was run
    twice = {name: keys for name, keys in sigs.items() if len(keys) != len(set(keys))}
    assert twice == {}
    # one model (SatI's 6 states) and one density table: one signature each, whether the
    # state size comes as the loop's constant or an array's length, the table from
    # Python or as compiled code's read-only global
    assert {name: sigs[name] for name in ONE_SIGNATURE if len(sigs[name]) != 1} == {}
