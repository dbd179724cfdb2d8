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


def state_scales(res) -> np.ndarray:
    """A scale per column of ``res.states``: the size of each coordinate in this run.

    Lengths of the balloon's offsets: the longest tether path; angles: pi; the
    orbit radius and position: r0; rates: those times the orbital rate.
    """
    sat = res.satellite
    length = max(sat.l10 + sat.b, sat.l20 + sat.a)
    names = list(res.layout.state)
    if res.states.shape[1] > len(names):  # the integrated COM orbit of a circular run
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
    err = np.abs(got - want) / state_scales(res)
    assert np.all(err <= rtol), (
        f"largest difference {err.max():.3g} of the scale (allowed {rtol:g}) in column "
        f"{int(np.argmax(err))}")


def assert_count_close(got: int, want: int, rtol: float = COUNT_RTOL):
    """An adaptive run's step or evaluation count within ``rtol`` of the stored one."""
    assert abs(got - want) <= rtol * want, f"{got} vs stored {want} (allowed {rtol:.0%})"
