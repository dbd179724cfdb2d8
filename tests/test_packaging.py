"""Packaging: one import name, and a run that needs neither sympy nor Dask."""
from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_every_installed_package_is_under_the_tethersim_name():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert all(p == "tethersim" or p.startswith("tethersim.") for p in cfg["packages"])
    # the generated kernels install as tethersim.generated from the top-level folder
    assert cfg["package-dir"] == {"tethersim.generated": "generated"}
    # every package folder under tethersim/ is listed (a missing one would not install)
    found = {".".join(p.relative_to(ROOT).parent.parts)
             for p in (ROOT / "tethersim").rglob("__init__.py")}
    assert found | {"tethersim.generated"} == set(cfg["packages"])


def test_a_run_imports_neither_sympy_nor_dask():
    code = ("import sys, tethersim as ts\n"
            "res = ts.simulate(ts.load_preset('satI'), periods=0.2, progress=False)\n"
            "ts.outcome(res)\n"
            "print(res.status, 'sympy' in sys.modules, any(m.startswith('dask') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                         timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.split() == ["ok", "False", "False"]


def test_no_code_imports_the_kernels_by_their_folder_name():
    """The generated kernels are ``tethersim.generated``; imported as the top-level
    ``generated`` (the repository on sys.path), numba caches their compiled code under that
    module name in the same cache files, and a later ``tethersim`` command that loads the
    cache fails with "No module named 'generated'" (it did after ``make bench``)."""
    import re
    pattern = re.compile(r"^\s*(from\s+generated[\s.]|import\s+generated\b)", re.M)
    found = [str(p.relative_to(ROOT)) for folder in ("tethersim", "derive", "bench", "tools",
                                                       "tests")
             for p in (ROOT / folder).rglob("*.py") if pattern.search(p.read_text())]
    assert not found, found
