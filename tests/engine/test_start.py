"""Consistent starts (issue 21 item 4): stiff lines have an equilibrium that converges to
the rigid bridle's as EA grows; a run of real lines starts there by default; the thesis's
presets start where given; a given start far from any physical state is refused in one
line pointing at the equilibrium start."""
from __future__ import annotations

import math

import numpy as np
import pytest

import tethersim as ts
from tests.messages import one_line
from tethersim.cli.main import main

SAT = ts.load_preset("satI")


def _apex(sat):
    """The rigid bridle's balloon, written here from the geometry alone: the apex of the
    triangle with sides l10, l20 over the base from the tip-mass (+b along the boom) to
    the bus (−a), on the wake side.  (s along the boom from the COM, h off it) [m]."""
    d = sat.a + sat.b
    along = (sat.l10 ** 2 - sat.l20 ** 2 + d ** 2) / (2 * d)  # from the tip-mass to the bus
    return sat.b - along, math.sqrt(sat.l10 ** 2 - along ** 2)


def _in_boom_frame(eq):
    """The equilibrium balloon's (s, h) in the boom frame: s along the boom towards the
    tip-mass (unit (sin θ, cos θ) in the local frame), h its distance off the boom."""
    e = np.array([math.sin(eq.theta), math.cos(eq.theta)])
    p = np.array([eq.delta_x, eq.delta_y])
    s = float(p @ e)
    return s, float(np.linalg.norm(p - s * e))


@pytest.mark.parametrize("lengths", [(6.0, 6.0), (30.83, 28.92)])
def test_stiff_equilibrium_converges_to_the_rigid_bridle_apex(lengths):
    sat0 = SAT.replace(l10=lengths[0], l20=lengths[1], c1=0.0, c2=0.0, allow_implausible=True)
    s_apex, h_apex = _apex(sat0)
    errors = []
    for ea in (1e3, 1e4, 1e5, 1e6):
        eq = ts.find_equilibrium(sat0.replace(E1=ea, E2=ea))
        assert eq.taut == (True, True)
        s, h = _in_boom_frame(eq)
        errors.append(math.hypot(s - s_apex, h - h_apex))
    # the lines stretch by T / (EA / l0): the distance to the apex falls as 1/EA
    for coarse, fine in zip(errors, errors[1:]):
        assert 5 < coarse / fine < 20
    assert errors[-1] < 1e-4


def test_stiff_six_metre_bridle_finds_the_pitched_equilibrium():
    """Issue 21: with 6 m real lines there is no upright equilibrium: the balloon sits at
    the apex 1.7 m off the boom and its drag pitches the boom until the drag line passes
    near the COM.  The equilibrium is found, and its drag line's lever is small."""
    sat = SAT.replace(E1=9e4, E2=9e4, c1=0.0, c2=0.0)
    eq = ts.find_equilibrium(sat)
    # the balloon's offset is nearly along the flow (+x): its lever about the COM for the
    # drag (+x) is |δy|, a small fraction of its distance
    assert abs(eq.delta_y) < 0.01 * math.hypot(eq.delta_x, eq.delta_y)
    assert 0.5 < eq.theta < 1.5 and eq.stable


def _dyneema(sat=SAT):
    t = {j: ts.tether_parameters("dyneema-sk75", 1e-3, l0, sat.m3)
         for j, l0 in ((1, sat.l10), (2, sat.l20))}
    return sat.replace(E1=t[1]["EA"], E2=t[2]["EA"], c1=t[1]["c"], c2=t[2]["c"],
                       Fb1=t[1]["breaking_load"], Fb2=t[2]["breaking_load"])


