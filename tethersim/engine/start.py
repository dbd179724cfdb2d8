"""Where a run starts: the satellite's given initial state, or its own equilibrium.

A preset's start is the thesis's deployment: the balloon 28-29 m behind two 6 m
rubber-band tethers, which they reach by stretching ~5x.  A real fibre line
(a strain of a few per cent at break) cannot be there: started so, it pulls
with ~1e5 N, tumbles the boom and proves nothing.  :func:`start_satellite`
resolves simulate()'s ``start``:

``"given"``
    ``Satellite.initial`` (and ``initial_3d``), refused in one line when it is
    far from any physical state (:func:`check_given_start`).
``"equilibrium"``
    the steady configuration of the run's own satellite and model, rates zero
    (engine/steady.py; a free orbit starts at the equilibrium of the orbit held
    circular at its altitude).
``"auto"`` (the default)
    ``"equilibrium"`` when a tether is a real line (EA >= ``REAL_TETHER_EA``, 100 N:
    tethersim.model.materials.real_tethers), else ``"given"``; so the thesis's
    tethers (EA 0.004-0.06 N) start where the thesis started them, to the last bit.
    A real-line satellite without an equilibrium to find starts from its given state if that
    passes :func:`check_given_start` (the result's ``start`` says "given").

The resolved start becomes the run's satellite (its ``initial`` is the state the
run starts from), so a rerun (``estimate_error``) and the files record it.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.engine.steady import NoEquilibrium, steady_coordinates
from tethersim.model.registry import get_model
from tethersim.model.satellite import Satellite

START_MODES = ("auto", "given", "equilibrium")
REAL_LINE_ATOL = 1e-10  # the smallest atol a real line's run meets near rest (atol_floor)
HINT = "start at the satellite's equilibrium: start='equilibrium' (--start equilibrium)"


def check_start_mode(start) -> str:
    """``start`` if it is one of :data:`START_MODES`; else a one-line ValueError."""
    if not isinstance(start, str) or start not in START_MODES:
        raise ValueError(f"start = {start!r}: allowed values {', '.join(START_MODES)}")
    return start


def resolved_mode(sat: Satellite, start: str) -> str:
    """``"given"`` or ``"equilibrium"``: what ``start`` means for ``sat`` (module docstring)."""
    if check_start_mode(start) != "auto":
        return start
    from tethersim.model.materials import real_tethers
    return "equilibrium" if real_tethers(sat) else "given"


def start_satellite(sat: Satellite, model: str, start: str = "auto") -> tuple:
    """(satellite whose initial state is the run's start, the start used).

    Parameters
    ----------
    sat : Satellite
        The satellite.
    model : str
        The model the run integrates (circular or free orbit).
    start : {"auto", "given", "equilibrium"}
        Module docstring.

    Returns
    -------
    (Satellite, str)
        ``sat`` itself for a given start (checked), else a copy whose ``initial``
        (and for a 3-D model ``initial_3d``) is the equilibrium, rates zero; and
        ``"given"`` or ``"equilibrium"``.

    Raises
    ------
    ValueError
        A given start far from any physical state (:func:`check_given_start`), or
        no equilibrium to start from (:class:`tethersim.engine.steady.NoEquilibrium`).
    """
    mode = resolved_mode(sat, start)
    if mode == "given":
        check_given_start(sat, model)
        return sat, mode
    if start == "equilibrium":
        return equilibrium_satellite(sat, model), mode
    try:
        return equilibrium_satellite(sat, model), mode
    except NoEquilibrium as exc:
        # auto: a stiff satellite with no equilibrium to find (the thesis's damper on a
        # real line turns its rest into a sideways push) starts where it is given, if
        # that is a physical state; else the reason there is no equilibrium is the news
        try:
            check_given_start(sat, model)
        except ValueError:
            raise exc from None
        return sat, "given"


def start_run(sat: Satellite, model: str, start: str = "auto", beads=None) -> tuple:
    """(satellite, start used, model) of a run: :func:`start_satellite` for the model the
    satellite's lines hang from, then with ``beads`` (or ``sat.beads``) the chain over it,
    tethersim.model.beads (its beads start on the straight lines: inputs.initial_model_state).
    """
    from tethersim.model.bead_layout import check_beads
    from tethersim.model.registry import bead_model_name
    if beads is not None:
        sat = sat.replace(beads=check_beads(beads))
    elif sat.beads is not None:
        check_beads(sat.beads)
    sat, start = start_satellite(sat, model, start)
    return sat, start, model if sat.beads is None else bead_model_name(model, sat.beads)


def equilibrium_satellite(sat: Satellite, model: str) -> Satellite:
    """A copy of ``sat`` whose initial state is its equilibrium in ``model`` (rates zero).

    A free-orbit model starts at the equilibrium of its circular twin, the orbit
    held circular at ``sat.altitude``.
    """
    from tethersim.model.registry import FREE_VARIANTS
    circular = {v: k for k, v in FREE_VARIANTS.items()}.get(model, model)
    solved = sat if sat.orbit == "circular" else sat.replace(
        orbit="circular", eccentricity=0.0, j2=False)
    mdl = get_model(circular)
    names = mdl.state[:mdl.n_coordinates]
    if sat.E1 == 0 and sat.E2 == 0:
        raise NoEquilibrium("start = 'equilibrium' with E1 = E2 = 0 N/mm^2: no tether holds "
                            "the balloon, so there is no equilibrium to start from; use "
                            "start='given' (--start given)")
    guess = {"delta_x": sat.initial[0], "delta_y": sat.initial[1], "theta": 0.0}
    try:
        q, _ = steady_coordinates(solved, circular, np.array([guess.get(k, 0.0) for k in names]))
    except NoEquilibrium as exc:
        hint = ""
        if (sat.c1 or sat.c2) and "stretch rate" not in mdl.description:
            # the thesis's damper acts on the whole relative velocity: at rest in the orbit
            # frame it still drags the balloon sideways by c x omega x length
            hint = (f"; with c1 = {sat.c1:g}, c2 = {sat.c2:g} N s/m the thesis's damper "
                    f"(model {mdl.name}: relative velocity) also pushes the balloon across "
                    f"its lines as they turn with the orbit, which a stiff line may not "
                    f"balance: model 'objective-damper' damps the stretch rate only")
        raise NoEquilibrium(f"start = 'equilibrium': {exc}{hint}; start='given' (--start "
                            f"given) starts from the satellite's initial state") from None
    coords = dict(zip(names, (float(x) for x in q)))
    for k in ("theta", "psi"):  # the Satellite holds angles in (-pi, pi]
        if k in coords:
            coords[k] = math.remainder(coords[k], 2 * math.pi)
    initial = (coords["delta_x"], coords["delta_y"], coords["theta"], 0.0, 0.0, 0.0)
    start_3d = {k: coords[k] for k in ("delta_z", "phi", "psi") if k in coords}
    return sat.replace(initial=initial, initial_3d=start_3d, source=sat.source)


def check_given_start(sat: Satellite, model: str) -> None:
    """Refuse a given start far from any physical state, in one line.

    Far means: a tether's spring tension E (λ − l0) / l0 at or beyond its breaking
    load Fb (it would break at t = 0), or a real line (EA >= 100 N,
    tethersim.model.materials.real_tethers) stretched beyond the largest failure
    strain of the fibres in tethersim.model.materials.

    Raises
    ------
    ValueError
        Naming the field (``initial``), the tether, its tension or strain, the
        limit, and the equilibrium start.
    """
    from tethersim.engine.bodies import bodies_from_states
    from tethersim.model.inputs import initial_model_state
    from tethersim.model.materials import MAX_FAILURE_STRAIN, real_tethers

    stiff = real_tethers(sat)
    if not (sat.Fb1 or sat.Fb2 or stiff):
        return  # nothing to judge: the thesis's tethers start where the thesis put them
    y = initial_model_state(sat, model)
    off = bodies_from_states(sat, model, 0.0, y).offset
    where = (f"initial (delta_x, delta_y, theta) = ({sat.initial[0]:g} m, {sat.initial[1]:g} m, "
             f"{sat.initial[2]:g} rad)")
    for j, (E, l0, fb) in enumerate(((sat.E1, sat.l10, sat.Fb1), (sat.E2, sat.l20, sat.Fb2)), 1):
        lam = float(np.linalg.norm(off[j - 1] - off[2]))
        strain = max(lam - l0, 0.0) / l0
        tension = E * strain
        if fb and tension >= fb:
            raise ValueError(f"{where}: tether {j} starts stretched to {lam:.4g} m (l{j}0 = "
                             f"{l0:g} m), tension {tension:.4g} N, at or beyond its breaking "
                             f"load Fb{j} = {fb:g} N; {HINT}")
        if j in stiff and strain > MAX_FAILURE_STRAIN:
            raise ValueError(f"{where}: tether {j} starts stretched to {lam:.4g} m (l{j}0 = "
                             f"{l0:g} m), strain {100 * strain:.4g} %, beyond the "
                             f"{100 * MAX_FAILURE_STRAIN:.3g} % at which the most extensible "
                             f"fibre of tethersim.model.materials breaks; {HINT}")


def atol_floor(sat: Satellite) -> float:
    """The smallest atol a run of ``sat`` can meet near rest: ``REAL_LINE_ATOL`` for real
    lines (their force is known to its rounding level only, EA/l0 x λ x 1e-16, ~1e-11
    m/s² on the balloon: more than a smaller atol allows a step), else 0."""
    from tethersim.model.materials import real_tethers
    return REAL_LINE_ATOL if real_tethers(sat) else 0.0


def atol_hint(sat: Satellite, atol: float) -> str:
    """Why a run may exhaust its steps (appended to "too many steps"), or ""."""
    if atol >= atol_floor(sat):
        return ""
    return (f"; real lines near rest need atol >= {REAL_LINE_ATOL:g}, their force's rounding "
            f"level (atol=..., --atol; docs/tethers.md)")
