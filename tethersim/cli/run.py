"""``tethersim run``: simulate one satellite; write time series, plots and a summary.

Writes timeseries.csv, timeseries.nc (NetCDF), the theta/delta_x/delta_y/overview
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


def add_parser(sub) -> None:
    """Declare ``run`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "run", help=HELP,
        description="Simulate a satellite; write timeseries.csv, timeseries.nc (NetCDF), "
                    "theta/delta_x/delta_y/overview PNGs and summary.json.")
    options.add_satellite(p)
    options.add_periods(p)
    options.add_integrator(p)
    options.add_model(p, "; see docs/errata.md")
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
    from tethersim.engine.simulate import simulate
    from tethersim.output.plots.run import plot_result
    from tethersim.output.tables import write_netcdf, write_timeseries

    sat = options.satellite(args)
    how = options.integrator(args)
    out = Path(args.out) if args.out else options.default_out(args)
    record = options.claim_folder(out, args, sat)
    res = simulate(sat, periods=args.periods, steps=how.steps, method=how.method,
                   model=args.model, rtol=how.rtol, locate_switches=how.locate,
                   samples=how.samples, check=not args.no_check,
                   progress=options.progress(args))
    options.interrupted_early(res)
    write_timeseries(res, out / "timeseries.csv")
    write_netcdf(res, out / "timeseries.nc")
    written = [out / "timeseries.csv", out / "timeseries.nc"]
    if not args.no_plots:
        written += plot_result(res, out)
    summary = run_summary(res)
    strict = {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
              for k, v in summary.items()}  # NaN is not JSON: null means "never settled"
    strict["integrator"] = how.describe(sat.period, args.periods)
    strict.update(record)  # whose results these are: checked by the next run into `out`
    written.append(options.write_record(out, "summary.json", strict, written))
    print(how.describe(sat.period, args.periods) + f"; {args.periods:g} orbits")
    for k, v in summary.items():
        print(f"  {k:<32} {v:.6g}" if isinstance(v, float) else f"  {k:<32} {v}")
    print("wrote " + ", ".join(str(p) for p in written))
    options.check_status(res)
    return 0
