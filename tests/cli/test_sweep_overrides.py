"""A sweep or atlas never applies a --set/--scale and then silently overwrites it: a
setting of a swept parameter, a repeated grid, a setting the atlas makes itself, or one
the model ignores is refused in one line naming it (before any run)."""
from __future__ import annotations

import pytest

from tethersim import load_preset
from tethersim.experiments.sweep import SweepSpec
from tethersim.model.registry import model_for_orbit
from tethersim.model.relevance import needs

QUICK = ["--periods", "0.05", "--quiet"]
CASES = [
    (["sweep", "satI", "--E1", "0.001,0.004", "--scale", "E1=2"], ["--scale E1", "sweep axis"]),
    (["sweep", "satI", "--E1", "0.001,0.004", "--set", "E1=0.5"], ["--set E1", "sweep axis"]),
    (["sweep", "satI", "--E1", "0.001", "--E1", "0.004"], ["--E1 given twice"]),
    (["sweep", "satI", "--E1", "-1,0.004"], ["--E1", "--E1=VALUE", "starts with '-'"]),
    (["sweep", "satI", "--f107", "100,200"], ["--f107 (sweep axis)", "atmosphere = nrlmsise00"]),
    (["sweep", "satI", "--E1", "0.001,0.004", "--set", "phi0_deg=5"], ["phi0_deg", "3-D model"]),
    (["feasibility", "satI", "--altitude", "200", "--set", "altitude=300"],
     ["--set altitude", "--altitude"]),
    (["feasibility", "satI", "--altitude", "200", "--A3", "3,4", "--set", "A3=5"],
     ["--set A3", "--A3"]),
    (["feasibility", "satI", "--altitude", "200", "--set", "density_scale=3"],
     ["--set density_scale", "atlas sets density_scale itself"]),
    (["feasibility", "satI", "--altitude", "200", "--set", "orbit=free"],
     ["--set orbit", "atlas sets orbit itself"]),
    (["feasibility", "satI", "--altitude", "200", "--scale", "f107=2"], ["--scale f107"]),
    (["run", "satI", "--set", "f107=150"], ["--set f107", "needs atmosphere = nrlmsise00"]),
    (["run", "satI", "--set", "epoch=2018-01-01"], ["--set epoch", "nrlmsise00"]),
    (["run", "satI", "--set", "reentry_altitude=150"], ["reentry_altitude", "orbit = free"]),
    (["run", "satI", "--set", "I1=1,2,3"], ["--set I1", "planar model 'derived'", "3-D"]),
    (["run", "satI", "--set", "psi_dot=0.001"], ["--set psi_dot", "3-D"]),
    (["forces", "satI", "--set", "inertia=points"], ["--set inertia", "3-D"]),
    (["compare", "satI", "--models", "derived,printed", "--set", "phi0_deg=5"], ["phi0_deg"]),
]


@pytest.mark.parametrize("argv, expected", CASES, ids=[" ".join(a) for a, _ in CASES])
def test_overwritten_or_ignored_setting_is_refused_in_one_line(argv, expected, cli, tmp_path):
    code, out, err = cli([*argv, *QUICK, "--out", str(tmp_path / "out")])
    assert code == 2, out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    for text in expected:
        assert text in lines[0], lines[0]
    assert not (tmp_path / "out").exists()  # refused before anything was written


def test_a_setting_the_run_uses_is_accepted():
    sat = load_preset("satI")
    msis = sat.replace(atmosphere="nrlmsise00")
    assert needs("f107", msis, "derived") is None
    assert needs("phi0_deg", sat, "3d") is None
    assert needs("reentry_altitude", sat.replace(orbit="free"), "derived") is None
    assert needs("E1", sat, "derived") is None  # every run uses the tethers


def test_sweep_spec_names_the_model_that_runs_a_free_orbit():
    free = load_preset("satI").replace(orbit="free")
    spec = SweepSpec(free, (("E1", (0.001, 0.004)),), periods=0.05)
    assert spec.model == model_for_orbit("derived", "free") != "derived"
    assert f'"model": "{spec.model}"' in spec.to_json()
