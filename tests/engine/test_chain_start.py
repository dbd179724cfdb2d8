"""A bead chain's own equilibrium as its start (issue 21 item 4, engine/start.chain_at_rest):
the chain's accelerations at rest vanish there to the rounding level of its forces, its
beads sag off the straight lines, and a stiff line started there is quiet."""
from __future__ import annotations

import numpy as np
import pytest

import tethersim as ts
from tethersim.engine.start import start_run
from tethersim.model import bead_kernels
from tethersim.model.bead_layout import straight_chain
from tethersim.model.inputs import initial_model_state, parameter_vector

SAT = ts.load_preset("satI")
MT = 4.6e-3  # kg: a 6 m line of 1 mm Dyneema SK75 (970 kg/m³ x 0.785 mm² x 6 m)


def _dyneema(sat=SAT, base="derived"):
    """SatI on 1 mm Dyneema lines of 4.6 g; the derived base without the thesis's damper
    (on a stiff line at rest it pushes the balloon sideways: no equilibrium)."""
    sat = ts.with_tethers(sat, "dyneema-sk75", 1e-3).replace(mt1=MT, mt2=MT)
    return sat.replace(c1=0.0, c2=0.0) if base == "derived" else sat


def _at_rest(model, sat, y, base="derived"):
    """The chain kernel's accelerations at the coordinates of y, rates zero."""
    nq = y.size // 2
    d = np.empty_like(y)
    bead_kernels.kernels(base).rhs(0.0, np.concatenate([y[:nq], np.zeros(nq)]),
                            parameter_vector(sat, model), d)
    return d[nq:]


def _across(sat, model, y, n):
    """The beads' accelerations at rest across their straight lines (boom end to balloon)."""
    a, straight = _at_rest(model, sat, y), initial_model_state(sat, model)
    out = []
    for j in range(2):
        first = straight[3 + 2 * j * n: 5 + 2 * j * n]
        e = (straight[:2] - first) / np.linalg.norm(straight[:2] - first)
        out.append(a[3 + 2 * j * n: 3 + 2 * (j + 1) * n].reshape(n, 2) @ [-e[1], e[0]])
    return np.concatenate(out)


