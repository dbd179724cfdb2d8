"""The layout of a bead-chain model: its bases, state, parameter vector and start.

The Python side of tethersim/model/beads.py (the compiled kernels are there):
which base models a chain may be added to, the names and units of its state, the
parameter vector with the line masses, diameters, drag coefficient and attachment
points (each checked against its range in one line), and the straight-line start.
docs/beads.md.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.model.registry import BEAD_BASES, get_model

#: the base models a chain can be added to (planar, circular orbit, derived tethers)
BASES = BEAD_BASES
#: beads per tether a chain may have
N_MAX = 64
#: parameters after the base model's: tether masses [kg], diameters [m], drag coefficient,
#: attachment points on the boom [m] (from the COM, + toward the tip-mass: b and −a are the
#: thesis's boom ends, Eqs 3.10-3.11)
EXTRA_PARAMETERS = ("mt1", "mt2", "dt1", "dt2", "CDt", "s1", "s2")
EXTRA_UNITS = ("kg", "kg", "m", "m", "1", "m", "m")
# plausible ranges of the extra parameters (SI): a line from a 1 mm thread to a 10 km cable
EXTRA_RANGES = {"mt1": (0.0, 1e4), "mt2": (0.0, 1e4), "dt1": (0.0, 0.1), "dt2": (0.0, 0.1),
                "CDt": (0.0, 4.0)}
_BASE_NAMES = ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b", "l10", "l20", "E1", "E2", "c1",
               "c2", "CD", "r0", "mu", "omega", "omega_earth", "rho1", "rho2", "rho3")
NB = len(_BASE_NAMES)  # length of the base models' parameter vector
(_M1, _M2, _M3, _A1, _A2, _A3, _A, _B, _L10, _L20, _E1, _E2, _C1, _C2, _CD, _R0, _MU, _OMEGA,
 _OMEGA_E, _RHO1, _RHO2, _RHO3) = range(NB)
_S1 = NB + EXTRA_PARAMETERS.index("s1")  # tether j's attachment point: p[_S1 + j]
#: floats of kernel scratch after the extra parameters (the base p, state, rates)
SCRATCH = NB + 12


def check_base(base: str) -> None:
    """Raise a one-line ValueError unless ``base`` is in :data:`BASES`."""
    if base not in BASES:
        raise ValueError(f"bead base model = {base!r}: allowed values {', '.join(BASES)}")
    if tuple(get_model(base).parameters) != _BASE_NAMES:  # a layout change in generated/
        raise ValueError(f"bead base model = {base!r}: its parameter vector is not the "
                         f"thesis layout {_BASE_NAMES}")


def check_beads(n) -> int:
    """N as an int; one-line ValueError unless 0 ≤ N ≤ :data:`N_MAX`."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 0 <= n <= N_MAX:
        raise ValueError(f"beads = {n!r}: allowed an integer 0 to {N_MAX} (beads per tether)")
    return int(n)


def state_names(base: str, n: int) -> tuple:
    """(names, SI units) of the chain model's state: base coordinates, beads, rates."""
    check_base(base)
    n = check_beads(n)
    m = get_model(base)
    nq = m.n_coordinates
    q = list(m.state[:nq])
    units = list(m.state_units[:nq])
    for j in (1, 2):
        for k in range(1, n + 1):
            q += [f"x_{j}_{k}", f"y_{j}_{k}"]
            units += ["m", "m"]
    return (tuple(q) + tuple(f"{s}_dot" for s in q),
            tuple(units) + tuple(f"{u}/s" for u in units))


def attachment_points(sat) -> tuple:
    """(s1, s2) [m]: where tether 1 and 2 hold the boom, from the COM toward the tip-mass.

    ``Satellite.s1``, ``s2``; None is the thesis's boom end (tether 1 at the tip-mass,
    +b; tether 2 at the bus, −a; Eqs 3.10-3.11).
    """
    return (sat.b if sat.s1 is None else sat.s1, -sat.a if sat.s2 is None else sat.s2)


def moved_attachments(sat) -> bool:
    """Whether a tether holds the boom elsewhere than the thesis's end (``s1``, ``s2``)."""
    return attachment_points(sat) != (sat.b, -sat.a)


