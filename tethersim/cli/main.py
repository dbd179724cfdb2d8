"""Command line: ``tethersim run | validate | show | equilibrium | compare | forces | sweep |
tune | report | headlines | feasibility | design | mc | deorbit | deploy``.

One module per command (``tethersim/cli/<command>.py``, each with ``add_parser(sub)``
and ``run(args)``) over the option groups of :mod:`tethersim.cli.options`.  This
module builds the parser and is the one place where errors, warnings and
interruptions become messages and exit codes:

- 0: done; 1: a run diverged or failed (its output is written);
- 2: bad input, one line ``tethersim: error: ...`` naming the option;
- 130: Ctrl-C or SIGTERM, one line (the finished work is written).

``tethersim CMD --help`` for each command.  Units at this edge: docs/conventions.md;
--set/--scale units: tethersim.model.params.
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
import warnings

from tethersim._version import __version__
from tethersim.cli import (
    compare,
    deorbit,
    deploy,
    design,
    equilibrium,
    feasibility,
    forces,
    headlines,
    mc,
    options,
    report,
    run,
    show,
    sweep,
    tune,
    validate,
)

# in the order of `tethersim --help`
COMMANDS = (run, validate, show, equilibrium, compare, forces, sweep, tune, report, headlines,
            feasibility, design, mc, deorbit, deploy)
# the options that set a command's run sizes: simulate()'s size refusal, which names its
# own arguments, names these instead (a command without --steps never blames --steps)
SIZE_OPTIONS = {"run": "--periods/--steps", "compare": "--periods/--steps",
                "forces": "--periods/--steps", "validate": "--periods", "sweep": "--periods",
                "tune": "--periods", "report": "--periods", "headlines": "--periods",
                "feasibility": "--periods/--max-lifetime",
                "design": "--periods/--max-lifetime", "mc": "--periods/--max-lifetime",
                "deorbit": "--from/--n/--max-years", "deploy": "--periods/--sample"}


def build_parser() -> options.Parser:
    """The ``tethersim`` parser with one subcommand per module of :data:`COMMANDS`.

    Returns
    -------
    options.Parser
        Usage errors raise :class:`options.UsageError` instead of exiting.
    """
    parser = options.Parser(
        prog="tethersim",
        description="Gravity-gradient satellite with a tethered drag balloon (Maramba, AFIT "
                    "2005). SI units inside; conventions in docs/conventions.md.")
    parser.add_argument("--version", action="version", version=f"tethersim {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for command in COMMANDS:
        command.add_parser(sub)
    return parser


def _raise_interrupt(signum, frame):
    raise KeyboardInterrupt


@contextlib.contextmanager
def _sigterm_as_interrupt():
    """SIGTERM (kill) handled like Ctrl-C while inside: finished work is written."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGTERM, _raise_interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _show_warning(message, category, filename, lineno, file=None, line=None):
    print(f"tethersim: warning: {category.__name__}: {message}", file=sys.stderr, flush=True)


def main(argv=None) -> int:
    """Run the ``tethersim`` command line.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name (default ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 done, 1 a run failed, 2 bad input, 130 interrupted.
        ``--help`` and ``--version`` exit through ``SystemExit(0)`` as argparse does.

    Examples
    --------
    >>> main(["show", "satI"])  # doctest: +SKIP
    0
    """
    # a sweep's SweepInterrupted is a KeyboardInterrupt: importing it here would load the
    # sweep store's xarray and zarr (0.3 s) into every command
    from tethersim.model.satellite import SatelliteError

    try:
        args = build_parser().parse_args(argv)
    except options.UsageError as exc:
        return _error(exc)
    try:
        with warnings.catch_warnings(), _sigterm_as_interrupt():
            warnings.simplefilter("always")
            warnings.showwarning = _show_warning
            return args.func(args)
    except BrokenPipeError:
        # the reader went away (`tethersim show satI | head`): not an error of the input;
        # point stdout at devnull so the interpreter's final flush does not complain either
        with contextlib.suppress(OSError, ValueError):  # in-process stdout may have no fd
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except (options.UsageError, SatelliteError, ValueError, OSError) as exc:
        return _error(_named(exc, args.command))
    except options.RunFailed as exc:
        print(f"tethersim: error: the run failed: {exc}", file=sys.stderr)
        return 1
    except (options.Interrupted, KeyboardInterrupt) as exc:
        # the command's hint says how to continue (sweep, report); {out} is its folder
        hint = getattr(args, "interrupted_hint", "").format(out=args.out if "out" in args else "")
        detail = "; ".join(s for s in (str(exc), hint) if s)
        print("tethersim: interrupted" + (f": {detail}" if detail else ""), file=sys.stderr)
        return 130


def _named(exc, command: str):
    """A size refusal of simulate() naming the command's options, not simulate()'s arguments."""
    from tethersim.engine.guards import API_SUBJECT, SizeLimitError
    if isinstance(exc, SizeLimitError) and exc.subject == API_SUBJECT and command in SIZE_OPTIONS:
        return exc.naming(SIZE_OPTIONS[command])
    return exc


def _error(exc) -> int:
    """Bad input: one line on stderr, exit code 2."""
    print(f"tethersim: error: {exc}", file=sys.stderr)
    return 2

if __name__ == "__main__":
    raise SystemExit(main())
