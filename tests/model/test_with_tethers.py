"""with_tethers: a satellite's lines made of a real material, from the one table."""
from __future__ import annotations

import pytest

import tethersim as ts

SAT = ts.load_preset("satI").replace(l10=30.83, l20=28.92)


def test_each_tether_takes_its_own_rest_length_and_the_balloon_s_reduced_mass():
    sat = ts.with_tethers(SAT, "dyneema-sk75", 1e-3, knockdown=0.7)
    mu = SAT.m3 * (SAT.m1 + SAT.m2) / (SAT.m1 + SAT.m2 + SAT.m3)
    for j, l0 in ((1, SAT.l10), (2, SAT.l20)):
        t = ts.tether_parameters("dyneema-sk75", 1e-3, l0, mu, knockdown=0.7)
        assert (getattr(sat, f"E{j}"), getattr(sat, f"c{j}"), getattr(sat, f"Fb{j}")) == \
            (t["EA"], t["c"], t["breaking_load"])
    assert (sat.l10, sat.l20) == (SAT.l10, SAT.l20)


def test_one_tether_leaves_the_other_as_it_was():
    sat = ts.with_tethers(SAT, "kevlar49", 1e-3, tethers=(2,))
    assert (sat.E1, sat.c1, sat.Fb1) == (SAT.E1, SAT.c1, SAT.Fb1) and sat.E2 > 8e4


@pytest.mark.parametrize("kw, words", [
    (dict(name="steel"), "tether material 'steel': allowed kevlar49"),
    (dict(diameter=1.0), "tether diameter = 1.0: allowed range"),
    (dict(tethers=(3,)), "tethers = (3,): allowed 1, 2 or both"),
])
def test_bad_input_is_one_line_naming_it(kw, words):
    args = dict(name="kevlar49", diameter=1e-3) | kw
    with pytest.raises(ValueError) as e:
        ts.with_tethers(SAT, args.pop("name"), args.pop("diameter"), **args)
    assert words in str(e.value) and "\n" not in str(e.value)
