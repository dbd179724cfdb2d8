"""After the balloon is lost: the boom alone, released from the state where it was lost.

A free-orbit run ends ``left-domain`` when a tether passes ``MAX_STRETCH`` times its
rest length or the balloon its reach (engine/domain.py): no elastic tether survives
that, so the tether is taken to **break there and release the balloon**.  What is
left is the gravity-gradient boom (tip mass and bus), still in orbit and still
decaying: :func:`continue_released` continues the run from its last state with the
tethers and the balloon off, until the boom's COM re-enters (or a time cap), so that
``feasibility`` can report the re-entry after the balloon was lost (docs/feasibility.md).

"Off" within the same model and state vector: the tether moduli and dampers zero
(no tether force on either body), the balloon's area and mass the smallest the
parameter table allows (1 mm^2, 1 g: its drag and its inertia in the coupled equations
are then negligible against the boom's).  The balloon's coordinates keep being
integrated as those of a force-free point and may drift anywhere: only the re-entry
check applies to the continuation, not the balloon's reach or the tether stretch.
The reference point (r, ν) is the boom's COM, so the orbit that is continued is the
boom's own.
"""
from __future__ import annotations

import math
from datetime import datetime, timedelta

from tethersim.engine.result import SimResult
from tethersim.engine.simulate import SAMPLES_PER_PERIOD, _run_adaptive
from tethersim.model.params import PARAMETERS
from tethersim.model.satellite import Satellite


def released(sat: Satellite, after_s: float = 0.0) -> Satellite:
    """The satellite with its balloon released: tethers off, the balloon's drag and mass
    at the table's minimum; the epoch moved on by ``after_s`` [s] (MSIS air is
    time-dependent), to the whole second (as an epoch is given)."""
    epoch = datetime.fromisoformat(sat.epoch) + timedelta(seconds=after_s)
    return sat.replace(E1=0.0, E2=0.0, c1=0.0, c2=0.0, A3=PARAMETERS["A3"].low,
                       m3=PARAMETERS["m3"].low, epoch=epoch.isoformat(timespec="seconds"))


def continue_released(res: SimResult, max_time_s: float) -> tuple:
    """Continue a free-orbit run that left the domain with the balloon released.

    Parameters
    ----------
    res : SimResult
        A free-orbit run whose status is ``"left-domain"`` (its last sample is
        the located state where the balloon was lost).
    max_time_s : float
        Cap on the continuation [s], counted from the start of ``res``.

    Returns
    -------
    (float or None, SimResult)
        When the boom's COM re-entered [s from the start of ``res``] (None when it
        had not by ``max_time_s``), and the continuation (its times from 0 at the
        release).

    Raises
    ------
    ValueError
        ``res`` is not a free-orbit run that left the domain, or the cap is not
        after its end.
    """
    if res.layout.orbit != "free" or res.status != "left-domain":
        raise ValueError(f"continue_released: needs a free-orbit run that left the domain, "
                         f"got model {res.model} with status {res.status!r}")
    t_lost = float(res.t[-1])
    if not max_time_s > t_lost:
        raise ValueError(f"max_time_s = {max_time_s!r}: must be after the release at "
                         f"{t_lost:.6g} s")
    sat = released(res.satellite, t_lost)
    periods = (max_time_s - t_lost) / sat.period
    n_out = max(2, math.ceil(SAMPLES_PER_PERIOD * periods))
    rtol = res.rtol if res.rtol is not None else 1e-10
    atol = res.atol if res.atol is not None else 1e-12
    # the loop stops itself at the re-entry, its only stopping event here (module docstring)
    run = _run_adaptive(sat, periods, n_out, res.model, rtol, atol, res.locate_switches,
                        False, start=res.states[-1], stops=("re-entry",))
    if run.status != "re-entered":
        return None, run
    return t_lost + run.reentry_time, run
