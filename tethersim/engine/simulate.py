"""simulate(): the driver that runs an integrator on a satellite and returns a SimResult.

Methods: "adaptive" (DOP853, error controlled, switches located; the default
for analysis), "rk4" (fixed step as in thesis Eqs 4.1-4.5; with
``locate_switches=False``, the default for RK4, it is the thesis's scheme and
the result is labelled faithful) and "implicit" (Radau IIA of order 5, error
controlled, switches located: for stiff, real tethers, docs/tethers.md).  All run their
whole loop in numba, in chunks so that a progress bar can be shown and Ctrl-C keeps what
finished; all locate the model's stopping limits (engine/events.py) in the loop and end a
run that reaches one just past it: its last sample is the located state.
"""
from __future__ import annotations

import math
import time
import warnings
from dataclasses import replace

import numpy as np
from tqdm.auto import tqdm

from tethersim.engine.arguments import (
    ATOL_RANGE,
    MIN_PERIODS,
    RTOL_RANGE,
    check_positive,
    check_range,
    check_scheme,
)
from tethersim.engine.domain import event_message
from tethersim.engine.events import EVENTS, STOPS, event_parameters
from tethersim.engine.guards import step_budget
from tethersim.engine.integrators.dop853 import STATUS_EVENT, STATUS_OK, dop853_run
from tethersim.engine.integrators.radau import N_COUNTERS as RADAU_COUNTERS
from tethersim.engine.integrators.radau import carry_size, radau_run
from tethersim.engine.integrators.rk4 import STATUS_EVENT as RK4_EVENT
from tethersim.engine.integrators.rk4 import rk4_run
from tethersim.engine.integrators.select import specialised
from tethersim.engine.linearise import rk4_amplification
from tethersim.engine.progress import advance as _advance
from tethersim.engine.progress import progress_bar
from tethersim.engine.result import SimResult
from tethersim.engine.start import atol_floor, atol_hint, check_start_mode, default_atol, start_run
from tethersim.model.inputs import air_vector, initial_model_state, parameter_vector
from tethersim.model.registry import DEFAULT_MODEL, model_for_orbit, model_index
from tethersim.model.satellite import Satellite

METHODS = ("adaptive", "rk4", "implicit")
STEPS_PER_PERIOD = 300  # thesis default: 1500 steps for 5 periods (p. 5-1)
FAITHFUL_STEPS_PER_PERIOD = 200  # thesis chapter 5 runs: 50 periods in 10,000 steps, 26.55 s (p. 5-7)
SAMPLES_PER_PERIOD = 200  # adaptive output grid when no steps are given
# metrics grid: 26.5 s at 200 km, below half the fastest tether period (~70 s) and far
# below the pitch libration's (~3100 s); the output grid is refined to at least this
METRIC_SAMPLES_PER_PERIOD = 200
CHUNKS = 100  # at least this many pauses in a long run: the progress bar's granularity
# The compiled loops see neither Ctrl-C nor the bar: Python does, between two calls.  A
# call lasts at most about PAUSE_S of wall time, whatever the run's length (a 50,000-orbit
# run used to pause every 500 orbits), so Ctrl-C stops a run within a fraction of a second.
PAUSE_S = 0.2
# RK4 pauses every RK4_PAUSE_STEPS steps (~0.1-0.25 s on one core for the planar to the
# 3-D free-orbit loops), with or without a bar: a fixed count, so the pauses are the same
# on every machine (the step times (k0 + k) h do not depend on them either)
RK4_PAUSE_STEPS = 50_000
# a DOP853 run whose first call projects a total under this finishes in one more call
# (its bar, delayed by a second, would never show)
QUICK_RUN_S = 0.5


class RK4StepWarning(UserWarning):
    """The RK4 step exceeds what the linearised system supports."""


def _kernel_args(sat: Satellite, model: str, duration: float) -> tuple:
    """(model index, air vector): the compiled loop is chosen by the first."""
    return model_index(model), air_vector(sat, duration)


