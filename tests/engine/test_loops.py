"""The compiled time loops (issue 10): one loop per model, no reference counting
per step, a cache keyed on the jitted sources only, one integration by default."""
from __future__ import annotations

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import tethersim.generated as generated
from tethersim import _jit, load_preset, simulate
from tethersim.engine.dynamics import KERNELS, held_circle
from tethersim.model.registry import MODELS

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def sat():
    return load_preset("satI")


def test_kernel_registry_is_the_generated_model_list():
    # make derive writes both: the loop of model i runs generated.MODELS's i-th kernel
    assert tuple(generated.MODELS) == tuple(m.name for m in MODELS)
    assert KERNELS == tuple(generated.MODELS.values())
    # each loop integrates the model's own state only; the held circle is every
    # circular-orbit model's (its orbit a closed form), a free orbit integrates r and nu
    for m in MODELS:
        assert held_circle(m.index) == (m.orbit == "circular") == ("r" not in m.state)


@pytest.mark.parametrize("method", ["rk4", "adaptive"])
def test_simulate_integrates_once_unless_asked_for_an_error_estimate(sat, method):
    kw = dict(periods=0.2, method=method, progress=False)
    if method == "rk4":
        kw["steps"] = 60
    one = simulate(sat, **kw)
    assert one.error_estimate is None and one.converged is None
    checked = simulate(sat, check=True, **kw)
    later = one.estimate_error()
    # the same rerun either way, and the run itself is untouched
    assert later.error_estimate == checked.error_estimate is not None
    np.testing.assert_array_equal(later.states, one.states)
    assert later.converged is checked.converged is not None


def test_estimate_error_leaves_a_failed_run_alone(sat):
    bad = simulate(sat, periods=5, steps=50, method="rk4", step_warning=False, progress=False)
    assert bad.status in ("diverged", "left-domain")
    assert bad.estimate_error() is bad


def _jitted_modules() -> set:
    # modules that define compiled code (or hand constants to it via numba)
    found = set()
    for f in (REPO / "tethersim").rglob("*.py"):
        src = f.read_text()
        if re.search(r"@(njit|intrinsic|overload|jit)\b", src):
            found.add(f.resolve())
    return found


def test_cache_key_covers_every_jitted_module_and_not_the_cli():
    keyed = {f.resolve() for f in _jit.jitted_sources()}
    assert _jitted_modules() <= keyed, sorted(map(str, _jitted_modules() - keyed))
    assert {f.resolve() for f in (REPO / "generated").glob("*.py")} <= keyed
    # modules that only drive or present the kernels do not recompile them
    for name in ("cli/main.py", "cli/run.py", "engine/simulate.py", "engine/result.py",
                 "output/report.py", "output/plots/run.py"):
        assert (REPO / "tethersim" / name).resolve() not in keyed


def _python(code: str, env: dict, timeout: float = 900) -> subprocess.CompletedProcess:
    full = dict(os.environ)
    full.pop("NUMBA_CACHE_DIR", None)
    full.update(env)
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], cwd=REPO, env=full,
                          capture_output=True, text=True, timeout=timeout)


def test_cache_folder_honours_tethersim_cache_dir(tmp_path):
    r = _python("import numba, tethersim; print(numba.config.CACHE_DIR)",
                {"TETHERSIM_CACHE_DIR": str(tmp_path), "NUMBA_CACHE_DIR": "/nonexistent"})
    assert r.returncode == 0, r.stderr
    assert Path(r.stdout.strip()).parent == tmp_path


RUN = """
import sys
from tethersim import load_preset, simulate
from tethersim.engine.evaluate import family_force_peaks
n = int(sys.argv[1])
sat = load_preset("satI")
# N fixed steps and N/20 orbits adaptive (about 3N/2 steps): work that scales with N
simulate(sat, periods=n / 300, steps=n, method="rk4", progress=False)
res = simulate(sat, periods=n / 20, progress=False)
# the loops along the samples (engine/evaluate.py): forces, Jacobi integral, tensions
res.energy_budget(), res.tether_tensions()
family_force_peaks(res.layout.index, res.air, res.t, res.states, res.parameters)
"""


# run after RUN on a cold cache (numba shows the LLVM IR only of what it compiled, not
# of what it loaded): calls to NRT_incref/NRT_decref in each per-evaluation function
IR_CALLS = """
import re
from tethersim.engine import dynamics
from tethersim.engine.integrators import steps
for f in (dynamics.derivative, steps.rk4_step, steps.dop853_step, steps.dop853_dense):
    for sig in f.signatures:
        calls = len(re.findall(r"call \\w+ @NRT_(?:incref|decref)", f.inspect_llvm(sig)))
        print("IR", f.__name__, calls)
"""


