"""How the balloon reaches its lines: the deployment on real tethers (issue 21;
docs/real-tethers.md, "Deployment").

Every other run of docs/real-tethers.md starts at rest at the equilibrium.  A real
balloon gets there by a deployment, and on a line that barely stretches the end of it is
a snap.  This module starts the two ends of the range of deployments:

* :func:`released`: a **free release**.  The balloon is inflated beside the satellite
  and let go at rest, ``distance`` behind the COM, its lines slack.  Drag carries it
  back until the lines catch it.
* :func:`arrival`: the end of a **braked deployment**.  A deployer has paid the lines
  out under tension and stops them at full length.  The balloon is at its trim point,
  moving away from the COM at ``speed``, and the lines must stop it.

The deployer itself (the reel, its brake, the lines' paying out) is not modelled.
:func:`deploy` runs either start on the implicit scheme and reads what a tether
engineer asks of it (:class:`Deployment`): the first catch's tension, the largest
tension and its safety factor, how far the boom pitches, whether it turns over and which
way up it ends.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tethersim.analysis.tethers import line_vectors
from tethersim.engine.result import SimResult
from tethersim.engine.simulate import simulate
from tethersim.engine.start import equilibrium_satellite, upright_or_refused
from tethersim.experiments.real_tethers import REAL_MODEL, RUN_TOLERANCES
from tethersim.model.registry import MODELS
from tethersim.model.satellite import Satellite

#: s: the output grid of :func:`deploy`.  A catch lasts half the balloon's bounce on its
#: lines, π √(m3 / k): 41 ms on both of SatI's 29 m lines of 1 mm Dyneema, 57 ms on one;
#: 2 ms samples read its peak to within 1 − cos(π 1 ms / 41 ms) = 0.3 %.
SAMPLE = 0.002
MAX_SAMPLES = 5_000_000  # a deployment's output grid: 400 MB of states
RELEASE = 3.0  # m behind the COM: the default free release, clear of SatI's boom
MAX_SPEED = 100.0  # m/s: an arrival speed beyond any deployer (a free release reaches ~3)
#: the models a deployment runs: planar, circular orbit (their state is δx, δy, θ and rates)
PLANAR = tuple(m.name for m in MODELS if m.geometry == "planar" and m.orbit == "circular")
SETTLE_PERIODS = 50.0  # orbits of :func:`settle`: the thesis's run length (p. 5-7)
#: the deployment table's columns (key, header with unit): tethersim.output.tables.write_table
COLUMNS = (("start", "start"), ("value", "arrival speed [m/s] or release distance [m]"),
           ("status", "status"),
           ("first_catch", "first catch [s]"), ("catch_speed", "speed at the catch [m/s]"),
           ("catch_duration", "first catch's duration [s]"),
           ("first_peak", "first catch's peak tension [N]"),
           ("spin", "pitch rate after the first catch [rad/s]"), ("peak", "largest tension [N]"),
           ("safety_factor", "safety factor"),
           ("catches", "catches after the first"),
           ("excursion", "pitch excursion [rad]"), ("turned_over", "turned over"),
           ("inverted", "ends the other way up"), ("clearance", "clearance to the boom [m]"),
           ("settled_class", "class after the settling run"),
           ("settling_h", "settling time [h]"))
#: the :class:`Deployment` fields of a row (:data:`COLUMNS` between the start and the settling)
RECORD = tuple(k for k, _ in COLUMNS[2:-2])


def line_lengths(sat: Satellite, delta_x: float, delta_y: float, theta: float) -> tuple:
    """Distances [m] from the tip-mass and the bus to the balloon at (δx, δy) with the
    boom at pitch θ (the lines' λ1, λ2 when they hold the boom ends, Eqs 3.10-3.11)."""
    s, c = math.sin(theta), math.cos(theta)
    return (math.hypot(sat.b * s - delta_x, sat.b * c - delta_y),
            math.hypot(-sat.a * s - delta_x, -sat.a * c - delta_y))


def balloon_radius(sat: Satellite) -> float:
    """√(A3 / π) [m]: the radius of a spherical balloon of frontal area A3."""
    return math.sqrt(sat.A3 / math.pi)


def boom_distance(sat: Satellite, delta_x, delta_y, theta):
    """Distance [m] from the balloon's centre at (δx, δy) to the boom at pitch θ: the
    segment from the bus (−a) to the tip-mass (+b) along (sin θ, cos θ).  Floats or
    arrays."""
    s, c = np.sin(theta), np.cos(theta)
    along = np.clip(delta_x * s + delta_y * c, -sat.a, sat.b)
    return np.hypot(delta_x - along * s, delta_y - along * c)


def released(sat: Satellite, distance: float, offset: float = 0.0,
             model: str = REAL_MODEL) -> Satellite:
    """``sat`` starting as a free release: the balloon at rest at (δx, δy) =
    (``distance``, ``offset``) [m] from the COM, the boom at its trim, at rest.

    Raises
    ------
    ValueError
        When the balloon would not start clear of the boom (its radius,
        :func:`balloon_radius`: the model's bodies are points and know no contact) or
        would start outside its lines' reach (a line already taut): the allowed
        distances are named.
    """
    check_model(sat, model)
    trim = upright_or_refused(sat, equilibrium_satellite(sat, model), model)
    theta = trim.initial[2]
    lam = line_lengths(sat, distance, offset, theta)
    radius = balloon_radius(sat)
    clear = distance > 0 and boom_distance(sat, distance, offset, theta) > radius
    if not (clear and lam[0] < sat.l10 and lam[1] < sat.l20):
        beyond = max(offset - sat.b, -sat.a - offset, 0.0)  # past an end of the boom
        low = math.sqrt(max(radius ** 2 - beyond ** 2, 0.0))
        reach = min(math.sqrt(max(sat.l10 ** 2 - (sat.b - offset) ** 2, 0.0)),
                    math.sqrt(max(sat.l20 ** 2 - (sat.a + offset) ** 2, 0.0)))
        allowed = (f"{low:.3g} < distance < {reach:.3g} m" if reach > low else
                   "no distance gives both")
        raise ValueError(f"release distance = {distance:g} m: a free release starts with "
                         f"the balloon (radius {radius:.3g} m) clear of the boom and both "
                         f"lines slack, {allowed} at offset {offset:g} m (lines "
                         f"{sat.l10:g} and {sat.l20:g} m)")
    return trim.replace(initial=(float(distance), float(offset), theta, 0.0, 0.0, 0.0))


def arrival(sat: Satellite, speed: float, model: str = REAL_MODEL) -> Satellite:
    """``sat`` starting at the end of a braked deployment: the balloon at its trim point,
    moving away from the COM at ``speed`` [m/s]; the boom at its trim, at rest.

    Raises
    ------
    ValueError
        For a speed outside 0 ... :data:`MAX_SPEED`.
    """
    if not 0.0 <= speed <= MAX_SPEED:
        raise ValueError(f"arrival speed = {speed:g} m/s: allowed 0 to {MAX_SPEED:g} m/s "
                         f"(a free release reaches a few m/s)")
    check_model(sat, model)
    trim = upright_or_refused(sat, equilibrium_satellite(sat, model), model)
    dx, dy, theta = trim.initial[:3]
    r = math.hypot(dx, dy)
    return trim.replace(initial=(dx, dy, theta, speed * dx / r, speed * dy / r, 0.0))


@dataclass(frozen=True)
class Deployment:
    """What a deployment asks of the lines and the boom (SI).

    Attributes
    ----------
    result : SimResult or None
        The run, on a :data:`SAMPLE` grid (None where a caller dropped it).
    status : str
        The run's end: ``ok``; ``tether-broke`` when a catch pulled a line past its
        breaking load (at the located time); any other status (a failed run) leaves
        every figure below NaN (False, 0).
    first_catch : float
        Time [s] the lines first pull (0 for an arrival: they are taut at the start).
    catch_speed : float
        The balloon's speed [m/s] relative to the COM as the lines first pull (the last
        sample before the catch; an arrival's speed).
    catch_duration : float
        How long [s] the first catch pulled, to the grid's sample.
    first_peak : float
        Largest tension [N] of either line in the first catch.
    spin : float
        The boom's pitch rate |dθ/dt| [rad/s] as the first catch ends.
    peak : float
        Largest tension [N] of either line over the run.
    safety_factor : float
        The smaller of the lines' breaking load over their largest tension (NaN when
        they never break).
    catches : int
        Times the bridle caught the balloon again after the first catch, seen on the
        grid: the rebounds, and the chatter of a balloon coming to rest on its lines (a
        count that moves with the last bits of the arithmetic).
    excursion : float
        Largest |θ − θ(0)| [rad].
    turned_over : bool
        Whether the boom passed a quarter turn from where it started (|θ − θ(0)| > π/2).
    inverted : bool
        Whether the boom ends the run the other way up from its start.
    clearance : float
        The smallest gap [m] between the balloon (a sphere of :func:`balloon_radius`)
        and the boom after the first catch; at or below 0 they touched, which the
        model, whose bodies are points, does not represent.
    """

    result: SimResult | None
    status: str
    first_catch: float
    catch_speed: float
    catch_duration: float
    first_peak: float
    spin: float
    peak: float
    safety_factor: float
    catches: int
    excursion: float
    turned_over: bool
    inverted: bool
    clearance: float


def check_model(sat: Satellite, model: str) -> None:
    """Refuse a model or satellite whose state is not the planar (δx, δy, θ) one that
    :func:`deploy` reads (one line naming the allowed models)."""
    chain = sat.beads is not None or sat.s1 is not None or sat.s2 is not None
    if model not in PLANAR or sat.orbit != "circular" or chain:
        raise ValueError(f"model = {model!r}, orbit = {sat.orbit!r}: a deployment runs the "
                         f"planar circular-orbit models ({', '.join(PLANAR)}) on a circular "
                         f"orbit, lines held at the boom's ends, no bead chains")


def check_sample(sat: Satellite, sample: float) -> None:
    """Refuse a grid too coarse to read a catch's peak: ``sample`` [s] at most a tenth
    of the shortest catch, π √(m3 / k) with both lines pulling (k = Σ E_j / l_j0)."""
    k = sat.E1 / sat.l10 + sat.E2 / sat.l20
    catch = math.pi * math.sqrt(sat.m3 / k) if k > 0 else math.inf
    if not 0 < sample <= catch / 10:
        raise ValueError(f"sample = {sample:g} s: a catch on these lines lasts {catch:.3g} s "
                         f"(π √(m3 / k)); reading its peak takes 0 < sample <= "
                         f"{catch / 10:.3g} s")


def samples(periods: float, period: float, sample: float) -> int:
    """Output samples of a :func:`deploy` run of ``periods`` orbits of ``period`` [s] every
    ``sample`` [s]; ValueError naming the sample and the allowed count."""
    n = periods * period / sample if sample > 0 else math.inf
    if not 1 <= n <= MAX_SAMPLES:
        raise ValueError(f"sample = {sample:g} s over {periods:g} orbits: {n:.3g} samples; "
                         f"allowed 1 to {MAX_SAMPLES:g} (a longer run takes a coarser sample)")
    return round(n)


def _finished(res: SimResult) -> SimResult:
    """The run, unless Ctrl-C stopped it: a truncated run is not a deployment's answer."""
    if res.status == "interrupted":
        raise KeyboardInterrupt
    return res


def deploy(start: Satellite, periods: float = 1.0, sample: float = SAMPLE,
           model: str = REAL_MODEL, rtol: float = RUN_TOLERANCES["rtol"]) -> Deployment:
    """Run a deployment start (:func:`released`, :func:`arrival`) for ``periods`` orbits
    on the implicit scheme (Radau IIA at ``rtol`` and :data:`RUN_TOLERANCES`'s atol),
    sampled every ``sample`` seconds (:func:`check_sample`), and read its
    :class:`Deployment`.

    Raises
    ------
    KeyboardInterrupt
        When Ctrl-C stopped the run (it is not recorded).
    """
    check_model(start, model)
    check_sample(start, sample)
    res = _finished(simulate(start, periods=periods, method="implicit", model=model,
                             progress=False, start="given", rtol=rtol,
                             atol=RUN_TOLERANCES["atol"],
                             steps=samples(periods, start.period, sample)))
    if res.status not in ("ok", "tether-broke"):
        return Deployment(result=res, **(dict.fromkeys(RECORD, math.nan) | {
            "status": res.status, "catches": 0, "turned_over": False, "inverted": False}))
    y = res.model_states
    tension = res.tether_tensions()
    pull = tension.max(axis=1)
    taut = pull > 0
    caught = bool(taut.any())
    first = int(np.argmax(taut)) if caught else len(pull)
    end = first + int(np.argmin(taut[first:])) if not taut[first:].all() else len(pull) - 1
    factors = [fb / tension[:, j].max() for j, fb in enumerate((start.Fb1, start.Fb2))
               if fb > 0 and tension[:, j].max() > 0]
    turn = y[:, 2] - y[0, 2]
    return Deployment(
        result=res,
        status=res.status,
        first_catch=float(res.t[first]) if caught else math.nan,
        catch_speed=float(np.hypot(*y[max(first - 1, 0), 3:5])) if caught else math.nan,
        catch_duration=float(res.t[end] - res.t[first]) if caught else math.nan,
        first_peak=float(pull[first:end + 1].max()) if caught else 0.0,
        spin=float(abs(y[end, 5])) if caught else math.nan,
        peak=float(pull.max()),
        safety_factor=min(factors) if factors else math.nan,
        catches=int(np.count_nonzero(taut[1:] & ~taut[:-1])) - (1 if first > 0 else 0)
        if caught else 0,
        excursion=float(np.abs(turn).max()),
        turned_over=bool((np.cos(turn) < 0).any()),
        inverted=bool(np.cos(turn[-1]) < 0),
        clearance=float(boom_distance(start, y[first:, 0], y[first:, 1], y[first:, 2]).min()
                        - balloon_radius(start)) if caught else math.nan)


def pull_along_trim(result: SimResult, start: Satellite) -> np.ndarray:
    """Both lines' pull [N] on the balloon projected on the start's trim line u (from the
    COM to the balloon), at each sample of ``result``: the quantity of
    :func:`catch_closed_form`."""
    y = result.model_states
    tension = result.tether_tensions()
    u = np.array(start.initial[:2]) / math.hypot(*start.initial[:2])
    pull = np.zeros(len(y))
    for j, d in enumerate(line_vectors(start, y)):
        pull += tension[:, j] * ((d / np.linalg.norm(d, axis=1)[:, None]) @ u)
    return pull


def catch_closed_form(start: Satellite) -> float:
    """The first catch's peak pull [N] along the trim line u for an :func:`arrival`
    start, from the bridle's linear modes.

    Taut lines are springs k_j = E_j / l_j0 [N/m] along their directions e_j, so the
    balloon (mass m3 against the satellite's m1 + m2: reduced mass μ) sits in a 2-D
    spring of stiffness K = Σ k_j e_j e_jᵀ.  Started at the trim with velocity v u, its
    displacement is Σ_i (φ_i · u) (v / ω_i) sin(ω_i t) φ_i over the modes K φ_i =
    μ ω_i² φ_i, and the pull along u is D + v μ Σ_i (φ_i · u)² ω_i sin(ω_i t), with D the
    lines' pull along u at the start (it holds the drag).  For one mode this is the
    energy balance's D + v √(k μ).  Left out: the dampers (set c = 0 to compare), the
    boom's turn (on SatI the run's peak is a few tenths of a percent lower,
    docs/real-tethers.md), the gravity gradient and Coriolis over the catch's tens of
    milliseconds.

    Raises
    ------
    ValueError
        When no line is taut at the start (the closed form is of a catch on taut lines).
    """
    dx, dy, theta, vx, vy, _ = start.initial
    v = math.hypot(vx, vy)
    u = np.array([dx, dy]) / math.hypot(dx, dy)
    s, c = math.sin(theta), math.cos(theta)
    stiffness, pull = np.zeros((2, 2)), 0.0
    for E, l0, p in ((start.E1, start.l10, (start.b * s, start.b * c)),
                     (start.E2, start.l20, (-start.a * s, -start.a * c))):
        d = np.array([dx - p[0], dy - p[1]])
        lam = float(np.linalg.norm(d))
        if lam <= l0 or E == 0:
            continue  # a slack line is no spring
        e = d / lam
        stiffness += E / l0 * np.outer(e, e)
        pull += E * (lam - l0) / l0 * float(e @ u)
    if not stiffness.any():
        raise ValueError("catch_closed_form: no line is taut at the start; the closed form "
                         "is of a catch on taut lines (an arrival)")
    mu = start.m3 * (start.m1 + start.m2) / (start.m3 + start.m1 + start.m2)
    k, phi = np.linalg.eigh(stiffness)
    held = k > 1e-12 * k.max()  # one taut line holds along itself only: one mode
    omega, share = np.sqrt(k[held] / mu), (phi[:, held].T @ u) ** 2
    # the catch ends at the pull's first maximum (the lines then slacken): it lies within
    # the slower mode's half period; samples 1e-4 of it apart read it to ~1e-7
    t = np.linspace(0.0, math.pi / omega.min(), 10001)
    along = pull + v * mu * (share * omega * np.sin(np.outer(t, omega))).sum(1)
    falls = np.flatnonzero(np.diff(along) < 0)
    return float(along[falls[0]] if falls.size else along[-1])


def settle(start: Satellite, periods: float = SETTLE_PERIODS, model: str = REAL_MODEL,
           rtol: float = RUN_TOLERANCES["rtol"]) -> dict:
    """Where a deployment start settles: ``periods`` orbits on the implicit scheme (as
    :func:`deploy`), judged by the thesis's criterion on the metrics grid
    (tethersim.analysis.outcome).

    Returns
    -------
    dict
        ``settled_class`` (stable, offset, upside_down, tumbling, ...: docs/metrics.md),
        ``settling_h``, the last time [h] θ left the ±0.05 rad band about its steady
        value (NaN when it never settled), and ``theta_ss`` [rad].
    """
    from tethersim.analysis.outcome import outcome
    check_model(start, model)
    out = outcome(_finished(simulate(start, periods=periods, method="implicit", model=model,
                                     progress=False, start="given", rtol=rtol,
                                     atol=RUN_TOLERANCES["atol"])), forces=False)
    m = out.metrics
    return {"settled_class": out.class_name,
            "settling_h": m.settling_time / 3600 if m is not None else math.nan,
            "theta_ss": m.steady_state_pitch if m is not None else math.nan}


def starts(sat: Satellite, speeds=(), releases=(), model: str = REAL_MODEL) -> list:
    """[(kind, value, start)]: an :func:`arrival` per speed [m/s], then a
    :func:`released` per distance [m] (each checked before anything runs)."""
    return ([("arrival", float(v), arrival(sat, v, model)) for v in speeds]
            + [("release", float(d), released(sat, d, model=model)) for d in releases])


def row(kind: str, value: float, dep: Deployment, settled: dict | None = None) -> dict:
    """One row of the deployment table (:data:`COLUMNS`): the catch's :class:`Deployment`
    and, when given, its :func:`settle` (else blank)."""
    settled = settled or {"settled_class": "", "settling_h": math.nan}
    return {"start": kind, "value": value, **{k: getattr(dep, k) for k in RECORD},
            "settled_class": settled["settled_class"], "settling_h": settled["settling_h"]}
