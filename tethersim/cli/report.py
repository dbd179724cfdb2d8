"""``tethersim report``: the whole of thesis chapter 5 as one HTML page.

Validation tables, nominal runs, SatI's headline cases faithful and converged,
force breakdowns, stability maps and the thesis's statements beside ours.
Sweeps are resumable: run the same command again after an interruption.
"""
from __future__ import annotations

import time
from pathlib import Path

from tethersim.cli import options

HELP = "the whole of thesis chapter 5 as one HTML page"


def add_parser(sub) -> None:
    """Declare ``report`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "report", help=HELP,
        description="Validation tables, nominal runs, SatI's headline cases faithful and "
                    "converged, force breakdowns, six stability maps (converged, faithful, "
                    "predicted), the design in a real orbit, roll and yaw in the 3-D models "
                    "(docs/roll.md) and a table of the thesis's statements beside ours.  "
                    "Sweeps are resumable: run again after an interruption.")
    p.add_argument("--out", default="results/report", metavar="DIR",
                   help="output folder (default results/report; the report covers every "
                        "preset, so it has no per-satellite folder)")
    p.add_argument("--grid", type=options.int_range(2, 201), default=41, metavar="N",
                   help="points per map axis (default 41, the thesis's sweep, p. 5-18)")
    options.add_periods(p, help="orbits per run of the nominal runs, forces and maps "
                                "(default 50); the headline cases keep the thesis's own "
                                "run lengths")
    p.add_argument("--workers", type=options.positive_int, default=None, metavar="N",
                   help="threads (default: every core; at most 4 per core)")
    p.add_argument("--no-roll", action="store_true",
                   help="leave out the roll section (the 3-D models; their first compile "
                        "takes a minute or two)")
    options.add_quiet(p)
    p.set_defaults(func=run, interrupted_hint="the finished sweeps are kept under "
                                              "{out}/sweeps: run the same command again "
                                              "to continue")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``report``.

    Returns
    -------
    int
        0.
    """
    from tethersim.cli import preflight
    from tethersim.output.report import build_report

    preflight.check_workers(args, "workers")
    preflight.check_folder(Path(args.out))
    preflight.check_subfolder(Path(args.out), "img")
    t0 = time.perf_counter()
    path = build_report(Path(args.out), grid=args.grid, periods=args.periods,
                        workers=args.workers, progress=options.progress(args),
                        roll=not args.no_roll)
    print(f"wrote {path} in {time.perf_counter() - t0:.0f} s")
    return 0
