"""Size guards: refuse a run or a sweep whose output would not fit, before allocating it.

``tethersim run satI --steps 100000000`` used to be killed by the kernel at
24 GB with no message, and a 10^6 x 10^6 sweep grid hung while validating its
points.  The estimates here are cheap arithmetic on the request; the limits are
stated in the messages and can be raised with environment variables:

``TETHERSIM_MAX_OUTPUT_BYTES``
    largest time-series output of one simulate() call (default 2 GiB).
``TETHERSIM_MAX_SWEEP_POINTS``
    largest sweep grid (default 1,000,000 points); also the most runs of a grid whose
    points are several runs each (``feasibility``: points x runs per point).
``TETHERSIM_MAX_STORE_BYTES``
    largest sweep store, in memory and on disk (default 2 GiB).

And the step budget of one run (:func:`step_budget`): a run that needs more steps stops
"too many steps" rather than run for hours.
"""
from __future__ import annotations

import math
import os

GIB = 1024**3
DEFAULT_OUTPUT_BYTES = 2 * GIB
DEFAULT_SWEEP_POINTS = 1_000_000
DEFAULT_STORE_BYTES = 2 * GIB
STATE_COLUMNS = 10  # the widest planar state: a free orbit's δx δy θ r ν and rates
# bytes per sweep point: 11 float64 + 4 int8 + 1 int64 record fields (sweep.point.VARIABLES),
# the done mask and the int64 checksum (sweep.verify); tests/engine/test_guards.py holds
# it to VARIABLES (which sits above this layer)
SWEEP_POINT_BYTES = 11 * 8 + 4 + 8 + 1 + 8


# what simulate()'s own guard blames: its arguments; a command names its options instead
API_SUBJECT = "periods/steps/samples"
# ~2500x a nominal run (steps of ~5 ms): a spinning-up run fails in about a minute, not an
# hour; no tether of this model's scale (N/mm^2 x 1 mm^2) needs more
MAX_STEPS_PER_PERIOD = 1_000_000
# implicit runs: a real line that rings (a near-slack line bouncing twice a second for an
# orbit: docs/real-tethers.md, deployment) resolves every ring; a runaway still stops
IMPLICIT_STEPS_PER_PERIOD = 5_000_000


def step_budget(scheme: str, periods: float) -> int:
    """Steps a run of ``periods`` orbits of ``scheme`` may take ("too many steps" past it)."""
    per = IMPLICIT_STEPS_PER_PERIOD if scheme == "implicit" else MAX_STEPS_PER_PERIOD
    return int(per * periods)


class SizeLimitError(ValueError):
    """A request whose output would exceed a stated size limit; the message gives both.

    ``subject`` names what sets the size (``"--periods/--steps"``; simulate()'s own
    guard: :data:`API_SUBJECT`), ``detail`` the rest of the one-line message, so a
    command can name its own options (:meth:`naming`).
    """

    def __init__(self, detail: str, subject: str | None = None):
        self.detail, self.subject = detail, subject
        super().__init__(f"{subject}: {detail}" if subject else detail)

    def naming(self, subject: str) -> SizeLimitError:
        """The same refusal blaming ``subject`` (a command's options)."""
        return SizeLimitError(self.detail, subject)


def _limit(env: str, default: float) -> float:
    text = os.environ.get(env)
    if text is None:
        return default
    try:
        value = float(text)
    except ValueError:
        raise SizeLimitError(f"{env} = {text!r}: must be a number") from None
    if not value > 0:
        raise SizeLimitError(f"{env} = {text!r}: must be > 0")
    return value


def human(nbytes: float) -> str:
    """A byte count for people.

    Parameters
    ----------
    nbytes : float
        Size in bytes.

    Returns
    -------
    str
        Three significant digits and a binary unit, e.g. ``'16.4 GiB'``.
    """
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if nbytes < 1024 or unit == "PiB":
            return f"{nbytes:.3g} {unit}"
        nbytes /= 1024
    return f"{nbytes:.3g} PiB"  # pragma: no cover - the loop always returns


def _number(value):
    """float(value) for a real number, else None (simulate's own checks then complain)."""
    if isinstance(value, bool):
        return None
    try:
        v = float(value)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def output_rows(periods, steps, method, samples):
    """Rows of one simulate() output, including t = 0.

    Mirrors simulate()'s defaults: RK4 stores every step (300 per orbit unless
    ``steps``); the adaptive method stores ``samples`` (else ``steps``, else 200
    per orbit) output points.

    Parameters
    ----------
    periods, steps, method, samples
        As given to :func:`tethersim.engine.simulate.simulate`.

    Returns
    -------
    float or None
        The row count, or None if the request is malformed (simulate names it).
    """
    from tethersim.engine.simulate import SAMPLES_PER_PERIOD, STEPS_PER_PERIOD

    p = _number(periods)
    if p is None or p <= 0:
        return None
    if method == "rk4":
        n = _number(steps) if steps is not None else max(1, round(STEPS_PER_PERIOD * p))
    else:
        given = samples if samples is not None else steps
        n = _number(given) if given is not None else max(2, round(SAMPLES_PER_PERIOD * p))
    return None if n is None or n < 1 else n + 1


