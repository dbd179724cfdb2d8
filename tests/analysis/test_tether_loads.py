"""Tether outputs (issue 21 item 6): the tension series is the spring law computed here
from the geometry with numpy; the slack fraction matches switch times found on a far
finer grid and a closed form; peak, snap and safety factor follow from the series; the
time series files and the summary carry them."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tethersim.analysis.tethers import metrics_grid, slack_fraction, tether_loads

SAT = ts.load_preset("satI")
# a start with both tethers slack (the balloon 1 m behind the boom, between its ends):
# drag carries it downstream and they snap taut
SLACK_START = SAT.replace(initial=(1.0, 4.75, 0.0, 0.0, 0.0, 0.0), Fb1=5.0, Fb2=20.0)


def _numpy_tensions(sat, states):
    """E_j (λ_j − l_j0) / l_j0 while taut, from the thesis's geometry (Eqs 3.39-3.42):
    tip-mass at b (sin θ, cos θ), bus at −a (sin θ, cos θ), balloon at (δx, δy)."""
    dx, dy, th = states[:, 0], states[:, 1], states[:, 2]
    lam1 = np.hypot(sat.b * np.sin(th) - dx, sat.b * np.cos(th) - dy)
    lam2 = np.hypot(-sat.a * np.sin(th) - dx, -sat.a * np.cos(th) - dy)
    return np.column_stack([sat.E1 / sat.l10 * np.maximum(lam1 - sat.l10, 0),
                            sat.E2 / sat.l20 * np.maximum(lam2 - sat.l20, 0)]), lam1, lam2


@pytest.fixture(scope="module")
def snapping():
    return ts.simulate(SLACK_START, periods=1, progress=False)


def test_tension_series_is_the_spring_law_of_the_geometry(snapping):
    expected, _, _ = _numpy_tensions(SLACK_START, snapping.states)
    np.testing.assert_allclose(snapping.tether_tensions(), expected, rtol=1e-12, atol=1e-15)


def test_the_time_series_files_hold_the_tensions(snapping, tmp_path):
    import xarray

    csv = ts.write_timeseries(snapping, tmp_path / "run.csv")
    header = csv.read_text().splitlines()[0].split(",")
    assert header[-2:] == ["tension_1 [N]", "tension_2 [N]"]
    data = np.loadtxt(csv, delimiter=",", skiprows=1)
    expected, _, _ = _numpy_tensions(SLACK_START, snapping.states)
    np.testing.assert_array_equal(data[:, -2:], snapping.tether_tensions())
    np.testing.assert_allclose(data[:, -2:], expected, rtol=1e-12, atol=1e-15)
    nc = ts.write_netcdf(snapping, tmp_path / "run.nc")
    ds = xarray.open_dataset(nc, engine="scipy")
    assert ds["tension_2"].attrs["units"] == "N"
    np.testing.assert_array_equal(ds["tension_2"].values, snapping.tether_tensions()[:, 1])


def test_slack_fraction_matches_switch_times_from_the_geometry():
    """The switch times, found here by the sign of λ − l0 from numpy's geometry on a grid
    of 0.5 s (the snapping tethers bounce slack and taut within seconds), give the same
    slack fraction to within a sample."""
    fine = ts.simulate(SLACK_START, periods=1, samples=10_000, progress=False)
    _, lam1, lam2 = _numpy_tensions(SLACK_START, fine.states)
    dt = np.diff(fine.t)
    for ld, lam, l0 in zip(tether_loads(fine), (lam1, lam2),
                           (SLACK_START.l10, SLACK_START.l20)):
        slack = lam <= l0
        # slack time: whole intervals slack at both ends, half of each switch interval
        reference = (np.sum(dt[slack[:-1] & slack[1:]])
                     + 0.5 * np.sum(dt[slack[:-1] != slack[1:]])) / fine.t[-1]
        assert 0 < ld.slack_fraction < 1
        assert ld.slack_fraction == pytest.approx(reference, abs=2 * dt.max() / fine.t[-1])


def test_slack_fraction_of_a_closed_form_margin():
    """g = cos t − 1/2 on [0, 2π] is slack for t in [π/3, 5π/3]: a fraction 2/3."""
    t = np.linspace(0, 2 * math.pi, 1001)
    assert slack_fraction(t, np.cos(t) - 0.5) == pytest.approx(2 / 3, abs=1e-6)
    assert slack_fraction(t, np.ones_like(t)) == 0.0
    assert slack_fraction(t, -np.ones_like(t)) == 1.0


def test_peak_snap_and_safety_factor_follow_from_the_series(snapping):
    run = metrics_grid(snapping)
    tension = run.tether_tensions()
    g = run.tether_margins()
    for ld, fb in zip(tether_loads(snapping), (SLACK_START.Fb1, SLACK_START.Fb2)):
        j = ld.tether - 1
        assert ld.peak == tension[:, j].max()
        assert ld.safety_factor == fb / ld.peak
        # it starts slack: every taut sample follows a slack interval, so the snap
        # tension is at most the peak, and it is the peak when the tether never slackened
        # after its first re-tautening
        assert ld.snaps >= 1 and 0 < ld.snap <= ld.peak
        first = int(np.argmax(g[:, j] > 0))
        assert np.all(g[:first, j] <= 0)


def test_a_tether_that_never_slackens_has_no_snap():
    loads = tether_loads(ts.simulate(SAT, periods=0.5, progress=False))
    for ld in loads:
        assert ld.snaps == 0 and math.isnan(ld.snap) and ld.slack_fraction == 0.0
        assert math.isnan(ld.safety_factor)  # Fb = 0: never breaks


def test_the_summary_reports_the_loads(snapping):
    s = ts.run_summary(snapping)
    ld = tether_loads(snapping)
    assert s["tether 1 peak tension [N]"] == ld[0].peak
    assert s["tether 2 slack fraction"] == ld[1].slack_fraction
    assert s["tether 2 safety factor to Fb2"] == ld[1].safety_factor
    assert s["start"] == "given"


def test_a_taut_line_whose_damper_outweighs_its_spring_applies_no_force():
    """A 3 m/s arrival on the stretched Dyneema bridle, sampled every 50 µs: at the end
    of its rebounds the Kelvin-Voigt damper's c λ̇ outweighs the spring while λ_j > l_j0.
    Where it does (λ̇ the time derivative of the generated margins λ_j − l_j0,
    np.gradient, independent of the kernels' own λ̇), the generated kernel's spring and
    damper families cancel: the line goes slack rather than push; elsewhere the damper
    acts in full."""
    from tethersim.experiments.deployment import arrival
    from tethersim.experiments.real_tethers import REAL_MODEL, STRETCHED_LENGTHS, real_lines
    from tethersim.generated import objective_damper as kernels
    from tethersim.model.inputs import parameter_vector
    start = arrival(real_lines(SAT, STRETCHED_LENGTHS), 3.0)
    periods = 0.002
    res = ts.simulate(start, periods=periods, method="implicit", model=REAL_MODEL,
                      start="given", steps=round(periods * start.period / 5e-5), rtol=1e-8,
                      atol=1e-10, progress=False)
    assert REAL_MODEL == kernels.MODEL
    g, p = res.tether_margins(), parameter_vector(start, REAL_MODEL)
    out = np.zeros((len(kernels.FAMILIES), 3))
    fam = {name: i for i, name in enumerate(kernels.FAMILIES)}
    clamped = free = 0
    for j, (l0, E, c) in enumerate(((start.l10, start.E1, start.c1),
                                    (start.l20, start.E2, start.c2))):
        spring = E * g[:, j] / l0
        damper = c * np.gradient(g[:, j], res.t)
        for k in np.flatnonzero(g[:, j] > 0):
            kernels.family_forces(res.model_states[k], p, out)
            s, d = out[fam[f"spring{j + 1}"]], out[fam[f"damper{j + 1}"]]
            if spring[k] + damper[k] < -0.01 * spring[k]:  # clear of the kink
                clamped += 1
                np.testing.assert_allclose(s + d, 0.0, atol=1e-9 * np.abs(s).max())
            elif spring[k] + damper[k] > 0.01 * spring[k] and abs(damper[k]) > 0.01 * spring[k]:
                free += 1
                assert np.abs(s + d).max() > 1e-3 * np.abs(s).max()
    # both sides of the clamp sampled (a clamped phase lasts a fraction of a millisecond)
    assert clamped >= 5 and free > 100