def simulate(sat: Satellite, periods: float = 5.0, steps: int | None = None,
             method: str = "adaptive", model: str = DEFAULT_MODEL, *,
             rtol: float = 1e-10, atol: float | None = None, locate_switches: bool | None = None,
             samples: int | None = None, check: bool = False,
             progress: bool | None = None, step_warning: bool = True,
             start: str = "auto", beads: int | None = None) -> SimResult:
    """Integrate a satellite for ``periods`` orbits with one model.

    Parameters
    ----------
    sat : Satellite
        The satellite (``load_preset``, ``load``, ``Satellite.replace``).
    periods : float, optional
        Run length in orbital periods (default 5).
    steps : int, optional
        RK4: the number of steps (step = periods x period / steps; default 300
        per orbit).  Adaptive: the number of output samples, unless ``samples``
        is given (default 200 per orbit).
    method : {"adaptive", "rk4", "implicit"}, optional
        DOP853 with error control and taut/slack switch location (default),
        the thesis's fixed-step RK4 (Eqs 4.1-4.5), or Radau IIA (order 5,
        L-stable, error controlled, switches located) for stiff tethers.
    model : str, optional
        Any name in ``tethersim.MODELS`` (default ``"derived"``).
    rtol, atol : float, optional
        Adaptive tolerances (default 1e-10; 1e-12, for real lines their force's rounding
        floor at rest, tethersim.engine.start.atol_floor: an atol given is run as given).
    locate_switches : bool, optional
        Land steps on taut/slack switches (default: True adaptive, False RK4, as
        the thesis).
    samples : int, optional
        Adaptive output samples.  Metrics use a grid of at least 200 per orbit
        whatever this is (``SimResult.fine_t``).
    check : bool, optional
        Also estimate the error of the final state by a finer rerun (RK4 at half
        the step, adaptive at rtol/100); off by default (one integration, as
        scipy's ``solve_ivp``); ``SimResult.estimate_error()`` does it on demand.
    progress : bool or None, optional
        Progress bar: None shows one for runs over a second, False never (the
        run is then one compiled call; Ctrl-C is seen when it ends).
    step_warning : bool, optional
        RK4: warn (``RK4StepWarning``) when the step exceeds what the
        linearised system supports.
    start : {"auto", "given", "equilibrium"}, optional
        The satellite's ``initial`` state, its equilibrium in this model (rates
        zero), or (default) the equilibrium for real lines (EA >= 100 N), else the
        given state; a given state far from any physical one is refused
        (tethersim.engine.start).  The result's ``satellite.initial`` is where
        the run started, ``start`` says which.
    beads : int, optional
        Each tether a chain of 0-64 beads (``sat.beads``; line masses ``sat.mt1``,
        ``sat.mt2``; docs/beads.md): on the straight lines of a given start, at the
        chain's own equilibrium for an equilibrium start (engine/start.py).

    Returns
    -------
    SimResult
        The samples and counters.  ``status`` is ``"ok"``, ``"diverged"``,
        ``"failed"``, ``"interrupted"`` (Ctrl-C: everything finished is kept),
        ``"re-entered"`` or ``"left-domain"`` (a stopping limit of
        tethersim.engine.events, located in the loop: the run ends just past it,
        its last sample the located state; ``event`` and ``event_time`` say
        which and when).

    Raises
    ------
    ValueError
        A bad argument, with its name and allowed range.
    tethersim.engine.guards.SizeLimitError
        An output that would exceed the memory limit (TETHERSIM_MAX_OUTPUT_BYTES).

    Examples
    --------
    >>> import tethersim as ts
    >>> res = ts.simulate(ts.load_preset("satI"), periods=1, progress=False)
    >>> res.status, res.t.size
    ('ok', 201)
    """
    # refuse an output that would not fit, before allocating anything
    from tethersim.engine.guards import check_simulation
    check_simulation(periods, steps, method, samples, check)
    if not isinstance(sat, Satellite):
        raise TypeError(f"sat must be a tethersim Satellite (load_preset/load), got {type(sat).__name__}")
    periods = check_positive("periods", periods)
    if periods < MIN_PERIODS:
        raise ValueError(f"periods = {periods!r}: allowed range >= {MIN_PERIODS:g} orbit (a "
                         f"shorter run has too few steps to integrate)")
    if locate_switches is not None and not isinstance(locate_switches, (bool, np.bool_)):
        raise TypeError(f"locate_switches = {locate_switches!r}: must be True, False or None "
                        f"(the method's default)")
    if method not in METHODS:
        raise ValueError(f"method = {method!r}: allowed values {', '.join(METHODS)}")
    check_start_mode(start)
    check_scheme(sat, method)
    # the run's own satellite (its beads the chain's; orbit = "free": the model's free
    # twin), start mode, model and start state (engine/start.py)
    sat, start, model, y0 = start_run(sat, model_for_orbit(model, sat.orbit), start, beads)
    if method == "rk4":
        steps = check_positive("steps", steps if steps is not None
                                else max(1, round(STEPS_PER_PERIOD * periods)), integer=True)
        locate = False if locate_switches is None else bool(locate_switches)
        run = _run_rk4(sat, periods, steps, model, locate, progress, step_warning, y0)
    else:
        rtol = check_range("rtol", rtol, RTOL_RANGE)
        atol = check_range("atol", default_atol(sat) if atol is None else atol, ATOL_RANGE)
        if samples is not None:
            n_out = check_positive("samples", samples, integer=True)
        elif steps is not None:
            n_out = check_positive("steps", steps, integer=True)
        else:
            n_out = max(2, round(SAMPLES_PER_PERIOD * periods))
        locate = True if locate_switches is None else bool(locate_switches)
        # the metrics are computed on a grid fine enough for the pitch and tether modes
        # (METRIC_SAMPLES_PER_PERIOD), whatever output the caller asked for: the output is
        # every refine-th sample of it, exactly the grid asked for (docs/metrics.md)
        refine = max(1, math.ceil(METRIC_SAMPLES_PER_PERIOD * periods / n_out))
        run = _run_adaptive(sat, periods, n_out, model, rtol, atol, locate, progress, refine,
                            start=y0, scheme=method)
    run = replace(run, start=start) if start != "given" else run
    return estimate_error(run) if check else run


