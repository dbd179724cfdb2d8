"""Bead chains through simulate() and the CLI (docs/beads.md)."""
from __future__ import annotations

import pytest

from tethersim.cli.main import main


@pytest.mark.parametrize("n", ["65", "-1"])
def test_cli_refuses_beads_outside_0_to_64_in_one_line(n, tmp_path, capsys):
    assert main(["run", "satI", "--beads", n, "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"beads = {n}: allowed an integer 0 to 64" in err


# each chain loop compiles for 20-50 s cold: the runs are the slow tier (CI runs it)
@pytest.mark.slow
def test_zero_beads_on_massless_lines_is_the_plain_run_to_1e_12():
    import numpy as np

    import tethersim as ts
    sat = ts.load_preset("satI")
    plain = ts.simulate(sat, 1.0, method="rk4", steps=2000, progress=False)
    chain = ts.simulate(sat, 1.0, method="rk4", steps=2000, progress=False, beads=0)
    assert chain.status == plain.status == "ok"
    a, b = plain.states[:, :6], chain.states[:, :6]
    scale = np.max(np.abs(a), axis=0)
    assert np.max(np.abs(a - b) / scale) <= 1e-12


@pytest.mark.slow
def test_a_bead_run_writes_bead_columns_and_the_tether_shape(tmp_path):
    out = tmp_path / "o"
    assert main(["run", "satI", "--beads", "2", "--set", "mt1=0.01", "--set", "mt2=0.01",
                 "--periods", "0.05", "--out", str(out), "--quiet"]) == 0
    header = (out / "timeseries.csv").read_text().splitlines()[0]
    for col in ("x_1_1", "y_1_2", "x_2_2", "tension_1_1", "tension_2_3"):
        assert col in header, col
    assert (out / "tether_shape.png").is_file()


@pytest.mark.slow
def test_a_bead_chain_run_conserves_the_jacobi_integral_to_1e_8_over_five_orbits():
    """Two beads of 1/6 kg per line (0.5 kg lines), the thesis's springs, drag and
    dampers off, from the preset's start (balloon 29 m behind): the compiled DOP853 loop
    at rtol 1e-12 keeps the chain's Jacobi integral (tethersim.model.beads.jacobi, which
    the loop never evaluates) to 1e-8 of |h| and of the spring energy exchanged, over five
    orbits with segments going slack and taut (issue 21's energy target).  It holds
    because every segment's switch is an event of its own (engine/events.py): with only
    each line's most stretched segment located, the kinks of the others were stepped
    over and the drift was twice the bound."""
    import numpy as np

    import tethersim as ts
    from tethersim.model import bead_kernels
    n = 2
    sat = ts.load_preset("satI").replace(CD=0.0, c1=0.0, c2=0.0, CDt=0.0, mt1=0.5, mt2=0.5)
    r = ts.simulate(sat, 5.0, method="adaptive", rtol=1e-12, atol=1e-14, samples=5000,
                    progress=False, beads=n)
    assert r.status == "ok" and r.model == "derived+beads2" and r.n_switches > 0
    k, p = bead_kernels.kernels("derived"), r.parameters
    h = np.array([k.jacobi(y, p) for y in r.states])
    T = np.empty((r.t.size, 2, n + 1))
    for i, y in enumerate(r.states):
        k.tensions(y, p, T[i])
    stiffness = p[10:12, None] / (p[8:10, None] / (n + 1))  # E_j / l_s [N/m]
    exchanged = np.ptp(np.sum(T**2 / (2 * stiffness), axis=(1, 2)))  # Σ ½ k (λ − l_s)²
    taut = T > 0
    assert np.any(taut.all(axis=0) != taut.any(axis=0))  # some segment went slack and taut
    assert np.max(np.abs(h - h[0])) <= 1e-8 * min(exchanged, abs(h[0]))


@pytest.mark.slow
def test_a_chain_started_at_its_own_equilibrium_stays_there_for_an_orbit():
    """SatI's thesis lines with 50 g each as two beads per line, drag and dampers on.
    simulate's equilibrium start is the chain's own (engine/start.chain_at_rest: beads
    sagging off the straight lines under their tidal load and the tension), a fixed point
    of the compiled DOP853 loop: from it, every coordinate stays within 1e-6 m (rates
    1e-6 m/s) over one orbit.  The same bodies with their beads on the straight lines are
    not one: the beads leave them by more than 1e-5 m."""
    import numpy as np

    import tethersim as ts
    from tethersim.engine.simulate import _run_adaptive
    from tethersim.model.inputs import initial_model_state
    n, tol = 2, 1e-6
    sat = ts.load_preset("satI").replace(mt1=0.05, mt2=0.05)
    held = ts.simulate(sat, 1.0, start="equilibrium", beads=n, progress=False)
    assert held.status == "ok" and held.start == "equilibrium"
    y0, nq = held.states[0], held.states.shape[1] // 2
    assert np.max(np.abs(held.states[:, :nq] - y0[:nq])) <= tol
    assert np.max(np.abs(held.states[:, nq:])) <= tol
    # the loop simulate runs, started on the straight lines (engine/release.py's way)
    y_straight = initial_model_state(held.satellite, held.model)
    assert np.array_equal(y_straight[:3], y0[:3]) and np.max(np.abs(y_straight - y0)) > 0
    straight = _run_adaptive(held.satellite, 1.0, 200, held.model, 1e-10, 1e-12, True,
                             False, start=y_straight)
    assert straight.status == "ok"
    assert np.max(np.abs(straight.states[:, 3:nq] - y_straight[3:nq])) > 10 * tol


@pytest.mark.slow
def test_each_segment_of_a_chain_is_a_switch_slot_of_its_own():
    """A chain's event vector (engine/events.py) holds, after the fixed slots, one
    switch slot per segment, (N + 1) λ_s − l_j0, tether 1's then tether 2's: checked
    against the segments' lengths from the node positions in numpy.  Slots 0, 1 (each
    line's most stretched segment) are the largest of their line's slots, bit for bit;
    without switch location the segment slots are +1."""
    import numpy as np

    import tethersim as ts
    from tethersim.engine.events import N_EVENTS, event_parameters, events_at
    from tethersim.model.registry import model_index
    n = 2
    sat = ts.load_preset("satI").replace(mt1=0.5, mt2=0.5)
    r = ts.simulate(sat, 0.05, method="adaptive", samples=20, progress=False, beads=n)
    k, p = model_index(r.model), r.parameters
    ev = event_parameters(sat, r.model)
    for y in r.states[::4]:
        g = events_at(k, y, p, ev)
        assert g.shape == (N_EVENTS + 2 * (n + 1),)
        th = y[2]
        for j, (arm, l0) in enumerate(((sat.b, sat.l10), (-sat.a, sat.l20))):
            nodes = [(arm * np.sin(th), arm * np.cos(th))]
            nodes += [tuple(y[3 + 2 * (j * n + i):5 + 2 * (j * n + i)]) for i in range(n)]
            nodes += [(y[0], y[1])]
            lam = np.hypot(*np.diff(np.array(nodes), axis=0).T)
            seg = g[N_EVENTS + j * (n + 1):N_EVENTS + (j + 1) * (n + 1)]
            np.testing.assert_allclose(seg, (n + 1) * lam - l0, rtol=0, atol=1e-12 * l0)
            assert g[j] == seg.max()
        off = events_at(k, y, p, ev, switches=False)
        assert np.all(off[N_EVENTS:] == 1.0)


@pytest.mark.slow
def test_a_chain_s_jacobi_integral_falls_by_the_work_of_drag_and_dampers_to_1e_6():
    """Two beads per 0.5 kg line, the thesis's springs and dampers, drag on the bodies and
    cross-flow drag on 1 mm segments, one orbit at rtol 1e-11: h(t) − h(0) equals the
    work of drag and dampers (beads.chain_power, Simpson on the samples) to 1e-6 of
    the work (issue 21's energy target).  The segments' share counts: the same budget
    with their dampers and drag left out of the power misses by more than 1e-4."""
    import numpy as np
    from scipy.integrate import cumulative_simpson

    import tethersim as ts
    from tethersim.engine.evaluate import chain_power_series
    from tethersim.model.inputs import parameter_vector
    from tethersim.model.registry import model_index
    sat = ts.load_preset("satI").replace(mt1=0.5, mt2=0.5, CDt=1.2, dt1=1e-3, dt2=1e-3)
    r = ts.simulate(sat, 1.0, method="adaptive", rtol=1e-11, atol=1e-13, samples=20000,
                    progress=False, beads=2)
    assert r.status == "ok"
    eb = r.energy_budget()
    work = eb["work"][-1]
    assert work < 0 and np.max(np.abs(eb["residual"])) <= 1e-6 * abs(work)
    bodies_only = parameter_vector(sat.replace(CDt=0.0, c1=0.0, c2=0.0), r.model)
    power = chain_power_series(model_index(r.model), r.air, r.t, r.states, bodies_only)
    missed = eb["jacobi"] - eb["jacobi"][0] - cumulative_simpson(power, x=r.t, initial=0.0)
    assert np.max(np.abs(missed)) > 1e-4 * abs(work)
