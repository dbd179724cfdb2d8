"""``tethersim sweep``: a stability map over one or two parameters.

Runs a grid of simulations over one or two parameters (thesis Figs 5.13,
5.21-5.28), classifies each point (docs/metrics.md) and draws the stability
map.  Grids are START:STOP:COUNT (ends included) or a comma list, in the
units of ``--set``.  Results go to a resumable Zarr store in
``results/<satellite>/sweep-<axes>[-faithful]`` (or ``--out``): the same
command continues an interrupted sweep.
"""
from __future__ import annotations

import argparse
from pathlib import Path

from tethersim.cli import options, parallel

HELP = "stability map over one or two parameters (thesis Figs 5.13, 5.21-5.28)"
SHOWN_AXES = ("E1", "E2", "c1", "c2")  # in --help; every parameter of `show` works


def add_parser(sub) -> None:
    """Declare ``sweep`` and its options on the subparsers ``sub``."""
    from tethersim.cli.overrides import Once
    from tethersim.model.params import NAMES, unit

    p = sub.add_parser(
        "sweep", help=HELP,
        description="Run a grid of simulations over one or two preset parameters, classify "
                    "each point (docs/metrics.md) and draw the stability map.  Grids: "
                    "START:STOP:COUNT (ends included) or a comma list, in the units of --set "
                    "(E in N/mm^2, altitude in km, else SI).  Results go to a resumable Zarr "
                    "store: run the same command again after an interruption to continue.")
    options.add_satellite(p)
    g = p.add_argument_group("grid axes")
    for n in NAMES:
        g.add_argument(f"--{n}", metavar="GRID", default=None, action=Once,
                       help=argparse.SUPPRESS if n not in SHOWN_AXES else
                       f"grid of {n} [{unit(n)}], e.g. 0:0.02:41 (any parameter of "
                       f"'tethersim show' works the same way)")
    options.add_periods(p, help="orbits per run (default 50: three days, thesis p. 5-6)")
    options.add_integrator(p, rtol=1e-9, fixed_step=False)
    options.add_model(p)
    parallel.add_parallel(p)
    options.add_out(p, "results/<satellite>/sweep-<axes>[-faithful]")
    p.add_argument("--restart", action="store_true", help="discard a previous store in --out")
    p.add_argument("--no-plots", action="store_true", help="skip the stability map PNG")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run, interrupted_hint="run the same command again to continue")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``sweep``.

    Returns
    -------
    int
        0; an interrupted sweep raises (main reports it, exit 130).

    Raises
    ------
    options.UsageError
        No grid or more than two, or several of --workers, --dask-workers, --scheduler.
    """
    import math
    from types import SimpleNamespace

    from tethersim.analysis.classify import UNDECIDED, describe
    from tethersim.cli import preflight
    from tethersim.cli.overrides import refuse, refuse_unused
    from tethersim.engine.guards import check_sweep
    from tethersim.experiments.sweep import SweepSpec, run_sweep
    from tethersim.experiments.sweep.analysis import (
        band_slope,
        class_counts,
        class_names,
        status_counts,
    )
    from tethersim.experiments.sweep.batch import check_point_size
    from tethersim.experiments.sweep.store import status_names
    from tethersim.model import params
    from tethersim.output.plots.sweep import plot_stability_map
    from tethersim.output.tables import write_table

    # Ctrl-C before the store exists leaves nothing to continue: no hint until then
    hint, args.interrupted_hint = args.interrupted_hint, ""
    refuse(args, [n for n in params.NAMES if getattr(args, n) is not None],
           lambda n: f"{n} is a sweep axis (--{n}): the grid gives its values; put the "
                     f"values you want in --{n}")
    sat = options.satellite(args)
    axes = [(n, params.parse_grid(n, getattr(args, n))) for n in params.NAMES
            if getattr(args, n) is not None]
    check_sweep([len(v) for _, v in axes], [n for n, _ in axes])  # at once, before any work
    # a setting or axis the model ignores would give identical points
    refuse_unused(args, sat, (args.model,), [n for n, _ in axes])
    if not 1 <= len(axes) <= 2:
        raise options.UsageError(
            f"give one or two grids, e.g. --E1 0:0.02:41 --E2 0:0.06:41; got "
            f"{len(axes)} ({', '.join(n for n, _ in axes) or 'none'})")
    parallel.check_parallel(args)
    how = options.integrator(args)
    method = "faithful" if how.faithful else how.method  # adaptive or implicit
    # every refusal before the spec (whose points' check takes a while on a large grid),
    # the folder and the store: a refused sweep leaves nothing that blocks the rerun
    check_point_size(SimpleNamespace(periods=args.periods, method=method,
                                     steps_per_period=SweepSpec.steps_per_period,
                                     samples_per_period=SweepSpec.samples_per_period),
                     subject="--periods")
    names = "-".join(n for n, _ in axes)
    out = Path(args.out) if args.out else options.default_out(
        args, f"sweep-{names}{'-faithful' if how.faithful else ''}")
    preflight.check_files(out, ("sweep.csv", "stability_map.png", "satellite.json"))
    preflight.check_subfolder(out, "sweep.zarr")
    # the store runs --faithful at FAITHFUL_STEPS_PER_PERIOD, the one faithful step
    spec = SweepSpec(sat, tuple(axes), periods=args.periods, method=method, model=args.model,
                     rtol=how.rtol, progress=options.progress(args))
    record = options.claim_folder(out, args, sat)
    print(f"{spec.size} runs of {spec.periods:g} orbits "
          f"({how.describe(sat.period, args.periods)}, model {spec.model}) "
          f"-> {out / 'sweep.zarr'}")
    args.interrupted_hint = hint
    store = run_sweep(spec, out / "sweep.zarr", workers=args.workers,
                      scheduler=args.scheduler, dask_workers=args.dask_workers,
                      restart=args.restart, progress=options.progress(args))
    ds = store.dataset()
    table = ds.drop_vars("done")
    columns = tuple((n, f"{n} [{table[n].attrs.get('units', '1')}]" if n != "status" else n)
                    for n in (*table.dims, *table.data_vars))
    # the status by the engine's name (ok, diverged, left-domain ...), not its code
    table["status"] = (table.status.dims, status_names(ds))
    table["class"] = (table.stability_class.dims, class_names(ds))  # the code's name
    columns += (("class", "class"),)
    write_table(out / "sweep.csv", table.to_dataframe().reset_index().to_dict("records"), columns)
    written = [out / "sweep.zarr", out / "sweep.csv"]
    slope = band_slope(ds) if spec.names == ("E1", "E2") else float("nan")
    if len(spec.names) == 2 and not args.no_plots:
        nominal = {n: params.edge_value(sat, n) for n in spec.names}
        written.append(plot_stability_map(ds, out / "stability_map.png", nominal=nominal,
                                          band_slope=slope))
    written.append(options.write_provenance(out, record, written))
    for name, n in class_counts(ds).items():
        hint = describe(UNDECIDED)[len(name):] if name == "undecided" and n else ""
        print(f"  {name:<12} {n}{hint}")
    not_ok = {s: n for s, n in status_counts(ds).items() if s != "ok" and n}
    if not_ok:  # their NaN metrics have a reason: say it, and how to see the message
        print(f"  {sum(not_ok.values())} point(s) did not finish ok "
              f"({', '.join(f'{n} {s}' for s, n in not_ok.items())}; metrics NaN): "
              f"'tethersim run' one with --set for its message")
    if math.isfinite(slope):
        print(f"  stable band centre: {spec.names[1]} = {slope:.4g} x {spec.names[0]}")
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
