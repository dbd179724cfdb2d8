"""The bead chain's compiled entry points, one per base model, and its event functions
(tethersim.model.beads).

Each base is a compile-time literal of its own entry points (``rhs_derived`` ...), as
tethersim/engine/dynamics.py picks a model's generated kernels; :func:`kernels` gives
them to Python, :func:`engine_kernels` to the engine's loops (the registry's module
of a chain, tethersim.model.registry).
"""
from __future__ import annotations

import math
from collections import namedtuple
from types import SimpleNamespace

from numba import njit

from tethersim.model.bead_base import GENERATED
from tethersim.model.bead_layout import _L10
from tethersim.model.beads import (
    chain_jacobi,
    chain_power,
    chain_rhs,
    check_base,
    node,
    tensions,
)

Kernels = namedtuple("Kernels", "rhs jacobi tensions power")


# the chain's event functions (engine/events.py): each line's most stretched segment, and
# every segment on its own
@njit(cache=True, inline="always")
def tether_margins(y, p, g):
    """g[j] = (N + 1) max_s (λ_s − l_s) [m]: the most stretched segment of tether j, as the
    line's extension at that segment's tension (the events' stretch and break limits)."""
    n = (y.shape[0] // 2 - 3) // 4
    for j in range(2):
        worst = -math.inf
        for s in range(n + 1):
            x0, y0, _, _ = node(y, p, n, j, s)
            x1, y1, _, _ = node(y, p, n, j, s + 1)
            worst = max(worst, (n + 1) * math.hypot(x1 - x0, y1 - y0))
        g[j] = worst - p[_L10 + j]


@njit(cache=True, inline="always")
def segment_count(y):
    """Segments of both lines together, 2 (N + 1): the chain's own switch slots."""
    return 2 * ((y.shape[0] // 2 - 3) // 4 + 1)


@njit(cache=True)  # not inlined: numba's inliner trips on its loops in model_events
def segment_margins(y, p, g, first):
    """g[first + j (N + 1) + s] = (N + 1)(λ_s − l_s) [m]: each segment's taut/slack margin,
    tether j's segment s (boom end first), in the line's extension units as
    :func:`tether_margins`; each is an event of its own, so the loops locate every
    segment's switch, not only the most stretched one's."""
    n = (y.shape[0] // 2 - 3) // 4
    for j in range(2):
        for s in range(n + 1):
            x0, y0, _, _ = node(y, p, n, j, s)
            x1, y1, _, _ = node(y, p, n, j, s + 1)
            g[first + j * (n + 1) + s] = (n + 1) * math.hypot(x1 - x0, y1 - y0) - p[_L10 + j]


# one entry point per base model: the base is a compile-time literal of each
@njit(cache=True)
def rhs_derived(t, y, p, dydt):
    """dy/dt of the chain over ``derived``."""
    chain_rhs(0, t, y, p, dydt)


@njit(cache=True)
def rhs_exact_gravity(t, y, p, dydt):
    """dy/dt of the chain over ``exact-gravity``."""
    chain_rhs(1, t, y, p, dydt)


@njit(cache=True)
def rhs_objective_damper(t, y, p, dydt):
    """dy/dt of the chain over ``objective-damper``."""
    chain_rhs(2, t, y, p, dydt)


@njit(cache=True)
def jacobi_derived(y, p):
    """Jacobi integral of the chain over ``derived`` [J]."""
    return chain_jacobi(0, y, p)


@njit(cache=True)
def jacobi_exact_gravity(y, p):
    """Jacobi integral of the chain over ``exact-gravity`` [J]."""
    return chain_jacobi(1, y, p)


@njit(cache=True)
def jacobi_objective_damper(y, p):
    """Jacobi integral of the chain over ``objective-damper`` [J]."""
    return chain_jacobi(2, y, p)


@njit(cache=True)
def power_derived(y, p, fam):
    """Power of drag and dampers of the chain over ``derived`` [W]."""
    return chain_power(0, y, p, fam)


@njit(cache=True)
def power_exact_gravity(y, p, fam):
    """Power of drag and dampers of the chain over ``exact-gravity`` [W]."""
    return chain_power(1, y, p, fam)


@njit(cache=True)
def power_objective_damper(y, p, fam):
    """Power of drag and dampers of the chain over ``objective-damper`` [W]."""
    return chain_power(2, y, p, fam)


_KERNELS = {"derived": Kernels(rhs_derived, jacobi_derived, tensions, power_derived),
            "exact-gravity": Kernels(rhs_exact_gravity, jacobi_exact_gravity, tensions,
                                     power_exact_gravity),
            "objective-damper": Kernels(rhs_objective_damper, jacobi_objective_damper, tensions,
                                        power_objective_damper)}


def engine_kernels(base: str) -> SimpleNamespace:
    """The module interface the engine's compiled loops read (tethersim.engine.dynamics):
    ``rhs``, ``tether_margins`` (the most stretched segment of each line),
    ``segment_count`` and ``segment_margins`` (every segment's switch, engine/events.py),
    ``body_radii`` (the base model's: the beads' air is the balloon's), ``jacobi`` and
    ``power`` (of drag and dampers, beads.chain_power)."""
    check_base(base)
    k = _KERNELS[base]
    return SimpleNamespace(rhs=k.rhs, jacobi=k.jacobi, tensions=tensions, power=k.power,
                           tether_margins=tether_margins, segment_count=segment_count,
                           segment_margins=segment_margins,
                           body_radii=GENERATED[base].body_radii)


def kernels(base: str = "derived") -> Kernels:
    """The compiled chain kernels (rhs, jacobi, tensions, power) over base model ``base``.

    The same number of beads per tether on both lines, read from the state's length.
    """
    check_base(base)
    return _KERNELS[base]