def metrics_rows(periods, output: float) -> float:
    """Rows of the adaptive run's metrics grid beside an output of ``output`` rows (0 if none).

    simulate() refines the output grid to at least METRIC_SAMPLES_PER_PERIOD per orbit
    (``SimResult.fine_t``): 10 output samples of 10^6 orbits hold a 2 x 10^8-row grid.
    """
    from tethersim.engine.simulate import METRIC_SAMPLES_PER_PERIOD

    n_out = output - 1
    refine = max(1, math.ceil(METRIC_SAMPLES_PER_PERIOD * float(periods) / n_out))
    return 0 if refine == 1 else n_out * refine + 1


def check_simulation(periods, steps=None, method="adaptive", samples=None, check=True,
                     subject: str = API_SUBJECT) -> None:
    """Refuse a simulate() request whose arrays would exceed the limit.

    Counted: the output (t and the state per row, float64), the adaptive method's
    metrics grid (refined to 200 samples per orbit), and with ``check`` the finer
    rerun held beside them (RK4: twice the steps; adaptive: the output grid again).

    Parameters
    ----------
    periods, steps, method, samples, check
        As given to :func:`tethersim.engine.simulate.simulate`; malformed values are
        left for simulate's own validation.
    subject : str, optional
        What the message blames: simulate()'s arguments by default, a command's
        options (e.g. ``"--periods/--steps"``) when it checks before any work.

    Raises
    ------
    SizeLimitError
        With the estimate, the limit (``TETHERSIM_MAX_OUTPUT_BYTES``) and what to change.
    """
    rows = output_rows(periods, steps, method, samples)
    if rows is None:
        return
    fine = 0 if method == "rk4" else metrics_rows(periods, rows)
    # the convergence check holds a second run beside the first (RK4: twice the steps;
    # adaptive: the output grid, unrefined)
    rerun = (2 * rows - 1 if method == "rk4" else rows) if check else 0
    row_bytes = (1 + STATE_COLUMNS) * 8
    need = (rows + fine + rerun) * row_bytes
    limit = _limit("TETHERSIM_MAX_OUTPUT_BYTES", DEFAULT_OUTPUT_BYTES)
    if need > limit:
        what = "steps" if method == "rk4" else "output samples"
        parts = [f"{rows - 1:.6g} {what}"]
        if fine:
            parts.append(f"a metrics grid of {fine - 1:.6g} samples (200 per orbit)")
        if rerun:
            parts.append(f"the convergence check's rerun of {rerun - 1:.6g} {what}")
        hint = ("fewer steps, a shorter run or the adaptive method" if method == "rk4"
                else "a shorter run" if fine else "fewer output samples or a shorter run")
        raise SizeLimitError(
            f"{' + '.join(parts)} need about {human(need)} of memory "
            f"(t and {STATE_COLUMNS} states x 8 bytes each); allowed at most {human(limit)} "
            f"(TETHERSIM_MAX_OUTPUT_BYTES): use {hint}", subject)


def check_sweep(shape, names=()) -> None:
    """Refuse a sweep grid whose store would exceed the point or byte limit.

    Parameters
    ----------
    shape : sequence of int
        Points per axis.
    names : sequence of str
        Axis names, for the message.

    Raises
    ------
    SizeLimitError
        With the grid size, the store size and the limits
        (``TETHERSIM_MAX_SWEEP_POINTS``, ``TETHERSIM_MAX_STORE_BYTES``).
    """
    points = math.prod(int(n) for n in shape)  # Python ints: no overflow at 10^12
    nbytes = points * SWEEP_POINT_BYTES
    max_points = _limit("TETHERSIM_MAX_SWEEP_POINTS", DEFAULT_SWEEP_POINTS)
    max_bytes = _limit("TETHERSIM_MAX_STORE_BYTES", DEFAULT_STORE_BYTES)
    if points > max_points or nbytes > max_bytes:
        axes = " x ".join(f"{n} {name}".strip() for n, name in
                          zip(shape, list(names) + [""] * len(shape)))
        raise SizeLimitError(
            f"sweep grid {axes} = {points:.6g} points (store about {human(nbytes)}): allowed "
            f"at most {max_points:.6g} points (TETHERSIM_MAX_SWEEP_POINTS) and "
            f"{human(max_bytes)} (TETHERSIM_MAX_STORE_BYTES); use fewer grid points")


def check_runs(points: int, runs_per_point: int, what: str, option: str) -> None:
    """Refuse a grid whose runs (points x runs per point) exceed the sweep's point limit.

    A sweep point is one run; a command whose point is several runs (``feasibility``)
    is capped on its runs by the same limit, before any point is validated or run.

    Parameters
    ----------
    points : int
        Grid points.
    runs_per_point : int
        Simulations per point.
    what : str
        The grid, for the message (e.g. ``"feasibility grid"``).
    option : str
        The options that set the grid (e.g. ``"--altitude"``).

    Raises
    ------
    SizeLimitError
        One line naming the grid, its runs, the limit (``TETHERSIM_MAX_SWEEP_POINTS``)
        and the option.
    """
    runs = int(points) * int(runs_per_point)
    max_runs = _limit("TETHERSIM_MAX_SWEEP_POINTS", DEFAULT_SWEEP_POINTS)
    if runs > max_runs:
        raise SizeLimitError(
            f"{what} of {points:.6g} points x {runs_per_point} runs = {runs:.6g} runs: allowed "
            f"at most {max_runs:.6g} runs (TETHERSIM_MAX_SWEEP_POINTS, the sweep's cap); "
            f"use fewer points in {option}")
