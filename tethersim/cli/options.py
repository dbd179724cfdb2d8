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
import json
import math
import re
from dataclasses import dataclass
from pathlib import Path

from tethersim.model.registry import DEFAULT_MODEL

PRESET_HELP = "preset name (satI, satII, dumbsat; any case) or path to a satellite .toml file"
RESULTS = Path("results")
# the file that records whose results a folder holds; `run` records it in summary.json
PROVENANCE_FILES = ("summary.json", "satellite.json")


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
        False for commands that only choose between the converged and the
        faithful scheme (sweep).
    """
    from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD, STEPS_PER_PERIOD

    g = parser.add_argument_group("integrator")
    g.add_argument("--faithful", action="store_true", help=_faithful_help())
    if fixed_step:
        g.add_argument("--method", choices=("adaptive", "rk4"), default=None,
                       help="adaptive DOP853 (default, converged) or fixed-step RK4")
        g.add_argument("--steps", type=positive_int, default=None, metavar="N",
                       help=f"RK4: number of steps in the whole run (default "
                            f"{FAITHFUL_STEPS_PER_PERIOD} per orbit with --faithful, "
                            f"{STEPS_PER_PERIOD} per orbit with --method rk4); adaptive: "
                            f"number of output samples")
        g.add_argument("--locate-switches", action="store_true",
                       help="RK4: split steps at taut/slack switches (not with --faithful)")
    g.add_argument("--rtol", type=rtol_float, default=rtol,
                   help=f"adaptive DOP853 relative tolerance (default {rtol:g})")


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
    from tethersim.cli.orbit import orbit_of_models
    return orbit_of_models(args, sat)


@dataclass(frozen=True)
class Integrator:
    """How a command integrates, resolved once from the integrator options.

    method: "rk4" or "adaptive"; steps: RK4 steps of the whole run (None for
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
            return f"DOP853 adaptive, rtol {self.rtol:g}, {located}"
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
        if method == "adaptive":
            raise UsageError("--faithful with --method adaptive: --faithful is fixed-step RK4")
        if locate_flag:
            raise UsageError("--faithful with --locate-switches: the thesis's scheme does not "
                             "locate switches")
        return Integrator("rk4", steps or faithful_steps(args.periods), False, True, args.rtol)
    if method == "rk4":
        return Integrator("rk4", steps or max(1, round(STEPS_PER_PERIOD * args.periods)),
                          locate_flag, False, args.rtol)
    # adaptive: DOP853 always locates switches; --steps sets the output samples
    return Integrator("adaptive", None, True, False, args.rtol, samples=steps)


def progress(args):
    """The engine's ``progress`` argument: None (bar if slow) or False (--quiet)."""
    return False if args.quiet else None


# --- output folders --------------------------------------------------------------------------
def satellite_key(arg: str) -> str:
    """A folder name for the satellite argument: the preset's name as shipped (satI, satII,
    dumbsat) or the TOML file's stem, with anything but letters, digits, '.', '_', '-'
    replaced by '_'."""
    from tethersim.model.presets import PRESET_NAMES
    stem = Path(PRESET_NAMES.get(arg.lower(), arg)).stem
    return re.sub(r"[^A-Za-z0-9._-]", "_", stem) or "satellite"


def default_out(args, *parts: str) -> Path:
    """results/<satellite>/<parts...>: one folder per satellite (see :func:`satellite_key`)."""
    return RESULTS.joinpath(satellite_key(args.satellite), *parts)


def provenance(args, sat) -> dict:
    """Whose results a folder holds: the satellite's name, where it came from, the overrides."""
    from tethersim.model.presets import PRESET_NAMES
    key = args.satellite.lower()
    origin = (Path(PRESET_NAMES[key]).stem if key in PRESET_NAMES
              else str(Path(args.satellite).resolve()))
    return {"satellite": sat.name, "from": origin, "overrides": overrides(args)}


def _describe(p: dict) -> str:
    if not p.get("satellite"):  # written before tethersim recorded it
        return "an unrecorded satellite"
    text = f"{p['satellite']} ({p.get('from') or '?'})"
    return text + (" " + " ".join(p["overrides"]) if p.get("overrides") else "")


def claim_folder(out: Path, args, sat) -> dict:
    """Create ``out`` for this satellite's results, refusing one that holds another's.

    The folder's ``summary.json`` (run) or ``satellite.json`` (other commands)
    records whose results it holds; unless ``--force``, a folder of another
    satellite, source or --set/--scale stops the command before anything runs.

    Returns
    -------
    dict
        This run's provenance, to write with :func:`write_provenance` (or into summary.json).

    Raises
    ------
    UsageError
        The folder holds results of another satellite (one line naming both).
    ValueError
        The folder cannot be created.
    """
    mine = provenance(args, sat)
    if not args.force:
        for name in PROVENANCE_FILES:
            path = out / name
            if not path.is_file():
                continue
            try:
                theirs = json.loads(path.read_text())
            except (OSError, ValueError):
                theirs = {}
            if not isinstance(theirs, dict):
                theirs = {}
            theirs = {k: theirs.get(k) for k in mine}
            theirs["overrides"] = theirs["overrides"] or []
            if theirs != mine:
                raise UsageError(
                    f"--out {out} holds results of {_describe(theirs)}, not "
                    f"{_describe(mine)}: give another --out, or --force to replace them")
    try:  # before the run, so a bad folder costs nothing
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {out}: cannot create the output folder: {exc.strerror}") from None
    return mine


def write_provenance(out: Path, record: dict) -> Path:
    """Write ``out/satellite.json`` (whose results the folder holds)."""
    path = out / "satellite.json"
    path.write_text(json.dumps(record, indent=2) + "\n")
    return path


def check_status(res) -> None:
    """Raise :class:`Interrupted` or :class:`RunFailed` for a run that did not end ok
    (call after its output is written)."""
    interrupted_early(res)
    if res.status == "interrupted":
        raise Interrupted(f"the output holds the run up to t = {res.t[-1]:.6g} s")
    if res.status != "ok":
        raise RunFailed(res.message)


def interrupted_early(res) -> None:
    """Raise :class:`Interrupted` for Ctrl-C before a second output sample: nothing to
    summarise or write (call right after the run)."""
    if res.status == "interrupted" and res.t.size < 2:
        raise Interrupted(f"at t = {res.t[-1]:.6g} s, before the first output sample: "
                          f"nothing written")
