"""``tethersim feasibility``: does the design work in a real orbit?

Per start altitude (and balloon area): when the free, decaying orbit loses its
balloon and when it re-enters, the settling time of the thesis's held circular orbit, and whether the pitch
trim holds across the solar cycle's air (docs/feasibility.md).  Writes
``feasibility.csv``, ``feasibility.png`` and a resumable store under ``--out``.
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options

HELP = ("balloon lost, re-entry, settling and trim across altitudes: does the design work in "
        "a real orbit?")


def add_parser(sub) -> None:
    """Declare ``feasibility`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "feasibility", help=HELP,
        description="For each start altitude (and balloon area): when the free orbit loses "
                    "its balloon (a tether beyond its stretch limit) and when it re-enters "
                    "(the boom alone, after the tether breaks; capped), the settling time of "
                    "the held circular orbit, and whether the trim |theta_ss| <= 0.05 rad "
                    "holds with the density scaled to NRLMSISE-00's solar minimum/mean/"
                    "maximum; a verdict per point, decided at two tolerances ('sensitive' "
                    "where they differ), 'undecided: run longer' where --periods is too "
                    "short to decide and 'undecided: raise the lifetime cap' where the "
                    "answer turns on a life longer than --max-lifetime.  Resumable: run "
                    "the same command again.")
    options.add_satellite(p)
    p.add_argument("--altitude", required=True, metavar="GRID",
                   help="start altitudes [km], START:STOP:COUNT or a comma list, e.g. "
                        "200:400:5")
    p.add_argument("--A3", default=None, metavar="GRID",
                   help="balloon areas [m^2] (default: the satellite's)")
    p.add_argument("--solar", default="min,mean,max", metavar="CASES",
                   help="solar cases of the trim runs (default min,mean,max)")
    options.add_periods(p, help="orbits per circular run (default 50: three days); a "
                                "verdict that needs a longer run says 'undecided: run "
                                "longer' and the periods_to_decide column says how long")
    p.add_argument("--max-lifetime", type=options.positive_float, default=240.0, metavar="H",
                   help="cap on the free run [h] (default 240: ten days); a verdict that "
                        "turns on a longer life says 'undecided: raise the lifetime cap'")
    p.add_argument("--workers", type=options.positive_int, default=None, metavar="N",
                   help="threads (default: every core; at most 4 per core)")
    p.add_argument("--rtol", type=options.rtol_float, default=1e-10,
                   help="relative tolerance of every run (default 1e-10); the "
                        "verdict's runs are repeated at rtol/100 and a verdict that differs "
                        "is reported as 'sensitive'")
    p.add_argument("--method", choices=("adaptive", "implicit"), default="adaptive",
                   help="scheme of every run: adaptive DOP853 (default) or implicit Radau IIA, "
                        "for real (stiff) lines (--tethers; docs/real-tethers.md)")
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
    from tethersim.cli import preflight
    from tethersim.experiments.feasibility import FeasibilitySpec, run_feasibility
    from tethersim.model import params
    from tethersim.model.registry import BY_NAME
    from tethersim.output.plots.feasibility import plot_feasibility
    from tethersim.output.tables import write_rows
    if BY_NAME[args.model].orbit == "free":  # before options.satellite makes the orbit free
        raise options.UsageError(f"--model {args.model}: feasibility takes a circular-orbit "
                                 f"model; it runs the trim on the held circular orbit and the "
                                 f"lifetime with the model's free twin")
    preflight.check_workers(args, "workers")
    from tethersim.cli.overrides import refuse
    from tethersim.experiments.feasibility import ATLAS_FIELDS
    refuse(args, ("altitude", "A3") if args.A3 else ("altitude",),
           lambda n: f"the atlas sets {n} per point from --{n}: give the values there")
    refuse(args, [{"density_mode": "density"}.get(f, f) for f in ATLAS_FIELDS],
           lambda n: f"the atlas sets {n} itself (circular orbit in uniform Vallado air scaled "
                     f"per solar case; free orbit in per-body Vallado and NRLMSISE-00 air): "
                     f"drop it")
    sat = options.satellite(args)
    altitudes = tuple(float(v) for v in params.parse_grid("altitude", args.altitude))
    areas = (tuple(float(v) for v in params.parse_grid("A3", args.A3)) if args.A3 else ())
    solar = tuple(s.strip() for s in args.solar.split(",") if s.strip())
    from tethersim.engine.guards import SizeLimitError
    try:
        spec = FeasibilitySpec(sat, altitudes, areas, solar, periods=args.periods,
                               max_lifetime_h=args.max_lifetime, model=args.model,
                               rtol=args.rtol, method=args.method)
    except SizeLimitError as exc:  # the option that sets the refused run, not the field
        names = {"periods": "--periods", "max_lifetime_h": "--max-lifetime"}
        raise exc.naming(names.get(exc.subject, exc.subject)) if exc.subject else exc from None
    out = Path(args.out) if args.out else options.default_out(args, "feasibility")
    preflight.check_files(out, ("feasibility.csv", "feasibility.png"))
    preflight.check_subfolder(out, "store")
    if args.force:  # replace another atlas's store
        import shutil
        shutil.rmtree(out / "store", ignore_errors=True)
    from tqdm.auto import tqdm

    if not args.quiet:
        print(f"{len(spec.points())} point(s), up to {spec.runs_per_point()} runs each "
              f"({spec.periods:g}-orbit circular runs at rtol {spec.rtol:g} and "
              f"{spec.check_rtol:g}, free runs capped at {spec.max_lifetime_h:g} h) -> "
              f"{out}")
    rows = run_feasibility(spec, out / "store", workers=args.workers,
                           log=(lambda *a: None) if args.quiet else tqdm.write,
                           progress=options.progress(args))
    csv = write_rows(out / "feasibility.csv", rows)
    png = plot_feasibility(rows, out / "feasibility.png", title=f"{sat.name}: does the design "
                                                                 f"work in a real orbit?")
    for r in rows:
        print(f"{r['altitude_km']:7.1f} km  A3 {r['A3_m2']:6.3g} m^2  balloon lost "
              f"{r['balloon_lost_h']:8.3g} h  re-entry "
              f"{'>=' if r['reentry_capped'] else '  '}{r['reentry_h']:8.3g} h  settling "
              f"{r['settling_h']:8.3g} h  {_verdict_text(r)}")
    print(f"wrote {csv} and {png}")
    return 0


def _verdict_text(r: dict) -> str:
    """The verdict with what it needs: the run length to decide, or both tolerances."""
    if r["verdict"] == "sensitive":
        return (f"sensitive: {r['verdict_rtol']} at rtol {r['rtol']:g}, "
                f"{r['verdict_check_rtol']} at rtol {r['check_rtol']:g}")
    if r["verdict"] == "undecided: raise the lifetime cap":
        return f"{r['verdict']} (the free orbit outlived --max-lifetime {r['reentry_h']:g} h)"
    if r["verdict"].startswith("undecided"):
        return f"{r['verdict']} (--periods >= {r['periods_to_decide']})"
    return r["verdict"]
