"""``tethersim deploy``: the end of a deployment on the satellite's lines.

Starts the satellite at the end of a braked deployment (``--speeds``: the balloon at its
trim point, moving outward at each speed) and as free releases (``--release``: the
balloon let go at rest that far behind the COM, its lines slack), runs each on the
implicit scheme (tethersim.experiments.deployment) and writes deployment.csv (one row
per start: the first catch's peak tension, the largest, the safety factor, the boom's
pitch excursion, whether it turned over; and the class and settling time of a second,
``--settle-periods`` run on the metrics grid) and deployment.png into
``results/<satellite>/deploy`` (or ``--out``).  docs/real-tethers.md, "Deployment".
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options

HELP = "the catch at the end of a deployment: snap tensions and the boom's pitch"
SPEEDS = "0.01,0.03,0.1,0.3,1,3"  # m/s: the default arrival speeds
PITCH_POINTS = 4000  # samples of each start's θ(t) kept for the plot


def add_parser(sub) -> None:
    """Declare ``deploy`` and its options on the subparsers ``sub``."""
    from tethersim.experiments.deployment import (
        PLANAR,
        REAL_MODEL,
        RELEASE,
        SAMPLE,
        SETTLE_PERIODS,
    )
    p = sub.add_parser(
        "deploy", help=HELP,
        description="Start the satellite at the end of a braked deployment (--speeds: the "
                    "balloon at its trim point moving outward) and as free releases "
                    "(--release: let go at rest behind the COM, lines slack); run each on the "
                    "implicit scheme and write deployment.csv (first catch's peak tension, "
                    "largest tension, safety factor, pitch excursion, turned over, and the "
                    "class and settling time of a --settle-periods run) and deployment.png. "
                    "Real lines: --tethers MATERIAL:DIAMETER_MM.")
    options.add_satellite(p)
    options.add_periods(p, default=1.0)
    p.add_argument("--speeds", default=SPEEDS, metavar="V,V,...",
                   help=f"arrival speeds [m/s], a list or start:stop:count (default {SPEEDS}); "
                        f"'' for none")
    p.add_argument("--release", default=None, metavar="D,D,...",
                   help=f"free-release distances behind the COM [m], the balloon clear of the "
                        f"boom (default {RELEASE:g} where the lines reach past it, else none: "
                        f"the thesis's 6 m tethers cannot); '' for none")
    p.add_argument("--sample", type=options.positive_float, default=SAMPLE, metavar="S",
                   help=f"output grid [s] (default {SAMPLE:g}: finer than a real line's catch, "
                        f"which lasts tens of ms)")
    p.add_argument("--settle-periods", type=float, default=SETTLE_PERIODS, metavar="N",
                   help=f"orbits of each start's settling run, on the 200-per-orbit metrics "
                        f"grid: class and settling time (default {SETTLE_PERIODS:g}; 0: none)")
    p.add_argument("--model", choices=PLANAR, default=REAL_MODEL,
                   help=f"model variant (default {REAL_MODEL}: the damper on the stretch rate, "
                        f"as a line's material loss)")
    options.add_out(p, "results/<satellite>/deploy")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def _starts(args, sat) -> list:
    """The starts of --speeds and --release, each checked before anything runs."""
    from tethersim.experiments.deployment import MAX_SPEED, starts
    from tethersim.model.params import parse_grid
    todo = []
    for option, key, what in (("speeds", "speeds", f"speeds 0 to {MAX_SPEED:g} m/s"),
                              ("release", "releases", "distances behind the COM in m")):
        text = getattr(args, option)
        if text is None:  # the default release, where the satellite's lines allow one
            todo += _default_release(args, sat)
            continue
        try:
            values = [] if not text.strip() else [float(v) for v in parse_grid(option, text)]
        except ValueError as exc:
            raise options.UsageError(f"{exc} (expected {what})") from None
        try:
            todo += starts(sat, model=args.model, **{key: values})
        except ValueError as exc:
            raise options.UsageError(f"--{option}: {exc}") from None
    if not todo:
        raise options.UsageError("--speeds and --release are both empty: nothing to deploy")
    return todo


def _default_release(args, sat) -> list:
    """The default free release (RELEASE behind the COM), or none, said in one line, when
    the satellite's lines cannot reach past the balloon beside the boom."""
    from tethersim.experiments.deployment import RELEASE, starts
    try:
        return starts(sat, releases=(RELEASE,), model=args.model)
    except ValueError as exc:
        print(f"no free release: {exc}")
        return []


