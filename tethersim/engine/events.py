"""Every model's event functions: one table, one compiled vector g(y), located in the loops.

An event is a function g_i of the integrated state, positive inside.  The
integrators evaluate the whole vector at the end of every step and, where a
slot changes sign inside the step, land the step on the earliest crossing
(integrators/switching.py) as scipy's ``solve_ivp(events=...)``, heyoka's and
Orekit's event detectors do:

=====  ===============  ========  ====================================================
slot   name             kind      g (positive: inside)
=====  ===============  ========  ====================================================
0, 1   tether 1/2       switch    λ_j − l_j0: taut/slack (the run continues across it;
                                  located when ``locate_switches``)
2      re-entry         terminal  r − R_E − h_min: free-orbit models only
3      roll             terminal  ROLL_LIMIT − |φ|: 3-D models only
4      balloon reach    terminal  reach² − |δ|²
5, 6   tether stretch   terminal  MAX_STRETCH l_j0 − λ_j (none for an absent line:
                                  E_j = c_j = 0 and no mass, one line flown alone)
7, 8   tether break     terminal  l_j0 Fb_j / E_j − (λ_j − l_j0): the spring's tension
                                  E_j (λ_j − l_j0) / l_j0 reaches the breaking load Fb_j
                                  (``Satellite.Fb1``, ``Fb2``; 0: never breaks)
9 ...  segment k        switch    a bead chain's segments (tethersim.model.beads):
                                  (N + 1)(λ_s − l_s), tether 1's N + 1 then tether 2's
=====  ===============  ========  ====================================================

A slot a model lacks is +1 (it never fires).  A bead chain's vector is longer
(:func:`model_n_events`): its lines go taut and slack segment by segment, and
slots 0, 1 (the most stretched segment, the stretch and break limits' measure)
would miss the kinks of the others, so each segment is a switch slot of its own.
A terminal event fires when its slot goes from positive to non-positive; the
run stops just past it (status ``re-entered`` for the re-entry, ``tether-broke``
for a break, else ``left-domain``: engine/domain.py).  The break is judged on the spring's tension,
the damper's share left out: the damper stands for the line's internal loss, and
a dashpot force on a fast snap is not a load the fibre's strength is quoted for.  The
limits of one run (h_min, the reach, MAX_STRETCH, ROLL_LIMIT) come in the small
vector :func:`event_parameters` builds once in Python: nothing satellite-specific
is compiled in.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import literally, njit
from numba.extending import overload

from tethersim.engine.dynamics import literal_index, model_tether_margins
from tethersim.engine.integrators.select import call
from tethersim.model.constants import R_EARTH
from tethersim.model.registry import bead_index, kernels_of, record

Event = namedtuple("Event", "name terminal status")
#: the single table of events: slot order of model_events' vector (module docstring)
EVENTS = (
    Event("tether 1 switch", False, ""),
    Event("tether 2 switch", False, ""),
    Event("re-entry", True, "re-entered"),
    Event("roll", True, "left-domain"),
    Event("balloon reach", True, "left-domain"),
    Event("tether 1 stretch", True, "left-domain"),
    Event("tether 2 stretch", True, "left-domain"),
    Event("tether 1 break", True, "tether-broke"),
    Event("tether 2 break", True, "tether-broke"),
)
N_EVENTS = len(EVENTS)
N_SWITCH = sum(not e.terminal for e in EVENTS)  # the switch slots come first
SLOT = {e.name: i for i, e in enumerate(EVENTS)}
STOPS = tuple(e.name for e in EVENTS if e.terminal)


@njit(cache=True)  # called once a step has located an event: not inlined
def is_switch(slot):
    """Whether event ``slot`` is a switch (the run continues across it); -1 (none) too."""
    return slot < N_SWITCH or slot >= N_EVENTS


def model_n_events(model, y):
    """Length of model ``model``'s event vector (compiled code, literal model only):
    N_EVENTS, and a bead chain's segment slots after them (module docstring)."""
    raise NotImplementedError("model_n_events is only callable from compiled code")


@overload(model_n_events, inline="always", prefer_literal=True)
def _model_n_events(model, y):
    if (k := literal_index(model)) is None:
        return None
    if bead_index(k):
        count = kernels_of(k).segment_count

        def impl(model, y):
            return N_EVENTS + count(y)
        return impl

    def impl(model, y):
        return N_EVENTS
    return impl


# the event parameter vector (event_parameters): where each limit sits
(EV_H_MIN, EV_ROLL, EV_REACH2, EV_STRETCH, EV_L10, EV_L20, EV_NEAR2, EV_BREAK1, EV_BREAK2,
 EV_STRETCH2) = range(10)
N_EV = 10


