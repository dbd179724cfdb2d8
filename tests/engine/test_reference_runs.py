"""Runs equal, bit for bit, the numbers recorded before the regroup and the engine rewrite.

tests/data/reference_af5dd73.json holds final states and counters written with
``repr`` (round-trip exact) by the code at commit af5dd73, the last commit
before the package regroup and the reference-count-free engine.  Every run here
must reproduce them exactly: the refactors moved and re-plumbed the code, they
must not change a single floating-point operation of the trajectories.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

import tethersim as ts
from tethersim.experiments.sweep import SweepSpec
from tethersim.experiments.sweep.runner import map_points

REF = json.loads((Path(__file__).parents[1] / "data" / "reference_af5dd73.json").read_text())


def _final(res):
    return [repr(float(v)) for v in res.states[-1]]


def test_rk4_thesis_scheme_is_bit_identical():
    res = ts.simulate(ts.load_preset("satI"), periods=2, steps=400, method="rk4",
                      check=False, progress=False)
    ref = REF["rk4_satI_2orbits_400steps"]
    assert _final(res) == ref["final"]
    assert res.nfev == ref["nfev"]


def test_dop853_with_switch_location_is_bit_identical():
    res = ts.simulate(ts.load_preset("satI"), periods=2, check=False, progress=False)
    ref = REF["dop853_satI_2orbits"]
    assert _final(res) == ref["final"]
    assert (res.nfev, res.n_accepted, res.n_rejected, res.n_switches) == (
        ref["nfev"], ref["n_accepted"], ref["n_rejected"], ref["n_switches"])


def test_rk4_with_switch_location_is_bit_identical():
    res = ts.simulate(ts.load_preset("satII"), periods=1, steps=300, method="rk4",
                      locate_switches=True, model="objective-damper", check=False,
                      progress=False)
    ref = REF["rk4_located_satII_objective_1orbit"]
    assert _final(res) == ref["final"]
    assert (res.nfev, res.n_switches) == (ref["nfev"], ref["n_switches"])


@pytest.mark.parametrize("model", ["derived", "printed", "exact-gravity", "objective-damper"])
def test_every_model_is_bit_identical(model):
    res = ts.simulate(ts.load_preset("dumbsat"), periods=1, check=False, progress=False,
                      model=model)
    ref = REF[f"dop853_dumbsat_{model}_1orbit"]
    assert _final(res) == ref["final"]
    assert res.nfev == ref["nfev"]


def test_sweep_records_are_bit_identical():
    # at 200 samples per orbit, the metrics grid (docs/metrics.md): a coarser sweep output
    # now has its metrics computed on a refined grid, which changes them on purpose
    spec = SweepSpec(ts.load_preset("satI"), (("E1", (0.003, 0.004)), ("E2", (0.04, 0.043))),
                     periods=2, samples_per_period=200)
    recs = map_points(spec, workers=1)
    got = [{k: repr(float(v)) for k, v in rec.items()} for rec in recs]
    assert got == REF["sweep_satI_2x2_2orbits_200_samples"]
