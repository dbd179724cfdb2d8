"""Runs reproduce the engine before the reference-count-free loops (issue 10).

The reference values below were computed with the engine at commit af5dd73: the
final state and the step counters of each run.  Stored on one machine, they are
compared to the tolerances of tests/reference.py (another CPU may round an
operation differently).  Bit identity is checked where it holds, on this
machine: the same run in one call, in chunks for a progress bar, or in one call
after a first chunk takes the same steps to the last bit; and ``make
check-bitwise BASE=af5dd73`` compares the whole state arrays of these runs at
that commit and now, both computed here.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests.reference import assert_count_close, assert_final_close, stored_tolerances
from tests.tiers import VARIANT_LOOP
from tethersim import load_preset, simulate


def _switching(sat):
    # tether 2 starts slack and goes taut: one located switch in 0.2 orbits
    return sat.replace(initial=(4.0, 0.0, 0.3, 0.0, 0.0, 0.0), c1=0.01, c2=0.01)


def _per_body(sat):
    return sat.replace(density_mode="per-body")


# name: (satellite transform, simulate kwargs, (accepted, rejected, switches, nfev),
#        final state)
REFERENCE = {
    "rk4": (None, dict(periods=2, steps=600, method="rk4"), (600, 0, 0, 2400),
            ['28.916867325583244', '0.011061566123339502', '-0.22479842708064043',
             '7.142599095753662e-05', '9.740738990105506e-05', '-0.0016592787819644892',
             '6578136.990745715', '0.45159564330242574', '-0.000534397306040546',
             '7784.261754041153']),
    "dop853": (None, dict(periods=2), (2000, 72, 0, 26066),
               ['28.917850782489907', '0.009501601128912731', '-0.2247978292966085',
                '-0.0001902262563104282', '0.00019874036713191383', '-0.0016592873687979156',
                '6578137.000000035', '1.3075162996756262e-07', '-1.6974038841155448e-10',
                '7784.261748565581']),
    "rk4_switch_printed": (
        _switching, dict(periods=0.2, steps=200, method="rk4", locate_switches=True,
                         model="printed"), (200, 0, 1, 800),
        ['28.91332391392838', '-0.09447261830484549', '-0.31823453879098246',
         '-4.052458306887107e-06', '9.062841070915942e-06', '0.0004751851302793594',
         '2032756.1243016066', '6256180.058823642', '-7403.272860696547', '2405.469168848531']),
    "dop853_switch": (
        _switching, dict(periods=0.2), (254, 36, 1, 3602),
        ['28.911985531120596', '-0.09553082897115726', '-0.292741381916631',
         '-4.827132599592915e-06', '5.341892541517537e-06', '0.0004630948117227226',
         '2032756.1243266454', '6256180.058932252', '-7403.272860520441', '2405.4691689696333']),
    "dop853_per_body_exact_gravity": (
        _per_body, dict(periods=1, model="exact-gravity"), (1938, 961, 0, 35390),
        ['28.88510542873113', '-0.030679642243214594', '0.29406805118135904',
         '0.0009526909032067725', '-0.0004581824977185236', '-0.001589947551836704',
         '6578137.0000000065', '-5.756010068580508e-08', '6.6691541178443e-11',
         '7784.261748565624']),
    "rk4_per_body_objective_damper": (
        _per_body, dict(periods=1, steps=300, method="rk4", model="objective-damper"),
        (300, 0, 0, 1200),
        ['28.899825728683847', '-0.03027208940651309', '0.3428245533522139',
         '1.8785598141529237e-05', '0.00012685141171110085', '-0.0014484902133203767',
         '6578136.995372875', '0.2039930471801199', '-0.00024139588703064874',
         '7784.261751303384']),
}


@pytest.fixture(scope="module")
def sat():
    return load_preset("satI")


# a stored adaptive run that no longer passes once the engine stopped integrating the COM
# orbit (issue 22), even at the stored steps' tolerances (tests/reference.py); strict: a
# pass means the note is stale.  Measured on the code before issue 22, the per-body run
# itself moves by 5.7e-9 of δẋ's scale under one ulp of its starting θ (its steps chatter:
# 961 rejected of 1938), above the 1e-9 its comparison assumes.  The 0.2-orbit switch run
# was listed too (251 steps against 254, its start guessed without the orbit's states);
# with the kernels' own sin and cos (generated/trig.py) it takes 252, within the 1 %: a
# count this close to its bound moves with the last bit of a sine, and the derived model
# kernels now call no libm function whose last bit depends on the CPU (sqrt is exact)
NOT_REPRODUCED = {
    "dop853_per_body_exact_gravity": "one ulp at the start moves δẋ by 5.7e-9 of its scale",
}


def _marks(name):
    """The reference's marks: xfail where NOT_REPRODUCED, slow for a variant's loop."""
    marks = [VARIANT_LOOP] if REFERENCE[name][1].get("model", "derived") != "derived" else []
    if name in NOT_REPRODUCED:
        marks.append(pytest.mark.xfail(strict=True, reason=NOT_REPRODUCED[name]))
    return marks


@pytest.mark.parametrize("name", [pytest.param(n, marks=_marks(n)) for n in sorted(REFERENCE)])
def test_trajectory_matches_the_reference(sat, name):
    transform, kwargs, counts, final = REFERENCE[name]
    if kwargs.get("method") != "rk4":  # the steps the stored run took (tests/reference.py)
        kwargs = {**kwargs, **stored_tolerances(kwargs.get("model", "derived"))}
    r = simulate(transform(sat) if transform else sat, check=False, progress=False, **kwargs)
    assert r.status == "ok"
    assert_final_close(r, final)
    if r.method == "rk4":  # fixed steps: the counts are the step count's
        assert (r.n_accepted, r.n_rejected, r.n_switches, r.nfev) == counts
    else:
        assert_count_close(r.n_accepted, counts[0])
        assert r.n_switches == counts[2]


@pytest.mark.parametrize("name", [
    pytest.param(n, marks=[m for m in _marks(n) if m is VARIANT_LOOP]) for n in sorted(REFERENCE)])
@pytest.mark.parametrize("progress", [True, None])
def test_chunked_runs_are_bit_identical_to_one_call(sat, name, progress):
    # progress=True runs in chunks (pauses for the bar), None in chunks or, for a short
    # run, in one call after the first chunk: the same steps every way, on one machine
    transform, kwargs, _, _ = REFERENCE[name]
    s = transform(sat) if transform else sat
    one = simulate(s, check=False, progress=False, **kwargs)
    r = simulate(s, check=False, progress=progress, **kwargs)
    assert (r.n_accepted, r.n_rejected, r.n_switches) == (
        one.n_accepted, one.n_rejected, one.n_switches)
    np.testing.assert_array_equal(r.t, one.t)
    np.testing.assert_array_equal(r.states, one.states)