def event_parameters(sat, model: str, stops=STOPS) -> np.ndarray:
    """The limits the compiled event function reads, for one run of ``sat`` with ``model``.

    Parameters
    ----------
    sat : Satellite
        The satellite (its re-entry altitude, tether rest lengths, boom ends).
    model : str
        Model name (tethersim.model.registry).
    stops : iterable of str, optional
        The terminal events that stop the run (names in :data:`EVENTS`); the
        others are given limits they never reach (a released balloon,
        engine/release.py, stops only at re-entry).

    Returns
    -------
    numpy.ndarray
        float64[N_EV]: h_min [m], roll limit [rad], reach² [m²], tether 1's largest
        stretch, l10, l20 [m], the squared balloon distance below which no tether can
        be over its stretch or break limit (the tether lengths are then not
        evaluated), each tether's extension at its breaking load [m] (inf: never
        breaks), and tether 2's largest stretch.  An absent line (E = c = 0, no mass:
        one line flown alone) has no stretch limit: it holds nothing.
    """
    from tethersim.engine.domain import MAX_STRETCH, ROLL_LIMIT, reach

    stops = set(stops)
    unknown = stops - set(STOPS)
    if unknown:
        raise ValueError(f"stops = {sorted(unknown)!r}: allowed values {', '.join(STOPS)}")
    inf = math.inf
    stretch_on = {"tether 1 stretch", "tether 2 stretch"} & stops
    stretch1, stretch2 = (inf if gone or not stretch_on else MAX_STRETCH
                          for gone in sat.absent_lines)
    ev = np.empty(N_EV)
    ev[EV_H_MIN] = sat.reentry_altitude if "re-entry" in stops else -inf
    ev[EV_ROLL] = ROLL_LIMIT if "roll" in stops else inf
    ev[EV_REACH2] = reach(sat) ** 2 if "balloon reach" in stops else inf
    ev[EV_STRETCH], ev[EV_STRETCH2] = stretch1, stretch2
    ev[EV_L10], ev[EV_L20] = sat.l10, sat.l20
    # the extension λ − l0 at which the spring's tension E (λ − l0) / l0 is the breaking load
    for slot, j, fb, e, l0 in ((EV_BREAK1, 1, sat.Fb1, sat.E1, sat.l10),
                               (EV_BREAK2, 2, sat.Fb2, sat.E2, sat.l20)):
        on = f"tether {j} break" in stops and fb > 0 and e > 0
        ev[slot] = l0 * fb / e if on else inf
    # tether j runs from the balloon (|δ| from the COM) to its point on the boom (|s_j|
    # from it; the thesis: b, a): λ_j <= |δ| + |s_j|, so λ_j > its limit L_j (stretch
    # l_j0, or l_j0 + the break extension) needs |δ| > L_j − |s_j|.  The margin 1e-9
    # keeps the bound conservative against the rounding of |δ|²
    from tethersim.model.bead_layout import attachment_points
    s1, s2 = attachment_points(sat)
    lim1 = min(stretch1 * sat.l10, sat.l10 + ev[EV_BREAK1])
    lim2 = min(stretch2 * sat.l20, sat.l20 + ev[EV_BREAK2])
    near = max(min(lim1 - abs(s1), lim2 - abs(s2)), 0.0) * (1.0 - 1e-9)
    ev[EV_NEAR2] = near * near
    return ev


@njit(cache=True, inline="always")
def line_limits(ev, g):
    """g[5..8], the tethers' stretch and break limits, from their margins g[0], g[1]."""
    l10, l20 = ev[EV_L10], ev[EV_L20]
    g[5] = ev[EV_STRETCH] * l10 - (g[0] + l10)
    g[6] = ev[EV_STRETCH2] * l20 - (g[1] + l20)
    g[7] = ev[EV_BREAK1] - g[0]
    g[8] = ev[EV_BREAK2] - g[1]


@njit(cache=True, inline="always")
def _no_segments(y, p, g, first):
    pass


def model_events(model, y, p, ev, g, switches):
    """g[i] = event i of model ``model`` at state y (compiled code, literal model only).

    ``switches``: whether slots 0, 1 (the tether margins) and a chain's segment slots
    are wanted; when not, the segment slots are +1 and, when the balloon is too close
    for any stretch or break limit, the tether lengths are not evaluated and slots 0,
    1, 5-8 are +1.  g has :func:`model_n_events` slots.
    """
    raise NotImplementedError("model_events is only callable from compiled code")


@overload(model_events, inline="always", prefer_literal=True)
def _model_events(model, y, p, ev, g, switches):
    if (k := literal_index(model)) is None:
        return None
    names = record(k).state
    chain = bead_index(k)
    segments = kernels_of(k).segment_margins if chain else _no_segments
    ix, iy = names.index("delta_x"), names.index("delta_y")
    iz = names.index("delta_z") if "delta_z" in names else -1
    i_r = names.index("r") if "r" in names else -1
    i_phi = names.index("phi") if "phi" in names else -1

    def impl(model, y, p, ev, g, switches):
        if i_r >= 0:
            g[2] = (y[i_r] - R_EARTH) - ev[EV_H_MIN]
        else:
            g[2] = 1.0
        if i_phi >= 0:
            g[3] = ev[EV_ROLL] - abs(y[i_phi])
        else:
            g[3] = 1.0
        d2 = y[ix] * y[ix] + y[iy] * y[iy]
        if iz >= 0:
            d2 = d2 + y[iz] * y[iz]
        g[4] = ev[EV_REACH2] - d2
        if switches or d2 > ev[EV_NEAR2]:
            model_tether_margins(model, y, p, g)  # writes g[0], g[1]
            line_limits(ev, g)
        else:
            g[0] = 1.0
            g[1] = 1.0
            g[5] = 1.0
            g[6] = 1.0
            g[7] = 1.0
            g[8] = 1.0
        if chain:
            if switches:
                segments(y, p, g, N_EVENTS)
            else:
                for i in range(N_EVENTS, g.shape[0]):
                    g[i] = 1.0
    return impl


@njit(cache=True)
def _events_at(model, y, p, ev, switches):
    literally(model)
    g = np.empty(model_n_events(model, y))
    model_events(model, y, p, ev, g, switches)
    return g


def events_at(model: int, y, p, ev, switches: bool = True) -> np.ndarray:
    """The event vector g (module docstring) of model index ``model`` at one state, from
    Python, as the loops evaluate it (``switches``: model_events)."""
    return call(_events_at, model, np.ascontiguousarray(y, dtype=float), p, ev, switches)
