"""``tethersim run``: simulate one satellite; write time series, plots and a summary.

Writes timeseries.csv, timeseries.nc (NetCDF), the theta/delta_x/delta_y/overview/tensions
PNGs and summary.json into ``results/<satellite>/`` (or ``--out``).  summary.json
also records whose results the folder holds, so a run of another satellite (or
other --set/--scale, or another model) into the same folder is refused unless
``--force``, and the files it wrote, so a later run removes those it does not write.
"""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.cli import options

HELP = "simulate a satellite, write time series, plots and a summary"
PERIODS = 50.0  # default run length [orbits]
# --until reentry: the default cap [h] (feasibility's --max-lifetime default too)
REENTRY_CAP_H = 240.0


def add_parser(sub) -> None:
    """Declare ``run`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "run", help=HELP,
        description="Simulate a satellite; write timeseries.csv, timeseries.nc (NetCDF), "
                    "theta/delta_x/delta_y/overview/tensions PNGs and summary.json.")
    options.add_satellite(p)
    options.add_periods(p, default=None,
                        help=f"orbits to simulate (default {PERIODS:g}); with --until reentry "
                             f"the most orbits to run (default {REENTRY_CAP_H:g} h worth)")
    p.add_argument("--until", choices=("periods", "reentry"), default="periods",
                   help="periods: run --periods orbits (default); reentry (free orbits): run "
                        "until the orbit re-enters (or the run leaves the model's domain), "
                        "at most --periods orbits")
    options.add_integrator(p)
    options.add_model(p, "; see docs/errata.md")
    options.add_atol(p)
    options.add_start(p)
    p.add_argument("--beads", type=int, default=None, metavar="N",
                   help="each tether a chain of N point-mass beads, 0-64 (line masses: --set "
                        "mt1=... mt2=... [kg]); adds tether_shape.png; docs/beads.md")
    options.add_out(p, "results/<satellite>, e.g. results/satI")
    p.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    p.add_argument("--no-check", action="store_true",
                   help="skip the convergence check (a second run at half step / rtol/100)")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``run``.

    Returns
    -------
    int
        0; a diverged or interrupted run raises :class:`options.RunFailed` or
        :class:`options.Interrupted` after its output is written.
    """
    from tethersim.analysis.summary import run_summary
    from tethersim.cli import preflight
    from tethersim.engine.simulate import simulate
    from tethersim.output.plots.run import FILE_NAMES as PLOT_NAMES
    from tethersim.output.plots.run import TENSIONS_FILE, plot_result
    from tethersim.output.plots.shape import SHAPE_FILE, plot_shape
    from tethersim.output.tables import write_netcdf, write_timeseries

    sat = options.satellite(args)
    if args.beads is not None:  # before the folder's record: a chain's results are its own
        from tethersim.model.bead_layout import check_beads
        sat = sat.replace(beads=check_beads(args.beads))
    from tethersim.cli.overrides import refuse_unused
    refuse_unused(args, sat, (args.model,))  # its run would equal one without it
    cap = _resolve_periods(args, sat)
    how = options.integrator(args)
    out = Path(args.out) if args.out else options.default_out(args)
    preflight.check_run_size(args, how, "--periods/--steps", check=not args.no_check)
    plots = () if args.no_plots else (
        "overview.png", "altitude.png", TENSIONS_FILE, SHAPE_FILE,
        *(f"{n}.png" for n in PLOT_NAMES.values()))
    preflight.check_files(out, ("timeseries.csv", "timeseries.nc", "summary.json", *plots))
    record = options.claim_folder(out, args, sat)
    res = simulate(sat, periods=args.periods, steps=how.steps, method=how.method,
                   model=args.model, rtol=how.rtol, atol=args.atol, locate_switches=how.locate,
                   samples=how.samples, check=not args.no_check,
                   progress=options.progress(args), start=args.start)
    options.interrupted_early(res)
    write_timeseries(res, out / "timeseries.csv")
    write_netcdf(res, out / "timeseries.nc")
    written = [out / "timeseries.csv", out / "timeseries.nc"]
    if not args.no_plots:
        written += plot_result(res, out)
        if res.satellite.beads is not None:  # a chain (--beads, or lines held off the ends)
            written.append(plot_shape(res, out))
    summary = run_summary(res)
    strict = {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
              for k, v in summary.items()}  # NaN is not JSON: null means "never settled"
    strict["integrator"] = how.describe(sat.period, args.periods)
    if args.until == "reentry":
        strict["until"] = cap
    strict.update(record)  # whose results these are: checked by the next run into `out`
    written.append(options.write_record(out, "summary.json", strict, written))
    print(how.describe(sat.period, args.periods)
          + (f"; until re-entry, {cap}" if args.until == "reentry" else f"; {args.periods:g} orbits"))
    for k, v in summary.items():
        print(f"  {k:<32} {v:.6g}" if isinstance(v, float) else f"  {k:<32} {v}")
    print("wrote " + ", ".join(str(p) for p in written))
    if args.until == "reentry" and res.status == "re-entered":
        return 0  # the end asked for
    options.check_status(res)
    return 0


def _resolve_periods(args, sat) -> str:
    """Set ``args.periods`` (the run length, or --until reentry's cap) and return the cap's
    description; refuse --until reentry on a circular orbit (it never re-enters)."""
    if args.until != "reentry":
        args.periods = PERIODS if args.periods is None else args.periods
        return ""
    if sat.orbit != "free":
        raise options.UsageError("--until reentry: needs a free orbit (--set orbit=free or a "
                                 "free-orbit --model); the circular orbit is held at its "
                                 "altitude and never re-enters")
    if args.periods is None:
        args.periods = REENTRY_CAP_H * 3600 / sat.period
        return f"at most {REENTRY_CAP_H:g} h ({args.periods:.4g} orbits)"
    return f"at most {args.periods:g} orbits ({args.periods * sat.period / 3600:.4g} h)"