def _stopped(sat, slot: int, t: float) -> tuple:
    """(status, message, other SimResult fields) of a run stopped by stopping event
    ``slot`` (engine/events.py) at time t."""
    event = EVENTS[slot]
    return (event.status, event_message(sat, event.name, t),
            dict(event=event.name, event_time=t,
                 reentry_time=t if event.name == "re-entry" else None))


def estimate_error(run: SimResult) -> SimResult:
    """The run with ``error_estimate`` set from a finer rerun (SimResult.estimate_error).

    Parameters
    ----------
    run : SimResult
        A finished run of :func:`simulate`.

    Returns
    -------
    SimResult
        A copy of ``run`` whose error_estimate holds |final state - final state
        of the rerun| in every generalized coordinate of the model, in its
        layout order (``SimResult.errors`` names them): RK4 reruns at half the
        step, the adaptive method at rtol/100 and atol/100 (real lines: at least the
        atol their force's rounding allows, tethersim.engine.start.atol_floor).
        ``run`` itself (unchanged) when it did not end with status "ok", when the
        rerun fails, or when it has no record of its length (``periods``).
    """
    if run.status != "ok" or run.periods is None:
        return run
    y0 = run.states[0]  # where the run started (a bead chain: at its own equilibrium)
    if run.method == "rk4":
        fine = _run_rk4(run.satellite, run.periods, 2 * run.n_accepted, run.model,
                        run.locate_switches, False, False, y0)
    else:
        fine = _run_adaptive(run.satellite, run.periods, run.t.size - 1, run.model,
                             run.rtol / 100, max(run.atol / 100, atol_floor(run.satellite)),
                             run.locate_switches, False, start=y0, scheme=run.method)
    return _with_error(run, fine)


def _with_error(run: SimResult, fine: SimResult) -> SimResult:
    if fine.status != "ok":  # no estimate from a rerun that failed
        return run
    # every generalized coordinate (the 3-D layout's θ is the fifth, φ and ψ beside it; a
    # free orbit's r and ν follow): the first three alone never looked at the attitude
    n = run.layout.n_coordinates
    err = tuple(float(abs(a - b)) for a, b in zip(run.states[-1, :n], fine.states[-1, :n]))
    return replace(run, error_estimate=err)


