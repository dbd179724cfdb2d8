"""Option groups shared by the commands, each option declared once, and their meaning.

Every command builds its parser from these groups, so ``--periods``, ``--out``,
``--force``, ``--model``, ``--quiet``, ``--set``/``--scale`` and the integrator
options (``--method``, ``--steps``, ``--rtol``, ``--faithful``,
``--locate-switches``) read and mean the same everywhere.  Values at this edge
are in the units of :mod:`tethersim.model.params` (E1, E2 in N/mm^2, altitude
in km, else SI).

The module also holds what the commands do alike with those options: resolve
the satellite, the integrator and its printed description, the output folder
(per satellite, never silently replacing another satellite's results), and the
exceptions that :func:`tethersim.cli.main.main` turns into exit codes.
"""
from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass

from tethersim.model.registry import DEFAULT_MODEL

PRESET_HELP = "preset name (satI, satII, dumbsat; any case) or path to a satellite .toml file"


class UsageError(Exception):
    """Bad command-line input: main prints one line and exits 2."""


class Interrupted(Exception):
    """Ctrl-C or SIGTERM after the finished work was written: main prints one line, exits 130."""


class RunFailed(Exception):
    """A run ended diverged or failed (its output is written): main prints one line, exits 1."""


class Parser(argparse.ArgumentParser):
    """An ArgumentParser whose usage errors are one line and leave the exit to main.

    argparse would print the usage and ``sys.exit(2)``; :class:`UsageError` lets
    :func:`tethersim.cli.main.main` report every bad input alike (one line, exit 2).
    """

    def error(self, message):
        """Raise :class:`UsageError` naming the command and pointing at its ``--help``."""
        from tethersim.cli.overrides import dash_hint
        raise UsageError(f"{dash_hint(message)} (see '{self.prog} --help')")


# --- argument types: reject bad values at parse time, naming the allowed range ---------------
def positive_float(text: str) -> float:
    """A finite number > 0 (argparse ``type``)."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a finite number > 0, got {text!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise argparse.ArgumentTypeError(f"must be a finite number > 0, got {text}")
    return v


def int_range(lo: int, hi: int | None = None):
    """An argparse ``type``: an integer in lo..hi (no upper bound if ``hi`` is None)."""
    allowed = f"an integer >= {lo}" if hi is None else f"an integer in {lo}..{hi}"

    def parse(text: str) -> int:
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be {allowed}, got {text!r}") from None
        if v < lo or (hi is not None and v > hi):
            raise argparse.ArgumentTypeError(f"must be {allowed}, got {v}")
        return v

    parse.__name__ = allowed  # argparse names the type in its own messages
    return parse


positive_int = int_range(1)


def rtol_float(text: str) -> float:
    """A relative tolerance in the engine's RTOL_RANGE (argparse ``type``; why: its comment)."""
    from tethersim.engine.simulate import RTOL_RANGE
    v = positive_float(text)
    if not RTOL_RANGE[0] <= v <= RTOL_RANGE[1]:
        raise argparse.ArgumentTypeError(f"allowed range {RTOL_RANGE[0]:g} <= rtol <= "
                                         f"{RTOL_RANGE[1]:g}, got {text}")
    return v


def atol_float(text: str) -> float:
    """An absolute tolerance in the engine's ATOL_RANGE (argparse ``type``)."""
    from tethersim.engine.arguments import ATOL_RANGE
    v = positive_float(text)
    if not ATOL_RANGE[0] <= v <= ATOL_RANGE[1]:
        raise argparse.ArgumentTypeError(f"allowed range {ATOL_RANGE[0]:g} <= atol <= "
                                         f"{ATOL_RANGE[1]:g}, got {text}")
    return v


# --- option groups ---------------------------------------------------------------------------
def add_satellite(parser, *, optional_default: str | None = None, note: str = "") -> None:
    """The positional satellite: a preset name or a .toml path."""
    if optional_default is None:
        parser.add_argument("satellite", help=PRESET_HELP + note)
    else:
        parser.add_argument("satellite", nargs="?", default=optional_default,
                            help=PRESET_HELP + note)