def attachments_refused(sat, model: str) -> str:
    """The one-line refusal of ``sat``'s attachment points by ``model``, whose lines hold
    the boom's ends (only a chain over :data:`BASES` holds them elsewhere)."""
    return (f"s1, s2 = {sat.s1}, {sat.s2} m (tether attachment points): model {model!r} "
            f"holds its tethers at the boom ends (b, -a); attachment points run as a bead "
            f"chain over {', '.join(BASES)} (simulate, tethersim run; --beads 0 for "
            f"massless lines; docs/beads.md)")


def parameter_vector(base_p, mt1: float, mt2: float, dt1: float = 0.0, dt2: float = 0.0,
                     CDt: float = 0.0, n: int = 1, s1: float | None = None,
                     s2: float | None = None) -> np.ndarray:
    """The chain model's parameter vector: the base model's p, then :data:`EXTRA_PARAMETERS`,
    then :data:`SCRATCH` floats the kernels overwrite (their scratch: no allocation).

    Parameters
    ----------
    base_p : array_like
        The base model's parameter vector (tethersim.model.inputs.parameter_vector).
    mt1, mt2 : float
        Mass of tether 1 and 2 [kg]; > 0 when N ≥ 1 (a bead needs mass).
    dt1, dt2 : float, optional
        Tether diameters [m] for the segment drag.
    CDt : float, optional
        Segment drag coefficient on the normal flow (0: no tether drag).
    n : int, optional
        Beads per tether (for the mass check).
    s1, s2 : float, optional
        Where tether 1 and 2 hold the boom [m], from the COM toward the tip-mass, in
        −a … b (None: the boom ends, b and −a, as in the thesis).

    Raises
    ------
    ValueError
        One line naming the field and its allowed range.
    """
    n = check_beads(n)
    base_p = np.asarray(base_p, dtype=np.float64)
    if base_p.shape != (NB,):
        raise ValueError(f"base parameter vector: length {base_p.shape} given, {NB} needed")
    values = {"mt1": mt1, "mt2": mt2, "dt1": dt1, "dt2": dt2, "CDt": CDt}
    for name, v in values.items():
        lo, hi = EXTRA_RANGES[name]
        if not (isinstance(v, (int, float, np.floating)) and lo <= v <= hi):
            raise ValueError(f"{name} = {v!r}: allowed {lo:g} to {hi:g} "
                             f"{EXTRA_UNITS[EXTRA_PARAMETERS.index(name)]}")
        if n > 0 and name in ("mt1", "mt2") and v <= 0.0:
            raise ValueError(f"{name} = {v!r}: a chain of {n} beads needs a tether mass > 0 "
                             f"(up to {hi:g} kg)")
    a, b = float(base_p[_A]), float(base_p[_B])
    s1 = b if s1 is None else s1
    s2 = -a if s2 is None else s2
    for name, v in (("s1", s1), ("s2", s2)):
        if not (isinstance(v, (int, float, np.floating)) and -a <= v <= b):
            raise ValueError(f"{name} = {v!r}: allowed {-a:g} to {b:g} m (a point on the boom, "
                             f"from the bus end −a through the COM 0 to the tip-mass end b)")
    return np.concatenate([base_p, np.array([mt1, mt2, dt1, dt2, CDt, s1, s2],
                                            dtype=np.float64), np.zeros(SCRATCH)])


def straight_chain(y_base, n: int, p) -> np.ndarray:
    """A chain state from a base-model state: beads evenly spaced on the straight lines.

    Each tether's beads sit at k/(N+1) of the way from its attachment point on the boom
    (p's s1, s2) to the balloon, their rates interpolated the same way between the
    attachment's and the balloon's velocities in L (a rigid straight line: taut wherever
    the tether was).
    """
    n = check_beads(n)
    y_base = np.asarray(y_base, dtype=np.float64)
    dx, dy, th, dxd, dyd, thd = y_base
    s, c = math.sin(th), math.cos(th)
    ends = tuple(((arm * s, arm * c), (arm * thd * c, -arm * thd * s))
                 for arm in (p[_S1], p[_S1 + 1]))
    pos, vel = [dx, dy, th], [dxd, dyd, thd]
    for (ex, ey), (evx, evy) in ends:
        for k in range(1, n + 1):
            f = k / (n + 1)
            pos += [ex + f * (dx - ex), ey + f * (dy - ey)]
            vel += [evx + f * (dxd - evx), evy + f * (dyd - evy)]
    return np.array(pos + vel, dtype=np.float64)