def _nrt_ops(n: int, env: dict) -> int:
    r = subprocess.run([sys.executable, "-c", RUN, str(n)], cwd=REPO, env=env,
                       capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-2000:]
    # numba/core/runtime/nrtdynmod.py prints one line per non-NULL incref/decref
    return sum(line.startswith(("*** NRT_Incref", "*** NRT_Decref"))
               for line in r.stdout.splitlines())


@pytest.mark.slow
def test_reference_count_operations_do_not_grow_with_the_step_count(tmp_path):
    """NUMBA_DEBUG_NRT=1 prints every atomic reference-count operation: a run of
    twice the steps, and the evaluation of its twice as many samples, must do exactly
    as many (before issue 10: ~92 per RK4 step)."""
    env = dict(os.environ)
    env.pop("NUMBA_CACHE_DIR", None)
    env.update(TETHERSIM_CACHE_DIR=str(tmp_path), NUMBA_DEBUG_NRT="1")
    # cold cache: compiles once (with the debug prints) and says so, once
    first = subprocess.run([sys.executable, "-c", RUN + IR_CALLS, "30"], cwd=REPO, env=env,
                           capture_output=True, text=True, timeout=900)
    assert first.returncode == 0, first.stderr[-2000:]
    assert first.stderr.count("compiling numerical kernels once") == 1
    # the loops pass borrowed arrays (borrow.BorrowedArray): numba emits no reference
    # counting at all, not even a call that returns at once on a NULL pointer
    ir = [line.split() for line in first.stdout.splitlines() if line.startswith("IR ")]
    assert {name for _, name, _ in ir} == {"derivative", "rk4_step", "dop853_step",
                                           "dop853_dense"}
    assert all(calls == "0" for *_, calls in ir), ir
    small, large = _nrt_ops(300, env), _nrt_ops(600, env)
    assert small == large
    assert small < 150  # a few per call (allocations, arguments; 117 with the 5 evaluations), none per step


def test_a_warm_run_and_its_analysis_never_go_through_numba_type_inference(sat, monkeypatch):
    """Every literal-model kernel is called from Python through its compiled entry
    (integrators/select.py: specialised, call); numba's dispatcher slow path (type
    inference, ~10 ms a call for a series kernel) must not run once a run is warm."""
    from numba.core.dispatcher import Dispatcher

    import tethersim as ts

    per_body = sat.replace(density_mode="per-body")

    def work():
        for s in (sat, per_body):
            for method in ("rk4", "adaptive"):
                res = simulate(s, periods=0.2, method=method, progress=False)
                ts.outcome(res)
                res.forces, res.tether_tensions(), res.energy_budget()
        ts.accelerations(per_body, sat.initial, t=10.0)
        ts.generalized_forces(per_body, sat.initial)

    work()  # compile or load everything once
    slow = []
    real = Dispatcher._compile_for_args

    def spy(self, *args, **kws):
        slow.append(self.py_func.__qualname__)
        return real(self, *args, **kws)
    monkeypatch.setattr(Dispatcher, "_compile_for_args", spy)
    work()
    assert slow == []


def test_avx512_hosts_prefer_512_bit_vectors_unless_the_user_chose_the_target(tmp_path):
    """_jit.vector_features: on an AVX-512 host numba compiles with LLVM's 256-bit
    preference off (the 8 SIMD lanes in one register); a CPU or features the user set
    (make test-generic's NUMBA_CPU_NAME=generic) are left alone."""
    import llvmlite.binding as ll
    code = ("import numba, tethersim; "
            "from numba.core.registry import cpu_target as c; "
            "print(c.target_context.codegen().magic_tuple()[2].split(',')[-1])")
    def run(**env):
        full = {k: v for k, v in os.environ.items()  # make test-generic sets NUMBA_CPU_NAME
                if k not in ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES", "NUMBA_CACHE_DIR")}
        full.update(TETHERSIM_CACHE_DIR=str(tmp_path), **env)
        r = subprocess.run([sys.executable, "-c", code], cwd=REPO, env=full,
                           capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, r.stderr
        return r.stdout.strip()

    avx512 = bool(ll.get_host_cpu_features().get("avx512f"))
    assert (run() == "-prefer-256-bit") == avx512
    for env in ({"NUMBA_CPU_NAME": "generic"}, {"NUMBA_CPU_FEATURES": "+sse2"}):
        assert "prefer-256-bit" not in run(**env), env