def add_periods(parser, default: float | None = 50.0, help: str | None = None) -> None:
    """``--periods N``: orbits per run, a finite number > 0."""
    parser.add_argument("--periods", type=positive_float, default=default, metavar="N",
                        help=help or f"orbits to simulate (default {default:g})")


def add_out(parser, default: str) -> None:
    """``--out DIR`` and ``--force``: where results go, and leave to replace another's."""
    parser.add_argument("--out", default=None, metavar="DIR",
                        help=f"output folder (default {default})")
    parser.add_argument("--force", action="store_true",
                        help="write into --out even if it holds results of another satellite "
                             "or other --set/--scale (they are replaced)")


def add_model(parser, note: str = "") -> None:
    """``--model NAME``: one of the model variants of the registry."""
    parser.add_argument("--model", choices=model_names(), default=DEFAULT_MODEL,
                        help=f"model variant (default {DEFAULT_MODEL}{note})")


def add_models(parser, default) -> None:
    """``--models A,B ...``: model variants, comma- or space-separated, first the reference."""
    names = ",".join(model_names())
    parser.add_argument("--models", nargs="+", default=list(default), metavar="MODEL",
                        help=f"model variants, comma- or space-separated, the first is the "
                             f"reference (default {','.join(default)}; allowed: {names})")


def models(args) -> tuple:
    """The ``--models`` values as a tuple of names, checked (ValueError names the allowed)."""
    from tethersim.experiments.compare import parse_models
    names = [m.strip() for arg in args.models for m in arg.split(",") if m.strip()]
    try:
        return parse_models(names)
    except ValueError as exc:
        raise UsageError(f"--{exc}") from None


def add_atol(parser) -> None:
    """``--atol X``: the adaptive and implicit schemes' absolute tolerance (run only)."""
    parser.add_argument("--atol", type=atol_float, default=None,
                        help="absolute tolerance of the adaptive and implicit schemes [m, rad, "
                             "m/s, rad/s] (default 1e-12; real lines 1e-10, with beads 1e-9: "
                             "their force's rounding level at rest, docs/tethers.md)")


def add_start(parser) -> None:
    """``--start MODE``: the satellite's initial state, its equilibrium, or auto
    (tethersim.engine.start)."""
    from tethersim.engine.start import START_MODES
    parser.add_argument("--start", choices=START_MODES, default="auto",
                        help="where the run starts: given (the satellite's initial state), "
                             "equilibrium (its steady configuration, rates zero), or auto "
                             "(default: equilibrium when a tether is a real line, EA >= 100 N; "
                             "else given); docs/tethers.md")


def add_quiet(parser) -> None:
    """``--quiet``: no progress bars or progress lines."""
    parser.add_argument("--quiet", action="store_true", help="no progress bars")


def add_overrides(parser) -> None:
    """``--set NAME=VALUE`` and ``--scale NAME=FACTOR`` (units: tethersim.model.params)."""
    parser.add_argument("--set", action="append", metavar="NAME=VALUE", default=[],
                        help="change a parameter, in the units 'tethersim show' prints (E1, E2 "
                             "in N/mm^2, altitude in km, else SI); repeatable")
    parser.add_argument("--scale", action="append", metavar="NAME=FACTOR", default=[],
                        help="multiply a parameter, e.g. --scale c1=10 --scale c2=10; repeatable")
    parser.add_argument("--tethers", metavar="MATERIAL:DIAMETER_MM[:KNOCKDOWN]", default=None,
                        help="both tethers made of a real line (after --set, so rest lengths "
                             "set there count): E1, E2 = EA, c1, c2 from its loss factor, Fb1, "
                             "Fb2 = breaking load; materials: docs/tethers.md, e.g. "
                             "--tethers kevlar49:1")
    parser.add_argument("--allow-implausible", action="store_true",
                        help="run values outside the plausible ranges (docs/limits.md); "
                             "the summary lists them")


def _faithful_help() -> str:
    """--faithful's one documented meaning, its numbers computed (200 per orbit, 26.55 s)."""
    from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD
    from tethersim.model.constants import MU_EARTH, R_EARTH
    period_200km = 2 * math.pi * math.sqrt((R_EARTH + 200e3) ** 3 / MU_EARTH)
    return (f"the thesis's scheme: fixed-step RK4 at the thesis's chapter-5 step, "
            f"{FAITHFUL_STEPS_PER_PERIOD} steps per orbit "
            f"({period_200km / FAITHFUL_STEPS_PER_PERIOD:.2f} s at 200 km), tether switches "
            f"not located; --steps sets another step count")


