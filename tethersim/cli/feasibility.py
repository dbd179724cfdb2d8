"""``tethersim feasibility``: does the design work in a real orbit?

Per start altitude (and balloon area): the lifetime of the free, decaying orbit,
the settling time of the thesis's held circular orbit, and whether the pitch
trim holds across the solar cycle's air (docs/feasibility.md).  Writes
``feasibility.csv``, ``feasibility.png`` and a resumable store under ``--out``.
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options

HELP = "lifetime, settling and trim across altitudes: does the design work in a real orbit?"


def add_parser(sub) -> None:
    """Declare ``feasibility`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "feasibility", help=HELP,
        description="For each start altitude (and balloon area): the lifetime of the free "
                    "orbit (run until re-entry, capped), the settling time of the held "
                    "circular orbit, and whether the trim |theta_ss| <= 0.05 rad holds with "
                    "the density scaled to NRLMSISE-00's solar minimum/mean/maximum; a "
                    "verdict per point.  Resumable: run the same command again.")
    options.add_satellite(p)
    p.add_argument("--altitude", required=True, metavar="GRID",
                   help="start altitudes [km], START:STOP:COUNT or a comma list, e.g. "
                        "200:400:5")
    p.add_argument("--A3", default=None, metavar="GRID",
                   help="balloon areas [m^2] (default: the satellite's)")
    p.add_argument("--solar", default="min,mean,max", metavar="CASES",
                   help="solar cases of the trim runs (default min,mean,max)")
    options.add_periods(p, help="orbits per circular run (default 50: three days)")
    p.add_argument("--max-lifetime", type=options.positive_float, default=240.0, metavar="H",
                   help="cap on the free run [h] (default 240: ten days)")
    p.add_argument("--workers", type=options.positive_int, default=None, metavar="N",
                   help="threads (default 1)")
    options.add_model(p)
    options.add_out(p, "results/<satellite>/feasibility")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run, interrupted_hint="run the same command again to continue")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``feasibility``.

    Returns
    -------
    int
        0.
    """
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    from tethersim.model import params
    from tethersim.model.registry import BY_NAME
    from tethersim.output.plots.feasibility import plot_feasibility
    from tethersim.output.tables import write_rows
    if BY_NAME[args.model].orbit == "free":  # before options.satellite makes the orbit free
        raise options.UsageError(f"--model {args.model}: feasibility takes a circular-orbit "
                                 f"model; it runs the trim on the held circular orbit and the "
                                 f"lifetime with the model's free twin")
    sat = options.satellite(args)
    altitudes = tuple(float(v) for v in params.parse_grid("altitude", args.altitude))
    areas = (tuple(float(v) for v in params.parse_grid("A3", args.A3)) if args.A3 else ())
    solar = tuple(s.strip() for s in args.solar.split(",") if s.strip())
    spec = FeasibilitySpec(sat, altitudes, areas, solar, periods=args.periods,
                           max_lifetime_h=args.max_lifetime, model=args.model)
    out = Path(args.out) if args.out else options.default_out(args, "feasibility")
    if args.force:  # replace another atlas's store
        import shutil
        shutil.rmtree(out / "store", ignore_errors=True)
    rows = run_feasibility(spec, out / "store", workers=args.workers,
                           log=(lambda *a: None) if args.quiet else print)
    csv = write_rows(out / "feasibility.csv", rows)
    png = plot_feasibility(rows, out / "feasibility.png", title=f"{sat.name}: does the design "
                                                                 f"work in a real orbit?")
    for r in rows:
        print(f"{r['altitude_km']:7.1f} km  A3 {r['A3_m2']:6.3g} m^2  lifetime "
              f"{'>=' if r['lifetime_capped'] else '  '}{r['lifetime_h']:8.3g} h  settling "
              f"{r['settling_h']:8.3g} h  {r['verdict']}")
    print(f"wrote {csv} and {png}")
    return 0