@pytest.mark.slow  # compiles the objective-damper model's Radau loop (~35 s cold)
def test_real_lines_start_at_their_equilibrium_by_default():
    sat = _dyneema()
    # atol 1e-10: at rest a real line's force is known to its rounding level only, which
    # the default 1e-12 does not allow a step (docs/tethers.md)
    res = ts.simulate(sat, periods=0.01, method="implicit", rtol=1e-6, atol=1e-10,
                      progress=False, model="objective-damper")
    eq = ts.find_equilibrium(sat, "objective-damper")
    assert res.start == "equilibrium" and res.status == "ok"
    assert np.allclose(res.states[0, :3], [eq.delta_x, eq.delta_y, eq.theta], rtol=0,
                       atol=1e-12)
    assert np.all(res.states[0, 3:6] == 0.0)
    assert res.satellite.initial[:3] == tuple(res.states[0, :3])
    # started at rest in balance, it stays there: tensions within 1e-6 of the start's
    tension = res.tether_tensions()
    assert np.max(np.abs(tension - tension[0])) < 1e-6 * np.max(tension[0])


@pytest.mark.slow  # compiles the objective-damper model's Radau loop (~35 s cold)
@pytest.mark.parametrize("altitude_km", [250.0, 300.0, 400.0])
def test_stretched_real_bridle_starts_upright_where_thin_air_pulls_little(altitude_km):
    """Above 200 km the balloon's drag is 5-100x weaker: the solver found only the boom
    flipped half a turn (θ = -3.134 at 250 and 300 km) until the balloon was first hung on
    its lines by geometry (steady._hung).  The upright start found must be an equilibrium
    of the motion itself: a run from it does not move."""
    sat = ts.with_tethers(SAT.replace(l10=30.83, l20=28.92, altitude=altitude_km * 1e3),
                          "dyneema-sk75", 1e-3)
    res = ts.simulate(sat, periods=0.5, method="implicit", rtol=1e-8, atol=1e-10,
                      progress=False, model="objective-damper")
    assert res.start == "equilibrium" and res.status == "ok"
    assert abs(res.theta[0]) < 0.05  # upright: the stretched bridle's trim, -0.007 rad
    assert np.max(np.abs(res.theta - res.theta[0])) < 1e-6
    assert np.max(np.abs(res.states[:, :2] - res.states[0, :2])) < 1e-6  # metres


def test_thesis_presets_start_where_given():
    res = ts.simulate(SAT, periods=0.01, progress=False)
    assert res.start == "given" and res.satellite is SAT
    assert tuple(res.states[0, :6]) == SAT.initial


def test_a_soft_satellite_can_start_at_its_equilibrium_and_stays_there():
    res = ts.simulate(SAT, periods=0.5, progress=False, start="equilibrium")
    eq = ts.find_equilibrium(SAT)
    assert res.start == "equilibrium"
    assert np.max(np.abs(res.theta - eq.theta)) < 1e-7
    assert np.max(np.abs(res.x - eq.delta_x)) < 1e-6


def test_a_start_beyond_the_breaking_load_is_refused_naming_the_field():
    with pytest.raises(ValueError) as e:
        ts.simulate(_dyneema(), periods=0.01, method="implicit", progress=False,
                    start="given")
    line = one_line(str(e.value))
    assert line.startswith("initial (delta_x, delta_y, theta) = (29 m, 0 m, 0.523599 rad): "
                           "tether 1 starts stretched to")
    assert "beyond its breaking load Fb1 = 2356.19 N" in line
    assert "start='equilibrium' (--start equilibrium)" in line


def test_a_real_line_stretched_past_any_fibre_is_refused_without_a_breaking_load():
    sat = _dyneema().replace(Fb1=0.0, Fb2=0.0)
    with pytest.raises(ValueError) as e:
        ts.simulate(sat, periods=0.01, method="implicit", progress=False, start="given")
    line = one_line(str(e.value))
    assert "tether 1 starts stretched to" in line and "strain" in line
    assert "at which the most extensible fibre of tethersim.model.materials breaks" in line


def test_the_fibre_strain_limit_is_the_tables_largest():
    from tethersim.model.materials import MATERIALS, MAX_FAILURE_STRAIN
    vectran = MATERIALS["vectran-ht"]
    assert MAX_FAILURE_STRAIN == pytest.approx(vectran.strength / vectran.E, rel=1e-15)
    assert all(m.strength / m.E <= MAX_FAILURE_STRAIN for m in MATERIALS.values())