def add_integrator(parser, *, rtol: float = 1e-10, fixed_step: bool = True) -> None:
    """Integrator options: ``--faithful`` and ``--rtol``; with ``fixed_step`` also
    ``--method``, ``--steps`` and ``--locate-switches``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The command's parser.
    rtol : float
        The command's default DOP853 relative tolerance.
    fixed_step : bool
        False for commands whose runs are adaptive, implicit or faithful, never
        free-standing RK4 (sweep).
    """
    from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD, STEPS_PER_PERIOD

    g = parser.add_argument_group("integrator")
    g.add_argument("--faithful", action="store_true", help=_faithful_help())
    if fixed_step:
        g.add_argument("--method", choices=("adaptive", "rk4", "implicit"), default=None,
                       help="adaptive DOP853 (default, converged), fixed-step RK4, or implicit "
                            "Radau IIA (stiff, real tethers: docs/tethers.md)")
        g.add_argument("--steps", type=positive_int, default=None, metavar="N",
                       help=f"RK4: number of steps in the whole run (default "
                            f"{FAITHFUL_STEPS_PER_PERIOD} per orbit with --faithful, "
                            f"{STEPS_PER_PERIOD} per orbit with --method rk4); adaptive, "
                            f"implicit: number of output samples")
        g.add_argument("--locate-switches", action="store_true",
                       help="RK4: split steps at taut/slack switches (not with --faithful)")
    else:  # a sweep's points: converged DOP853, or Radau for real tethers
        g.add_argument("--method", choices=("adaptive", "implicit"), default=None,
                       help="adaptive DOP853 (default, converged) or implicit Radau IIA "
                            "(stiff, real tethers: docs/tethers.md)")
    g.add_argument("--rtol", type=rtol_float, default=rtol,
                   help=f"relative tolerance of the adaptive and implicit schemes (default "
                        f"{rtol:g})")


def model_names() -> tuple:
    """The model variants of the registry (generated by ``make derive``)."""
    from tethersim.model.registry import NAMES
    return NAMES


# --- resolving the options -------------------------------------------------------------------
def overrides(args) -> list:
    """The --set/--scale options as typed, in order (for labels and provenance)."""
    return ([f"--set {a}" for a in getattr(args, "set", None) or ()]
            + [f"--scale {a}" for a in getattr(args, "scale", None) or ()])


def satellite(args):
    """The satellite of ``args.satellite`` with --set/--scale applied (edge units), in the
    orbit its ``--model``/``--models`` run (:func:`tethersim.cli.orbit.orbit_of_models`)."""
    from tethersim.model.params import apply_overrides
    from tethersim.model.presets import resolve
    sat = resolve(args.satellite, getattr(args, "allow_implausible", False))
    sat = apply_overrides(sat, getattr(args, "set", None) or (),
                          getattr(args, "scale", None) or ())
    if getattr(args, "tethers", None):
        from tethersim.cli.overrides import with_tethers_option
        sat = with_tethers_option(sat, args)
    from tethersim.cli.orbit import orbit_of_models
    return orbit_of_models(args, sat)


@dataclass(frozen=True)
class Integrator:
    """How a command integrates, resolved once from the integrator options.

    method: "rk4", "adaptive" or "implicit"; steps: RK4 steps of the whole run (None for
    adaptive); locate: locate taut/slack switches; faithful: the thesis's scheme;
    rtol: adaptive tolerance; samples: adaptive output samples (None: the default).
    """

    method: str
    steps: int | None
    locate: bool
    faithful: bool
    rtol: float
    samples: int | None = None

    def describe(self, period: float, periods: float) -> str:
        """One line saying the step used, e.g. ``RK4 step 26.55 s (200 per orbit, thesis
        ch. 5), switches not located``; ``period`` [s] of the orbit, ``periods`` run."""
        located = "switches located" if self.locate else "switches not located"
        if self.method != "rk4":
            from tethersim.engine.result import ADAPTIVE_SCHEMES
            return f"{ADAPTIVE_SCHEMES[self.method]}, rtol {self.rtol:g}, {located}"
        per_orbit = self.steps / periods
        thesis = self.faithful and self.steps == faithful_steps(periods)
        why = ", thesis ch. 5" if thesis else ""
        return (f"RK4 step {periods * period / self.steps:.2f} s ({per_orbit:.4g} per orbit{why}; "
                f"{self.steps} steps), {located}")


