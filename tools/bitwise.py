"""Bit identity where it holds: one machine, a commit against the working tree.

Usage: ``python tools/bitwise.py REV`` (``make check-bitwise BASE=REV``).

Runs a fixed set of reference runs (planar models, RK4 and DOP853, switch
location, per-body air) with the code at ``REV`` (a temporary git worktree) and
with the working tree, each in a fresh process on this machine, and compares the
arrays of the model's states (not a circular run's COM orbit, integrated before
issue 22 and a closed form since), the times and the evaluation counts to the last
bit.  A refactor that must not change a single floating-point operation passes;
anything else prints the first run that differs.  Stored numbers in tests/ are compared to tolerances instead
(tests/reference.py): another CPU may round an operation differently.
"""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# (preset, satellite changes, simulate keyword arguments): the public API only, so a
# commit from before any refactor runs them too
CASES = {
    "rk4_satI": ("satI", {}, dict(periods=2, steps=600, method="rk4")),
    "dop853_satI": ("satI", {}, dict(periods=2)),
    "rk4_located_printed": ("satI", dict(initial=(4.0, 0.0, 0.3, 0.0, 0.0, 0.0), c1=0.01,
                                         c2=0.01),
                            dict(periods=0.2, steps=200, method="rk4", locate_switches=True,
                                 model="printed")),
    "dop853_satII_objective": ("satII", {}, dict(periods=1, model="objective-damper")),
    "dop853_per_body_exact": ("satI", dict(density_mode="per-body"),
                              dict(periods=1, model="exact-gravity")),
}

RUNNER = r"""
import hashlib, json, sys
import numpy as np
import tethersim as ts
cases = json.loads(sys.argv[1])
out = {}
for name, (preset, change, kwargs) in cases.items():
    sat = ts.load_preset(preset)
    if change:
        change = {k: tuple(v) if isinstance(v, list) else v for k, v in change.items()}
        sat = sat.replace(**change)
    try:
        r = ts.simulate(sat, check=False, progress=False, **kwargs)
    except TypeError:  # a commit from before simulate() took check= / progress=
        r = ts.simulate(sat, **kwargs)
    # the model's own states: a circular run's COM orbit was integrated after them before
    # issue 22 and is a closed form since; every case is a planar model of 6 states (a
    # commit from before the model registry has no layout)
    n = len(r.layout.state) if hasattr(r, "layout") else 6
    states = np.ascontiguousarray(r.states[:, :n])
    out[name] = [hashlib.sha256(states.tobytes()).hexdigest(),
                 hashlib.sha256(np.ascontiguousarray(r.t).tobytes()).hexdigest(),
                 int(r.nfev), r.status]
print(json.dumps(out))
"""


def run(tree: Path, cache: Path) -> dict:
    """The digests of every case computed with the code in ``tree``, in a fresh process."""
    env = dict(os.environ, PYTHONPATH=str(tree), TETHERSIM_CACHE_DIR=str(cache))
    done = subprocess.run([sys.executable, "-c", RUNNER, json.dumps(CASES)], cwd=tree, env=env,
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(f"check-bitwise: the runs at {tree} failed:\n{done.stderr.strip()}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        sys.exit("usage: python tools/bitwise.py REV  (a commit, branch or tag)")
    rev = argv[0]
    with tempfile.TemporaryDirectory(prefix="tethersim-bitwise-") as tmp:
        base = Path(tmp) / "base"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", "-q", str(base),
                        rev], check=True)
        try:
            # the generated kernels install as tethersim.generated (pyproject package-dir):
            # make the base tree's own copy importable under that name
            link = base / "tethersim" / "generated"
            if (base / "generated").is_dir() and not link.exists():
                link.symlink_to(base / "generated")
            theirs = run(base, Path(tmp) / "cache-base")
            mine = run(ROOT, Path(tmp) / "cache-work")
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(base)],
                           check=False)
    differ = [name for name in CASES if theirs[name] != mine[name]]
    for name in CASES:
        print(f"{name:<28} {'same to the last bit' if name not in differ else 'DIFFERS'}")
    digest = hashlib.sha256(json.dumps(mine, sort_keys=True).encode()).hexdigest()[:16]
    print(f"{len(CASES) - len(differ)} of {len(CASES)} runs bit-identical to {rev} "
          f"on this machine (digest {digest})")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
