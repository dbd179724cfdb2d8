"""Roll, yaw and δz figures of the 3-D run summary (issue 19)."""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.summary import out_of_plane_summary

KEYS = ("largest |roll phi| [rad]", "largest |yaw psi| [rad]", "steady-state roll [rad]",
        "steady-state yaw [rad]", "final roll phi [rad]", "final yaw psi [rad]",
        "largest |delta_z| [m]", "final delta_z [m]")


@pytest.fixture(scope="module")
def sat():
    return ts.load_preset("satI")


def test_a_planar_summary_has_no_out_of_plane_figures(sat):
    s = ts.run_summary(ts.simulate(sat, periods=0.2, progress=False))
    assert not set(KEYS) & set(s)


@pytest.mark.slow  # compiles the 3-D loop
def test_an_in_plane_3d_run_stays_in_plane(sat):
    """δz = φ = ψ = 0 is invariant (z → −z symmetry, docs/roll.md): every figure is 0."""
    s = ts.run_summary(ts.simulate(sat, periods=0.3, model="3d", progress=False))
    assert all(s[k] == 0.0 for k in KEYS), {k: s[k] for k in KEYS}


@pytest.mark.slow  # compiles the 3-D loop
def test_a_tilted_3d_run_reports_its_roll_yaw_and_sideways_offset(sat):
    phi0, psi0 = 0.1, -0.05
    res = ts.simulate(sat.replace(initial_3d={"phi": phi0, "psi": psi0}), periods=0.3,
                      model="3d", progress=False, samples=7)
    s = ts.run_summary(res)
    # the largest |angle| is at least the initial one; the final value is the last sample
    assert s["largest |roll phi| [rad]"] >= phi0
    assert s["largest |yaw psi| [rad]"] >= abs(psi0)
    assert s["final roll phi [rad]"] == res.series("phi")[-1]
    assert s["final yaw psi [rad]"] == res.series("psi")[-1]
    assert s["final delta_z [m]"] == res.series("delta_z")[-1]
    # a roll moves the balloon out of the plane
    assert s["largest |delta_z| [m]"] > 0
    # figures on the metrics grid, not the 7 output samples: the maximum over the fine grid
    assert res.fine_t is not None
    assert s["largest |roll phi| [rad]"] == np.max(np.abs(res.fine_states[:, 3]))
    steady = out_of_plane_summary(res)["steady-state roll [rad]"]
    assert min(res.fine_states[:, 3]) <= steady <= max(res.fine_states[:, 3])
