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
    passes :func:`check_given_start` (the result's ``start`` says "given"); one whose
    equilibrium the thesis's damper turned over is refused in one line naming the model
    whose damper is the line's loss (:func:`upright_or_refused`).

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
DEFAULT_ATOL = 1e-12  # the adaptive schemes' atol (default_atol)
REAL_LINE_ATOL = 1e-10  # the smallest atol a real line's run meets near rest (atol_floor)
NEWTON_ITERATIONS = 20  # chain_at_rest's most per stage (3 without progress end it sooner)
BEAD_LINE_ATOL = 1e-9  # the same with beads on the lines (docs/beads.md, "Running a chain")
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
        return upright_or_refused(sat, equilibrium_satellite(sat, model), model), mode
    except NoEquilibrium as exc:
        # auto: a stiff satellite with no equilibrium to find (the thesis's damper on a
        # real line turns its rest into a sideways push) starts where it is given, if
        # that is a physical state; else the reason there is no equilibrium is the news
        try:
            check_given_start(sat, model)
        except ValueError:
            raise exc from None
        return sat, "given"


def thesis_damper(model: str) -> bool:
    """Whether ``model``'s damper is the thesis's (on the whole relative velocity of a
    line's ends), not a Kelvin-Voigt damper on the line's stretch rate."""
    return "Kelvin-Voigt" not in get_model(model).description


def upright_or_refused(sat: Satellite, eq: Satellite, model: str) -> Satellite:
    """The auto start ``eq`` (the equilibrium of ``sat``), unless the thesis's damper
    turned its boom over.

    The thesis's damper acts on the whole relative velocity of a line's ends, which is
    not zero at rest (the formation turns with the orbit): on a real line its push
    across the line can turn the boom over at the equilibrium (docs/real-tethers.md).  A
    default start there would fly an inverted satellite without a word; one line says
    why and which model damps a line's material loss.  Only the damper's doing is
    refused: lines that rest turned over without their dampers too (a stiff line held
    far from the COM, docs/real-tethers.md "One line") start there.
    """
    theta = eq.initial[2]
    # turned over: more than 120° from upright; upright: within 60° (a boom along the
    # flow, θ near ±90°, is neither: a single stiff line's own rest, "One line")
    if not (thesis_damper(model) and (eq.c1 or eq.c2) and math.cos(theta) < -0.5):
        return eq
    try:  # the damper's doing only if the same lines rest upright without it
        undamped = equilibrium_satellite(sat.replace(c1=0.0, c2=0.0), model).initial[2]
    except NoEquilibrium:
        return eq
    if math.cos(undamped) > 0.5:
        raise ValueError(
            f"start = 'auto' on real lines: model {model}'s damper (the thesis's, on the whole "
            f"relative velocity) with c1 = {eq.c1:.4g}, c2 = {eq.c2:.4g} N s/m turns the boom "
            f"over at its equilibrium (θ = {theta:.4g} rad); model 'objective-damper' damps "
            f"the stretch rate, as a line's material loss does (docs/real-tethers.md); "
            f"simulate(start='equilibrium') (tethersim run --start equilibrium) starts "
            f"there anyway")
    return eq


def start_run(sat: Satellite, model: str, start: str = "auto", beads=None) -> tuple:
    """(satellite, start used, model, start state) of a run: :func:`start_satellite` for
    the model the satellite's lines hang from, then with ``beads`` (or ``sat.beads``) the
    chain over it, tethersim.model.beads: a given start puts its beads on the straight
    lines (inputs.initial_model_state), an equilibrium start at the chain's own
    equilibrium (:func:`chain_at_rest`), whose boom and balloon coordinates then become
    the satellite's ``initial``.
    """
    from tethersim.model.bead_layout import attachments_refused, check_beads, moved_attachments
    from tethersim.model.inputs import initial_model_state
    from tethersim.model.registry import BEAD_BASES, bead_model_name
    if beads is not None:
        sat = sat.replace(beads=check_beads(beads))
    elif sat.beads is not None:
        check_beads(sat.beads)
    moved = moved_attachments(sat)
    if moved and model not in BEAD_BASES:
        raise ValueError(attachments_refused(sat, model))
    if moved and sat.beads is None:  # lines held between the boom's ends: a chain's
        sat = sat.replace(beads=0)
    # the lines' equilibrium: massless, held at their points on the boom (a chain of no
    # beads where those are not the boom's ends), the beads' then from it
    hung = bead_model_name(model, 0) if moved else model
    sat, start = start_satellite(sat, hung, start)
    if sat.beads is None:
        return sat, start, model, initial_model_state(sat, model)
    model = bead_model_name(model, sat.beads)
    y = initial_model_state(sat, model)
    if start == "equilibrium" and sat.beads > 0:
        y = chain_at_rest(y, model, sat)
        sat = sat.replace(initial=(*(float(v) for v in y[:3]), 0.0, 0.0, 0.0),
                          source=sat.source)
    return sat, start, model, y


def chain_at_rest(y, model: str, sat: Satellite) -> np.ndarray:
    """The bead chain's equilibrium near state ``y``: every coordinate (boom, balloon,
    beads) where the chain's accelerations vanish at rest in L, rates zero.

    The massless lines' equilibrium with its beads on the straight lines is not one: the
    beads sag under their tidal load and the tension, and a stiff line started there rings
    at its transverse modes.  Newton's method on the accelerations, the beads moved along
    and across their line: a fibre segment is taut by ~1e-8 m, so a derivative taken with
    one step for all (scipy's ``root``) crosses its slack kink along the line or drowns in
    rounding across it.  Here central differences step 1000 x the rounding of a position
    along the line (and of the body coordinates), sqrt(ε) x the largest offset across it.
    Accepted when the largest acceleration left is at most 100 x the rounding level of the
    forces, ε x the largest offset x the stiffest segment's EA / (l_s m_b) (or ε r0 ω²):
    on a stiff line that level, 1e-7-1e-5 m/s², is all any solver can reach.  Not
    accepted: ``y`` (the straight chain), with a one-line warning.
    """
    from tethersim.model import bead_kernels
    from tethersim.model.bead_layout import NB
    from tethersim.model.inputs import parameter_vector
    from tethersim.model.registry import bead_split
    base, n = bead_split(model)
    p = parameter_vector(sat, model)
    rhs, nq = bead_kernels.kernels(base).rhs, y.size // 2
    rest, d, q0 = np.zeros(nq), np.empty_like(y), np.array(y[:nq], dtype=float)

    def acceleration(q):
        rhs(0.0, np.concatenate([q, rest]), p, d)
        return d[nq:].copy()
    # the coordinates Newton moves: δx, δy, θ, then per bead along / across its line
    v = dict(zip(get_model(base).parameters, p))  # SI: E1, E2 are EA [N]
    size, eps = float(np.max(np.abs(q0))), np.finfo(float).eps
    basis = np.eye(nq)
    at = {name: i for i, name in enumerate(get_model(model).state[:nq])}  # the layout's
    balloon = q0[[at["delta_x"], at["delta_y"]]]
    stiffest = 0.0
    for j, (E, l0, mt) in enumerate(((v["E1"], v["l10"], p[NB]), (v["E2"], v["l20"], p[NB + 1])), 1):
        stiffest = max(stiffest, E * (n + 1) ** 2 / (l0 * mt))  # EA / (l_s m_b) [1/s²]
        first = q0[[at[f"x_{j}_1"], at[f"y_{j}_1"]]]
        e = (balloon - first) / np.linalg.norm(balloon - first)  # the line's direction
        for k in range(1, n + 1):  # the bead's x, y turned to along, across its line
            xy = [at[f"x_{j}_{k}"], at[f"y_{j}_{k}"]]
            basis[np.ix_(xy, xy)] = [[e[0], -e[1]], [e[1], e[0]]]
    across = np.array([at[f"y_{j}_{k}"] for j in (1, 2) for k in range(1, n + 1)])
    steps = np.full(nq, 1e3 * eps * size)  # along a line, and the bodies' offsets
    steps[at["theta"]] /= max(v["a"], v["b"])  # rad: the boom ends move as much
    steps[across] = np.sqrt(eps) * size
    level = eps * max(size * stiffest, v["r0"] * v["omega"] ** 2)

    def local(x):  # the accelerations in the coordinates Newton moves
        return basis.T @ acceleration(q0 + basis @ x)
    # every coordinate, then across the lines alone: along a stiff line the rows are
    # rounding noise that can hide (in the largest row) a sag not yet balanced
    x = _newton(local, np.zeros(nq), steps, np.arange(nq))
    x = _newton(local, x, steps, across)
    left = float(np.max(np.abs(local(x))))
    if left <= 100 * level:
        return np.concatenate([q0 + basis @ x, rest])
    import warnings
    warnings.warn(f"start = 'equilibrium': the {n}-bead chain's equilibrium was not found "
                  f"(acceleration {left:.3g} m/s² left, {100 * level:.3g} allowed): its "
                  f"beads start on the straight lines", RuntimeWarning, stacklevel=4)
    return y


def _newton(f, x, steps, moved) -> np.ndarray:
    """Newton's method on the rows ``moved`` of f(x) = 0, moving those coordinates of x,
    central differences of ``steps``; the best x seen (largest of those rows) when no
    better in 3 iterations or after :data:`NEWTON_ITERATIONS`."""
    x = x.copy()
    r = f(x)[moved]
    best, stalled = (float(np.max(np.abs(r))), x.copy()), 0
    J = np.empty((moved.size, moved.size))
    for _ in range(NEWTON_ITERATIONS):
        if stalled == 3 or best[0] == 0.0:
            break
        for c, i in enumerate(moved):
            dx = np.zeros_like(x)
            dx[i] = steps[i]
            J[:, c] = (f(x + dx)[moved] - f(x - dx)[moved]) / (2 * steps[i])
        try:
            x[moved] -= np.linalg.solve(J, r)
        except np.linalg.LinAlgError:
            break
        r = f(x)[moved]
        if np.all(np.isfinite(r)) and np.max(np.abs(r)) < best[0]:
            best, stalled = (float(np.max(np.abs(r))), x.copy()), 0
        else:
            stalled += 1
    return best[1]


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
        if (sat.c1 or sat.c2) and thesis_damper(circular):
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
    from tethersim.model.bead_layout import attachment_points
    y = initial_model_state(sat.replace(s1=None, s2=None), model)
    bodies = bodies_from_states(sat, model, 0.0, y)
    off = bodies.offset
    holds = [s * bodies.attitude[:, 1] for s in attachment_points(sat)]  # on the boom axis
    where = (f"initial (delta_x, delta_y, theta) = ({sat.initial[0]:g} m, {sat.initial[1]:g} m, "
             f"{sat.initial[2]:g} rad)")
    for j, (E, l0, fb) in enumerate(((sat.E1, sat.l10, sat.Fb1), (sat.E2, sat.l20, sat.Fb2)), 1):
        lam = float(np.linalg.norm(holds[j - 1] - off[2]))
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
    """The smallest atol a run of ``sat`` can meet near rest: for real lines their force
    is known to its rounding level only (EA/l0 x λ x 1e-16): ~1e-11 m/s² on the balloon,
    ``REAL_LINE_ATOL``; ~1e-8 m/s² on sub-gram beads, ``BEAD_LINE_ATOL``; else 0."""
    from tethersim.model.materials import real_tethers
    if not real_tethers(sat):
        return 0.0
    return BEAD_LINE_ATOL if sat.beads else REAL_LINE_ATOL


def default_atol(sat: Satellite) -> float:
    """The adaptive schemes' atol when none is given: ``DEFAULT_ATOL``, at least
    :func:`atol_floor` (docs/tethers.md)."""
    return max(DEFAULT_ATOL, atol_floor(sat))


def atol_hint(sat: Satellite, atol: float) -> str:
    """Why a run may exhaust its steps (appended to "too many steps"), or ""."""
    if atol >= (floor := atol_floor(sat)):
        return ""
    lines = "real lines with beads" if sat.beads else "real lines"
    return (f"; {lines} near rest need atol >= {floor:g}, their force's rounding "
            f"level (atol=..., --atol; docs/tethers.md)")