def _bar(total, desc, progress):  # tqdm looked up here: tests replace it
    return progress_bar(total, desc, progress, tqdm)


def _run_rk4(sat, periods, steps, model, locate, progress, warn, start) -> SimResult:
    m, air = _kernel_args(sat, model, periods * sat.period)
    p = parameter_vector(sat, model)
    pw = p.copy()
    h = periods * sat.period / steps
    if warn and (amp := rk4_amplification(sat, h, model)) > 1.0:
        warnings.warn(RK4StepWarning(
            f"RK4 step {h:.4g} s is unstable for the linearised system at the initial state "
            f"(spurious amplification per step {amp:.4g} > 1): a tether oscillation will grow "
            f"numerically. Use more steps or method='adaptive'."), stacklevel=3)
    ev = event_parameters(sat, model)
    y = np.array(start, dtype=float)
    out_t = np.empty(steps + 1)
    out_y = np.empty((steps + 1, y.size))
    out_t[0], out_y[0] = 0.0, y
    row, switches, status, message, stop, done = 1, 0, "ok", "", {}, 0
    t0 = time.perf_counter()
    chunk = min(steps, RK4_PAUSE_STEPS)  # the same pauses with or without a bar
    # this model's compiled loop, chosen (compiled or loaded) once, before the bar
    # starts: its rate, hence its ETA, then counts integration only
    loop = specialised(rk4_run, m, (air, 0, y, h, chunk, 1, p, pw, ev, locate, out_t, out_y,
                                    row), name=model)
    with _bar(periods, f"{sat.name} RK4", progress) as bar:
        try:
            while done < steps:
                n = min(chunk, steps - done)
                rows, sw, st, slot, t_hit = loop(m, air, done, y, h, n, 1, p, pw, ev, locate,
                                                 out_t, out_y, row)
                row += rows
                switches += sw
                if st == RK4_EVENT:  # the last row is the located state (rk4_run)
                    done += rows
                    status, message, stop = _stopped(sat, slot, t_hit)
                    break
                done += n
                _advance(bar, done * h / sat.period)
                if st != 0:
                    status = "diverged"
                    message = (f"state became non-finite near t = {out_t[row - 1]:.6g} s: the "
                               f"RK4 step {h:.4g} s is too long; use more steps or method='adaptive'")
                    break
        except KeyboardInterrupt:
            status, message = "interrupted", f"interrupted at t = {out_t[row - 1]:.6g} s"
    if row < out_t.size:  # stopped early: keep only the rows written, not the whole buffer
        out_t, out_y = out_t[:row].copy(), out_y[:row].copy()
    return SimResult(sat, model, "rk4", out_t, out_y, step=h, periods=periods,
                     locate_switches=locate, nfev=4 * done, n_accepted=done,
                     n_switches=switches, status=status, message=message,
                     wall_time=time.perf_counter() - t0, **stop)


def refined_grid(t_end: float, n_out: int, refine: int) -> np.ndarray:
    """n_out·refine + 1 times whose every refine-th is exactly linspace(0, t_end, n_out + 1)."""
    coarse = np.linspace(0.0, t_end, n_out + 1)
    if refine == 1:
        return coarse
    inner = coarse[:-1, None] + np.diff(coarse)[:, None] * (np.arange(refine) / refine)
    return np.append(inner.ravel(), coarse[-1])


