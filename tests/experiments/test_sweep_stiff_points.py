"""A point whose tether an explicit scheme cannot step (a real fibre line, docs/tethers.md)
is refused in one line before any store or run; the implicit scheme sweeps it."""
from __future__ import annotations

import pytest

from tests.messages import one_line
from tethersim import SatelliteError, load_preset
from tethersim.experiments.sweep import SweepSpec

SAT = load_preset("satI")


@pytest.mark.parametrize("method", ["adaptive", "faithful"])
def test_a_sweep_refuses_a_point_too_stiff_for_its_scheme_before_any_run(method):
    with pytest.raises(SatelliteError) as e:
        SweepSpec(SAT, (("E1", [0.004, 7e4]),), periods=1.0, method=method)
    line = one_line(str(e.value))
    assert line.startswith(f"sweep point E1 = 70000 N/mm^2 is too stiff for the sweep's {method} "
                           f"scheme: E1 = 70000 N/mm^2: tether 1 would oscillate")
    assert "the implicit scheme (--method implicit)" in line


def test_allowing_implausible_input_lets_the_sweep_run_it_slowly():
    sat = SAT.replace(allow_implausible=True)
    assert SweepSpec(sat, (("E1", [0.004, 7e4]),), periods=1.0).size == 2
