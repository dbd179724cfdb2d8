"""The arguments of simulate(): allowed tolerances, run lengths and schemes, refused in one line.

Every check names the argument, the value given and the allowed range (docs/limits.md).
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.model.satellite import Satellite

# allowed adaptive tolerances.  rtol: below 1e-14 is under double precision's resolution
# (~2.2e-16 per operation, amplified by the stage sums); above 1e-3, scipy solve_ivp's
# default and the loosest tolerance in common use, a step may be wrong by more than 0.1 %
# and over the thousands of steps of a run the pitch error reaches the 0.05 rad settling
# band (`run --rtol 0.9` "left the domain" on satI): the result would be the integrator's.
# atol [m, rad, m/s, rad/s]: below 1e-20 the absolute term vanishes beside any
# state of size >= 1e-6 (it then plays no role) and near 1e-300 the starting-step estimate
# divides by zero; above 1e-3 (1 mm, 1 mrad per step) it swamps rtol on the states of order
# 1 rad and 10 m that the thesis's runs have.
RTOL_RANGE = (1e-14, 1e-3)
ATOL_RANGE = (1e-20, 1e-3)
# shortest run: below 1e-4 orbit (~0.5 s at 200 km) the step budget (guards.step_budget) x
# periods falls under 100 steps (0 for 1e-9 orbit: "too many steps at t = 0")
MIN_PERIODS = 1e-4


def check_positive(name, value, integer=False):
    """``value`` as a finite float > 0 (an int >= 1 when ``integer``); else ValueError."""
    if integer:
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError(f"{name} = {value!r}: must be an integer >= 1")
        return int(value)
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r}: must be a positive number") from None
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {value!r}: must be a finite number > 0")
    return v


def check_range(name, value, bounds):
    """``value`` as a float inside ``bounds`` (inclusive); else ValueError naming them."""
    v = check_positive(name, value)
    if not bounds[0] <= v <= bounds[1]:
        raise ValueError(f"{name} = {value!r}: allowed range {bounds[0]:g} <= {name} <= "
                         f"{bounds[1]:g} (docs/limits.md)")
    return v


def check_scheme(sat: Satellite, method: str) -> None:
    """Refuse tethers or dampers too stiff for an explicit scheme, in one line.

    RK4 and DOP853 must resolve a tether's axial oscillation step by step (a real fibre
    line's is a fraction of a second: docs/tethers.md); the implicit scheme need not.
    A satellite made with ``allow_implausible`` runs anyway (slowly).

    Parameters
    ----------
    sat : Satellite
        The satellite.
    method : str
        ``"adaptive"``, ``"rk4"`` (explicit) or ``"implicit"``.

    Raises
    ------
    ValueError
        Naming the tether, its period and the way out.
    """
    if method == "implicit" or sat.allow_implausible:
        return
    from tethersim.model.plausibility import stiffness_problems
    stiff = stiffness_problems(sat)
    if stiff:
        raise ValueError(f"{stiff[0]}; method='implicit' (--method implicit) integrates stiff "
                         f"tethers (docs/tethers.md)")
