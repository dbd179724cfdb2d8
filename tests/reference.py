"""Stored reference numbers, compared to a stated tolerance (issue 19).

Bit identity is a property of one machine: the same code on another CPU may round
one operation differently (LAPACK's eigenvalue kernels, chosen at run time by the
CPU, differ in the last bit between an AMD EPYC and an Intel Xeon; numba compiles
for the host CPU).  So a number stored in the repository is compared to a
tolerance that says why it is enough, and bit identity is checked by computing
twice on the machine at hand (``make check-bitwise BASE=REV`` compares a commit
with the working tree, both run here, to the last bit).

Trajectories, in units of each state's scale (:func:`state_scales`):

* fixed-step RK4: ``RK4_RTOL`` = 1e-12.  A last-bit change at the start of a
  2-orbit run moves its final state by ~1e-14 of the scale (measured by
  ``test_one_ulp_moves_a_fixed_step_run_by_less_than_its_tolerance``), and any
  change of the model or the scheme by far more than 1e-12;
* adaptive DOP853: ``ADAPTIVE_RTOL`` = 1e-9.  A last-bit change can flip one step's
  accept/reject decision (one ulp at the start turns 2000 accepted steps into
  1999), and a different step sequence moves the final state by up to the local
  error the tolerance admits: ~1e-11 of the scale at rtol 1e-10 (measured by the
  test of the same name for the adaptive run).  Step counts then agree to 1 %.

The stored adaptive runs integrated a circular run's COM orbit as four more states
(before issue 22), and DOP853's error norm is the RMS over the integrated states: the
orbit's states had next to no error, so the norm weighed the model's errors by
sqrt(n / (n + 4)).  Today's run takes those steps at its tolerances times
:func:`orbit_norm_factor` (the same norm for the same model errors); at the stored
tolerances themselves it takes 1-5 % more steps and lands closer to the truth.

Eigenvalue-derived numbers (the RK4 amplification): ``EIGEN_RTOL``, a few
hundred ulp: LAPACK's results differ between kernels by a few ulp of the largest
eigenvalue.
"""
from __future__ import annotations

import math

import numpy as np

RK4_RTOL = 1e-12
ADAPTIVE_RTOL = 1e-9
COUNT_RTOL = 0.01
EIGEN_RTOL = 1e-13


def orbit_norm_factor(res_or_model) -> float:
    """sqrt((n + 4) / n) for a circular-orbit model of n states, else 1 (module docstring).

    ``res_or_model``: a model name or a run; a factor on rtol and atol.
    """
    from tethersim.model.registry import get_model

    m = get_model(getattr(res_or_model, "model", res_or_model))
    return math.sqrt((m.n_state + 4) / m.n_state) if m.orbit == "circular" else 1.0


def stored_tolerances(model: str, rtol: float = 1e-10, atol: float = 1e-12) -> dict:
    """simulate()'s rtol and atol (default: its defaults) at which a run of ``model`` takes the
    steps a stored run at ``rtol``, ``atol`` took (:func:`orbit_norm_factor`)."""
    k = orbit_norm_factor(model)
    return {"rtol": rtol * k, "atol": atol * k}


def state_scales(res, columns: int | None = None) -> np.ndarray:
    """A scale per column of a state row of ``res``: the size of each coordinate in this run.

    Lengths of the balloon's offsets: the longest tether path; angles: pi; the
    orbit radius and position: r0; rates: those times the orbital rate.  A row of
    ``columns`` > the model's states continues with a circular run's COM orbit X, Y,
    VX, VY (``res.orbit``: a row as the reference code stored it, which integrated
    the orbit); default ``res.states``'s width.
    """
    sat = res.satellite
    length = max(sat.l10 + sat.b, sat.l20 + sat.a)
    names = list(res.layout.state)
    if (columns or res.states.shape[1]) > len(names):
        names += ["X", "Y", "X_dot", "Y_dot"]
    scales = []
    for n in names:
        base = n.removesuffix("_dot")
        s = (math.pi if base in ("theta", "phi", "psi", "nu")
             else sat.r0 if base in ("r", "X", "Y") else length)
        scales.append(s * sat.omega if n.endswith("_dot") else s)
    return np.array(scales)


def assert_state_close(res, final, ref, rtol=None):
    """``final`` (a state row of ``res``) equals the stored ``ref`` to ``rtol`` of the scales
    (default: the run's scheme's tolerance above)."""
    if rtol is None:
        rtol = RK4_RTOL if res.method == "rk4" else ADAPTIVE_RTOL
    got = np.asarray(final, dtype=float)
    want = np.array([float(v) for v in ref])
    err = np.abs(got - want) / state_scales(res, got.size)
    assert np.all(err <= rtol), (
        f"largest difference {err.max():.3g} of the scale (allowed {rtol:g}) in column "
        f"{int(np.argmax(err))}")


def assert_final_close(res, ref, rtol=None):
    """The final sample of ``res`` equals a stored final row ``ref`` (see assert_state_close).

    A row stored while the engine integrated a circular run's COM orbit (before issue 22)
    continues after the model's states with that orbit's X, Y, VX, VY (two-body, Eq 3.9);
    the engine now computes it in closed form (``res.orbit``).  Those columns are
    compared for an adaptive run, whose integrated orbit was the circle to ~1e-14 of r0,
    far inside its tolerance, and left out for a fixed-step RK4 run: they hold RK4's own
    truncation error of the circle (~4e-7 of r0 after 2 orbits of 400 steps), which the
    closed form no longer makes; its model states are compared as before.
    """
    final = res.states[-1]
    if len(ref) > final.size and res.method != "rk4":
        final = np.concatenate([final, res.orbit[-1]])
    assert_state_close(res, final, list(ref)[:final.size], rtol)


def assert_count_close(got: int, want: int, rtol: float = COUNT_RTOL):
    """An adaptive run's step or evaluation count within ``rtol`` of the stored one."""
    assert abs(got - want) <= rtol * want, f"{got} vs stored {want} (allowed {rtol:.0%})"