@pytest.mark.parametrize("bad", ["rest", None, 1])
def test_an_unknown_start_is_refused_naming_the_choices(bad):
    with pytest.raises(ValueError, match=r"start = .*: allowed values auto, given, "
                                         r"equilibrium$"):
        ts.simulate(SAT, periods=0.01, progress=False, start=bad)


def test_the_thesis_damper_on_a_real_line_says_why_there_is_no_equilibrium():
    """A 50 N s/m damper of the thesis's law (relative velocity) pushes the balloon across
    its real lines as they turn with the orbit harder than anything balances."""
    with pytest.raises(ValueError) as e:
        ts.simulate(_dyneema().replace(c1=50.0, c2=50.0), periods=0.01, method="implicit",
                    progress=False, start="equilibrium")
    line = one_line(str(e.value))
    assert line.startswith("start = 'equilibrium': no equilibrium found")
    assert "model 'objective-damper' damps the stretch rate only" in line


def test_the_thesis_damper_turning_a_real_bridle_over_is_no_default_start():
    """SatI's stretched bridle of 1 mm Dyneema: the thesis's damper (model derived) rests
    with the boom turned over; the default start says so in one line and names the model
    whose damper is the line's loss, which rests upright; asked for, the turned-over rest
    is still where a run starts."""
    from tethersim.engine.start import start_satellite
    from tethersim.experiments.real_tethers import STRETCHED_LENGTHS, real_lines
    sat = real_lines(SAT, STRETCHED_LENGTHS)
    with pytest.raises(ValueError) as e:
        start_satellite(sat, "derived")
    line = one_line(str(e.value))
    assert "turns the boom over at its equilibrium (θ = -2.908 rad)" in line
    assert "model 'objective-damper' damps the stretch rate" in line
    assert abs(start_satellite(sat, "objective-damper")[0].initial[2]) < 0.01
    assert abs(start_satellite(sat, "derived", "equilibrium")[0].initial[2]) > 2.9


def test_the_command_line_takes_the_start(tmp_path, capsys):
    argv = ["run", "satI", "--periods", "0.01", "--no-plots", "--no-check", "--quiet"]
    assert main([*argv, "--start", "rest", "--out", str(tmp_path / "a")]) == 2
    assert "--start: invalid choice: 'rest'" in capsys.readouterr().err
    assert main([*argv, "--start", "equilibrium", "--out", str(tmp_path / "b")]) == 0
    assert "start                            equilibrium" in capsys.readouterr().out


@pytest.mark.slow  # compiles the objective-damper model's Radau loop (~35 s cold)
def test_a_real_line_at_rest_runs_at_its_default_atol_and_is_told_under_its_rounding():
    """At rest a real line's force is known to its rounding level only (~1e-11 m/s² on the
    balloon).  The error test takes an atol down to 1e-12 there (Radau's Newton stopping at
    NEWTON_TOL of the error scale; at scipy's 1e-3 it stalled at 1e-12 too); 1e-13 given
    fails and says what it needs; the default is the floor, 1e-10, in a few steps."""
    sat = _dyneema()
    kw = dict(periods=0.01, method="implicit", rtol=1e-6, progress=False,
              model="objective-damper")
    assert ts.simulate(sat, atol=1e-12, **kw).status == "ok"
    failed = ts.simulate(sat, atol=1e-13, **kw)
    assert failed.status == "failed"
    assert failed.message.endswith("real lines near rest need atol >= 1e-10, their force's "
                                   "rounding level (atol=..., --atol; docs/tethers.md)")
    ok = ts.simulate(sat, **kw)
    assert ok.status == "ok" and ok.atol == 1e-10 and ok.n_accepted <= 20


def test_the_command_line_takes_the_atol_in_its_range(tmp_path, capsys):
    argv = ["run", "satI", "--periods", "0.01", "--no-plots", "--no-check", "--quiet"]
    assert main([*argv, "--atol", "1", "--out", str(tmp_path / "a")]) == 2
    assert "allowed range 1e-20 <= atol <= 0.001, got 1" in capsys.readouterr().err