def faithful_steps(periods: float) -> int:
    """RK4 steps of a faithful run of ``periods`` orbits: the thesis's chapter-5 step."""
    from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD
    return max(1, round(FAITHFUL_STEPS_PER_PERIOD * periods))


def integrator(args) -> Integrator:
    """Resolve ``--faithful``, ``--method``, ``--steps``, ``--locate-switches``, ``--rtol``.

    ``--faithful`` is fixed-step RK4 at :data:`FAITHFUL_STEPS_PER_PERIOD` steps per
    orbit, switches not located, whatever the command; ``--method rk4`` alone keeps
    the engine's default of 300 steps per orbit.

    Raises
    ------
    UsageError
        ``--faithful`` with ``--method adaptive`` or ``--locate-switches``.
    """
    from tethersim.engine.simulate import STEPS_PER_PERIOD
    method = getattr(args, "method", None)
    steps = getattr(args, "steps", None)
    locate_flag = getattr(args, "locate_switches", False)
    if args.faithful:
        if method in ("adaptive", "implicit"):
            raise UsageError(f"--faithful with --method {method}: --faithful is fixed-step RK4")
        if locate_flag:
            raise UsageError("--faithful with --locate-switches: the thesis's scheme does not "
                             "locate switches")
        return Integrator("rk4", steps or faithful_steps(args.periods), False, True, args.rtol)
    if method == "rk4":
        return Integrator("rk4", steps or max(1, round(STEPS_PER_PERIOD * args.periods)),
                          locate_flag, False, args.rtol)
    # adaptive, implicit: always locate switches; --steps sets the output samples
    return Integrator(method or "adaptive", None, True, False, args.rtol, samples=steps)


def progress(args):
    """The engine's ``progress`` argument: None (bar if slow) or False (--quiet)."""
    return False if args.quiet else None


def check_status(res) -> None:
    """Raise :class:`Interrupted` or :class:`RunFailed` for a run that did not end ok
    (call after its output is written)."""
    interrupted_early(res)
    if res.status == "interrupted":
        raise Interrupted(f"the output holds the run up to t = {res.t[-1]:.6g} s")
    if res.status != "ok":
        raise RunFailed(res.message)


# an interrupted run with more output samples than this says, before writing them, that a
# second Ctrl-C stops the writing (a million samples: ~20 s of CSV and ~10 s of plots)
WRITE_NOTICE_SAMPLES = 100_000


def interrupted_early(res) -> None:
    """Raise :class:`Interrupted` for Ctrl-C before a second output sample: nothing to
    summarise or write (call right after the run).  An interrupted run with a long
    output says on stderr that it writes it, and that Ctrl-C again stops that: every
    file is written whole under a temporary name, so the folder keeps complete files."""
    if res.status == "interrupted" and res.t.size < 2:
        raise Interrupted(f"at t = {res.t[-1]:.6g} s, before the first output sample: "
                          f"nothing written")
    if res.status == "interrupted" and res.t.size > WRITE_NOTICE_SAMPLES:
        print(f"tethersim: interrupted at t = {res.t[-1]:.6g} s: writing the {res.t.size} "
              f"samples finished; Ctrl-C again to stop writing (files are complete or absent)",
              file=sys.stderr, flush=True)


# the output folders (tethersim.cli.folders), used by every command as options.<name>
from tethersim.cli import folders as _folders  # noqa: E402  (it uses UsageError, above)

RESULTS = _folders.RESULTS
PROVENANCE_FILES = _folders.PROVENANCE_FILES
satellite_key = _folders.satellite_key
default_out = _folders.default_out
provenance = _folders.provenance
claim_folder = _folders.claim_folder
write_provenance = _folders.write_provenance
write_record = _folders.write_record