def _run_adaptive(sat, periods, n_out, model, rtol, atol, locate, progress,
                  refine: int = 1, start=None, stops=STOPS, scheme="adaptive") -> SimResult:
    t_end = periods * sat.period
    ev = event_parameters(sat, model, stops)  # stops: the stopping events watched
    m, air = _kernel_args(sat, model, t_end)
    p = parameter_vector(sat, model)
    pw = p.copy()
    # start: the run's start state (start_run) or one to continue from (release.py)
    y = initial_model_state(sat, model) if start is None else np.array(start, dtype=float)
    out_t = refined_grid(t_end, n_out, refine)
    out_y = np.full((out_t.size, y.size), np.nan)
    out_y[0] = y
    t, h, i_out, status, message, calls, stop = 0.0, 0.0, 1, "ok", "", 0, {}
    max_steps = step_budget(scheme, periods)
    # the scheme's loop and what it keeps between calls: DOP853 (explicit), or Radau IIA
    # (implicit, for stiff tethers: engine/integrators/radau.py) with its carry (Jacobian,
    # controller memory, last dense output) so that the pauses do not change its steps
    if scheme == "implicit":
        run_fn, name = radau_run, "Radau"
        counters = np.zeros(RADAU_COUNTERS, dtype=np.int64)
        kept = (counters, np.zeros(carry_size(y.size)))
    else:
        run_fn, name = dop853_run, "DOP853"
        counters = np.zeros(5, dtype=np.int64)
        kept = (counters,)
    # this model's compiled loop, chosen (compiled or loaded) once, before the bar
    # starts: its rate, hence its ETA, then counts integration only
    loop = specialised(run_fn, m, (air, t, t_end, y, h, p, pw, ev, rtol, atol, locate,
                                   out_t, out_y, i_out, max_steps, *kept, math.inf), name=model)
    t0 = time.perf_counter()
    with _bar(periods, f"{sat.name} {name}", progress) as bar:
        try:
            # pauses for Ctrl-C and the bar; they do not change the steps (dop853_run's
            # t_pause), at whatever times they fall
            span = min(t_end / CHUNKS, sat.period)  # the first call: the loop's speed
            t_pause = span
            while True:
                t_prev, t_call = t, time.perf_counter()
                # the step budget is the whole run's, however many calls it takes
                t, h, i_out, st, slot = loop(m, air, t, t_end, y, h, p, pw, ev, rtol, atol,
                                             locate, out_t, out_y, i_out,
                                             max_steps - int(counters[4]), *kept, t_pause)
                calls += 1
                _advance(bar, t / sat.period)
                if st == STATUS_EVENT:
                    status, message, stop = _stopped(sat, slot, t)
                    break
                if st != STATUS_OK:
                    status = "diverged" if st == 1 else "failed"
                    message = {1: "state became non-finite", 2: "step size became too small",
                               3: "too many steps"}[st] + f" at t = {t:.6g} s" + atol_hint(sat, atol)
                    break
                if t >= t_end:
                    break
                rate = (t - t_prev) / max(time.perf_counter() - t_call, 1e-9)  # sim s per s
                if rate * QUICK_RUN_S >= t_end - t:
                    t_pause = math.inf
                else:
                    span = min(t_end / CHUNKS, 10.0 * span, rate * PAUSE_S)
                    # a span below t's resolution would make no step: run to the end
                    t_pause = t + span if t + span > t else math.inf
        except KeyboardInterrupt:
            status, message = "interrupted", f"interrupted at t = {t:.6g} s"
    # one copy of the rows written (none for a whole run): an interrupted long run's
    # millions of rows were copied twice, seconds between Ctrl-C and the first file
    fine_t, fine_y = ((out_t, out_y) if i_out == out_t.size
                      else (out_t[:i_out].copy(), out_y[:i_out].copy()))
    t_out, y_out = ((fine_t, fine_y) if refine == 1
                    else (fine_t[::refine].copy(), fine_y[::refine].copy()))
    if stop and t > fine_t[-1]:  # the located state: the last sample of both grids
        fine_t, fine_y = np.append(fine_t, t), np.vstack([fine_y, y])
        t_out, y_out = ((fine_t, fine_y) if refine == 1
                        else (np.append(t_out, t), np.vstack([y_out, y])))
    return SimResult(sat, model, scheme, t_out, y_out,
                     fine_t=fine_t if refine > 1 else None,
                     fine_states=fine_y if refine > 1 else None,
                     periods=periods,
                     rtol=rtol, atol=atol, locate_switches=locate,
                     # each resumed call evaluates f at its start again, a value the step
                     # before it had (FSAL): not counted, so nfev is the run's, not the pauses'
                     nfev=int(counters[0]) - max(calls - 1, 0),
                     n_accepted=int(counters[1]), n_rejected=int(counters[2]),
                     n_switches=int(counters[3]), status=status, message=message,
                     wall_time=time.perf_counter() - t0, **stop)