@pytest.mark.parametrize("n", [1, 4, 16])
def test_the_chain_start_cancels_the_straight_chains_accelerations_to_rounding(n):
    """Started on the straight lines, 1 mm Dyneema beads feel ~1e-5 m/s² (their tidal load
    and the tension's pull across the line).  At the chain's start, across the lines
    (where the beads ring slowly) less than 1e-3 of that is left; along them what is left
    is the rounding of EA (λ − l_s) / l_s on sub-gram beads, below ε x 100 m x
    EA / (l_s m_b), which a position of 10 m rounds to."""
    sat, start, model, y = start_run(_dyneema(), "derived", "equilibrium", beads=n)
    assert start == "equilibrium" and y.size == 2 * (3 + 4 * n)
    straight = initial_model_state(sat, model)  # the same bodies, beads on the lines
    assert np.array_equal(straight[:3], y[:3])
    before = np.max(np.abs(_across(sat, model, straight, n)))
    assert before > 1e-6
    assert np.max(np.abs(_across(sat, model, y, n))) < 1e-3 * before
    bead_stiffness = sat.E1 * (n + 1) ** 2 / (sat.l10 * MT)  # EA / (l_s m_b) [1/s²]
    left = np.max(np.abs(_at_rest(model, sat, y)))
    assert left < np.finfo(float).eps * 100.0 * bead_stiffness
    assert np.all(y[y.size // 2:] == 0.0)  # at rest in L
    assert sat.initial == (*y[:3], 0.0, 0.0, 0.0)  # the record says where it started


def test_the_beads_sag_across_their_lines_not_along_them():
    """The chain's shape differs from the straight one across the lines (sag) by much more
    than along them: a taut fibre line barely stretches (strain ~1e-8)."""
    sat, _, model, y = start_run(_dyneema(), "derived", "equilibrium", beads=4)
    straight = initial_model_state(sat, model)
    moved = (y - straight)[3:3 + 16].reshape(2, 4, 2)
    balloon = straight[:2]
    for j in range(2):
        first = straight[3 + 8 * j: 5 + 8 * j]
        e = (balloon - first) / np.linalg.norm(balloon - first)
        along, across = moved[j] @ e, moved[j] @ np.array([-e[1], e[0]])
        assert np.max(np.abs(across)) > 1e-8  # metres: a visible sag
        assert np.max(np.abs(along)) < 1e-3 * np.max(np.abs(across))


def test_the_thesis_lines_chain_start_is_a_root_of_the_accelerations():
    """SatI's rubber-band lines with 50 g beads (derived base, dampers on): their
    accelerations vanish to 1e-13 m/s² at the chain's start, 3e-5 on the straight lines."""
    sat = SAT.replace(mt1=0.05, mt2=0.05)
    sat, start, model, y = start_run(sat, "derived", "equilibrium", beads=2)
    assert np.max(np.abs(_at_rest(model, sat, y))) < 1e-13
    assert np.max(np.abs(_at_rest(model, sat, initial_model_state(sat, model)))) > 1e-6


def test_a_given_start_keeps_its_beads_on_the_straight_lines():
    sat = SAT.replace(mt1=0.05, mt2=0.05)
    run_sat, start, model, y = start_run(sat, "derived", "given", beads=2)
    assert start == "given" and run_sat.initial == SAT.initial
    np.testing.assert_array_equal(y, straight_chain(initial_model_state(run_sat, "derived"), 2,
                                                    parameter_vector(run_sat, model)))


def test_a_chain_equilibrium_not_found_falls_back_to_the_straight_chain_in_one_warning(
        monkeypatch):
    """A chain kernel whose accelerations are noise at any state (a stand-in for a chain
    with no equilibrium near its straight start): the straight chain, and one line saying
    so."""
    rng = np.random.default_rng(21)
    real = bead_kernels.kernels("derived")

    def noisy(t, y, p, dydt):
        real.rhs(t, y, p, dydt)
        dydt[y.size // 2:] = rng.normal(0.0, 1.0, y.size // 2)
    monkeypatch.setattr(bead_kernels, "kernels", lambda base: real._replace(rhs=noisy))
    with pytest.warns(RuntimeWarning) as caught:
        sat, start, model, y = start_run(_dyneema(), "derived", "equilibrium", beads=2)
    message = str(caught[0].message)
    assert "\n" not in message and "2-bead chain's equilibrium was not found" in message
    np.testing.assert_array_equal(y, initial_model_state(sat, model))


# compiles the objective-damper chain's Radau loop (~45 s cold)
@pytest.mark.slow
def test_a_dyneema_chain_started_at_its_equilibrium_takes_few_implicit_steps():
    """0.2 orbit of SatI on 1 mm Dyneema lines as four beads each, Radau IIA at rtol 1e-8,
    atol 1e-9 (the bead lines' rounding floor): from the chain's equilibrium the run is
    quiet (≤ 100 steps, every coordinate within 1e-9 m of the start); from the straight
    chain the beads ring across their lines and it takes more than 1000."""
    from tethersim.engine.simulate import _run_adaptive
    sat = _dyneema(base="objective-damper")
    kw = dict(method="implicit", model="objective-damper", rtol=1e-8, atol=1e-9, beads=4,
              progress=False)
    res = ts.simulate(sat, 0.2, **kw)
    assert res.status == "ok" and res.start == "equilibrium"
    nq = res.states.shape[1] // 2
    assert res.n_accepted <= 100
    assert np.max(np.abs(res.states[:, :nq] - res.states[0, :nq])) < 1e-9
    straight = _run_adaptive(res.satellite, 0.2, res.t.size - 1, res.model, 1e-8, 1e-9, True,
                             False, start=initial_model_state(res.satellite, res.model),
                             scheme="implicit")
    assert straight.status == "ok" and straight.n_accepted > 1000


# the same compiled loop as the test above (any N reuses it)
@pytest.mark.slow
@pytest.mark.parametrize("n", [8, 16, 32])
def test_many_stiff_beads_at_rest_take_few_implicit_steps_with_the_fine_jacobian(n):
    """With 8 or more 1 mm Dyneema beads a line a segment at rest stretches by less than
    the √ε difference step of the Jacobian (~1e-7 m at the nodes' 6-30 m), which crosses
    its slack kink: Newton then stalled at every step (N = 8 took thousands of steps in
    0.2 orbit, N = 16 did not finish in minutes).  Radau switches to the
    fine step (linalg.FD_STEP_FINE) once Newton fails with a fresh Jacobian: the chain
    at rest takes tens of steps and stays within 1e-9 m of its start."""
    sat = _dyneema(base="objective-damper")
    res = ts.simulate(sat, 0.2, method="implicit", model="objective-damper", rtol=1e-8,
                      atol=1e-9, beads=n, progress=False)
    assert res.status == "ok" and res.start == "equilibrium"
    nq = res.states.shape[1] // 2
    assert res.n_accepted <= 100
    assert np.max(np.abs(res.states[:, :nq] - res.states[0, :nq])) < 1e-9