def _check_sizes(args, sat) -> None:
    """Refuse, before anything runs, a catch grid or a settling run that would not fit."""
    import math

    from tethersim.analysis.metrics import min_run_orbits
    from tethersim.engine.guards import check_simulation
    from tethersim.experiments.deployment import check_sample, samples
    try:
        check_sample(sat, args.sample)
        samples(args.periods, sat.period, args.sample)
    except ValueError as exc:
        raise options.UsageError(f"--periods/--sample: {exc}") from None
    low = math.ceil(min_run_orbits())
    n = args.settle_periods
    if not (n == 0 or (math.isfinite(n) and n >= low)):
        raise options.UsageError(f"--settle-periods {n:g}: 0 (no settling run) or at least "
                                 f"{low} orbits (a shorter run decides no class, "
                                 f"docs/metrics.md)")
    if n:
        check_simulation(n, check=False, subject="--settle-periods")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``deploy``.

    Returns
    -------
    int
        0; an interrupted command raises :class:`options.Interrupted` after the rows
        of the starts it finished are written.
    """
    from tqdm.auto import tqdm

    from tethersim.cli import preflight
    from tethersim.experiments.deployment import COLUMNS, deploy, row, settle
    from tethersim.output.plots.deploy import FILE, plot_deployment
    from tethersim.output.tables import write_table

    sat = options.satellite(args)
    from tethersim.cli.overrides import refuse_unused
    refuse_unused(args, sat, (args.model,))
    _check_sizes(args, sat)  # cheap: before the starts' equilibria are solved
    todo = _starts(args, sat)
    out = Path(args.out) if args.out else options.default_out(args, "deploy")
    preflight.check_files(out, ("deployment.csv", FILE, "satellite.json"))
    record = options.claim_folder(out, args, sat)
    rows, pitch, written = [], [], []
    table = out / "deployment.csv"
    try:
        for kind, value, start in tqdm(todo, desc="deploy", unit="start",
                                       disable=options.progress(args) is False, leave=False):
            dep = deploy(start, args.periods, args.sample, args.model)
            settled = (settle(start, args.settle_periods, args.model)
                       if args.settle_periods else None)
            rows.append(row(kind, value, dep, settled))
            y = dep.result.model_states
            every = max(1, len(y) // PITCH_POINTS)
            pitch.append((dep.result.t[::every].copy(), y[::every, 2] - y[0, 2]))
            del dep  # its fine grid is hundreds of MB
            write_table(table, rows, COLUMNS)  # an interruption keeps the finished rows
    except KeyboardInterrupt:
        if rows:
            options.write_provenance(out, record, [table])
        raise options.Interrupted(f"{len(rows)} of {len(todo)} starts written to {table}") from None
    written.append(table)
    written.append(plot_deployment(rows, pitch, sat.period, out,
                                   f"{sat.name}: lines {sat.l10:g} / {sat.l20:g} m, EA "
                                   f"{sat.E1:.4g} / {sat.E2:.4g} N, {args.model}",
                                   breaking=min(sat.Fb1, sat.Fb2)))
    written.append(options.write_provenance(out, record, written))
    _print(rows)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


def _print(rows) -> None:
    head = ("start", "value", "status", "catch [s]", "speed [m/s]", "first peak [N]",
            "peak [N]", "safety", "pitch [rad]", "turned over", "settles as", "in [h]")
    print("  ".join(f"{h:>14}" for h in head))
    for r in rows:
        cells = (r["start"], f"{r['value']:g}", r["status"], f"{r['first_catch']:.4g}",
                 f"{r['catch_speed']:.4g}", f"{r['first_peak']:.4g}", f"{r['peak']:.4g}",
                 f"{r['safety_factor']:.4g}", f"{r['excursion']:.4g}",
                 "yes" if r["turned_over"] else "no", r["settled_class"] or "-",
                 f"{r['settling_h']:.3g}")
        print("  ".join(f"{c:>14}" for c in cells))
