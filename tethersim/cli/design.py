"""``tethersim design``: which design settles before its orbit decays and keeps its trim?

A seeded NSGA-II search (pymoo) over ``--vary NAME=LOW:HIGH`` and ``--choice NAME=v1,v2``
(edge units of ``tethersim show``), each design judged as a feasibility point; the Pareto
set re-verified by finer runs in NRLMSISE-00 air, checked against the trail bound
(docs/design.md).  Writes ``pareto.csv``, ``designs.csv``, ``design.png`` and a resumable
store under ``--out``.
"""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.cli import options, parallel

HELP = "multi-objective design search: settle before the orbit decays, hold the trim"


def add_parser(sub) -> None:
    """Declare ``design`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "design", help=HELP,
        description="Search designs for the largest margin of usable life over settling "
                    "time and the smallest worst |theta_ss| across solar min/mean/max, "
                    "subject to the feasibility verdict (docs/design.md). Seeded and "
                    "resumable: run the same command again to continue.")
    options.add_satellite(p)
    p.add_argument("--vary", action="append", default=[], metavar="NAME=LOW:HIGH",
                   help="a continuous design variable in the units 'tethersim show' prints, "
                        "e.g. --vary c1=0.0001:0.01; repeatable")
    p.add_argument("--choice", action="append", default=[], metavar="NAME=v1,v2,...",
                   help="a discrete design variable, e.g. --choice A3=6,12,24; repeatable")
    p.add_argument("--altitude", default=None, metavar="KM|LOW:HIGH",
                   help="start altitude [km]: one value, or a range to search")
    p.add_argument("--budget", type=options.positive_int, default=32, metavar="N",
                   help="designs evaluated at most (default 32)")
    p.add_argument("--seed", type=options.int_range(0), default=0, metavar="S",
                   help="seed of the search (default 0)")
    p.add_argument("--population", type=options.int_range(0), default=0, metavar="N",
                   help="designs per generation (default min(budget, 16))")
    options.add_periods(p, help="orbits per circular run (default 50: three days)")
    p.add_argument("--max-lifetime", type=options.positive_float, default=240.0, metavar="H",
                   help="cap on the free run [h] (default 240)")
    p.add_argument("--rtol", type=options.rtol_float, default=None,
                   help="tolerance of the search's runs (default: the plans' CLASS_RTOL, "
                        "enough for a verdict, docs/tolerances.md); re-verification runs at "
                        "rtol/100")
    p.add_argument("--method", choices=("adaptive", "implicit"), default="adaptive",
                   help="scheme of every run: adaptive (DOP853, default; a design with a "
                        "tether too stiff for it is recorded 'refused') or implicit (Radau "
                        "IIA: real fibre tethers, docs/tethers.md; seconds per orbit)")
    p.add_argument("--tol", type=options.positive_float, default=SETTLING_TOL, metavar="RAD",
                   help=f"settling and trim band [rad] (default {SETTLING_TOL:g}, the thesis's)")
    p.add_argument("--safety", type=options.positive_float, default=1.5, metavar="F",
                   help="where breaking loads Fb1/Fb2 are set, every run uses them divided "
                        "by F (default 1.5)")
    p.add_argument("--verify", type=options.int_range(0), default=10, metavar="N",
                   help="Pareto designs re-verified at most (default 10)")
    parallel.add_parallel(p)
    options.add_model(p)
    options.add_out(p, "results/<satellite>/design")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run, interrupted_hint="run the same command again to continue")


def _range(text: str, what: str) -> tuple:
    from tethersim.model.params import _float
    parts = text.split(":")
    if len(parts) != 2:
        raise options.UsageError(f"{what}: expected LOW:HIGH, e.g. 0.001:0.01")
    return _float(parts[0], what), _float(parts[1], what)


def parse_variables(args) -> tuple:
    """(variables, choices) from --vary, --choice and --altitude (edge units)."""
    variables, choices = [], []
    for text in args.vary:
        name, sep, rng = text.partition("=")
        if not sep:
            raise options.UsageError(f"--vary {text}: expected NAME=LOW:HIGH, e.g. "
                                     f"c1=0.0001:0.01")
        variables.append((name.strip(), *_range(rng, f"--vary {text}")))
    for text in args.choice:
        name, sep, vals = text.partition("=")
        if not sep:
            raise options.UsageError(f"--choice {text}: expected NAME=v1,v2, e.g. A3=6,12")
        from tethersim.model.params import _float
        choices.append((name.strip(), tuple(_float(v.strip(), f"--choice {text}")
                                            for v in vals.split(",") if v.strip())))
    if args.altitude and ":" in args.altitude:
        variables.append(("altitude", *_range(args.altitude, f"--altitude {args.altitude}")))
    return tuple(variables), tuple(choices)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``design``.

    Returns
    -------
    int
        0 (also when no design qualifies: the summary says why).
    """
    from tethersim.cli import preflight
    from tethersim.cli.overrides import refuse
    from tethersim.experiments.design import FIXED, DesignSpec
    from tethersim.experiments.design_search import search
    from tethersim.experiments.sweep.plan import CLASS_RTOL
    from tethersim.model.registry import BY_NAME
    from tethersim.output.plots.design import plot_design
    from tethersim.output.tables import write_table
    if BY_NAME[args.model].orbit == "free":  # before options.satellite makes the orbit free
        raise options.UsageError(f"--model {args.model}: design takes a circular-orbit model; "
                                 f"it runs the trim on the held circular orbit and the life "
                                 f"with the model's free twin")
    where = parallel.check_parallel(args)
    refuse(args, FIXED, lambda n: "the design search sets it itself: drop it")
    variables, choices = parse_variables(args)
    if args.altitude and ":" not in args.altitude:
        args.set = [*args.set, f"altitude={args.altitude}"]
    sat = options.satellite(args)
    spec = DesignSpec(sat, variables, choices, budget=args.budget, seed=args.seed,
                      population=args.population, periods=args.periods,
                      max_lifetime_h=args.max_lifetime, model=args.model,
                      rtol=CLASS_RTOL if args.rtol is None else args.rtol,
                      method=args.method, tol=args.tol, safety=args.safety,
                      verify=args.verify)
    out = Path(args.out) if args.out else options.default_out(args, "design")
    preflight.check_files(out, ("pareto.csv", "designs.csv", "design.png"))
    preflight.check_subfolder(out, "store")
    if args.force:
        import shutil
        shutil.rmtree(out / "store", ignore_errors=True)
    if not args.quiet:
        print(f"design search over {', '.join(spec.names)}: {spec.generations} generation(s) "
              f"of {spec.population} (seed {spec.seed}) -> {out}")
    res = search(spec, out / "store", **where, progress=options.progress(args))
    columns = _columns(spec)
    write_table(out / "designs.csv", ({k: r.get(k) for k, _ in columns[:-len(VERIFY_COLUMNS)]}
                                      for r in res["evaluations"]),
                columns[:-len(VERIFY_COLUMNS)])
    csv = write_table(out / "pareto.csv", ({k: r.get(k) for k, _ in columns}
                                           for r in res["pareto"]), columns)
    png = plot_design(res["evaluations"], res["pareto"], out / "design.png", tol=spec.tol,
                      title=f"{sat.name}: design search ({len(res['evaluations'])} designs)")
    _summary(spec, res)
    print(f"wrote {csv}, {out / 'designs.csv'} and {png}")
    return 0


# (key, header with unit) of a design's row after its variables; the re-verification's last
ROW_COLUMNS = (
    ("verdict", "verdict"), ("reason", "reason"), ("margin_h", "margin life - settling [h]"),
    ("life_h", "usable life [h]"), ("life_capped", "life capped"), ("free_end", "free run end"),
    ("settling_h", "settling time [h]"), ("worst_theta_ss_rad", "worst |theta_ss| [rad]"),
    ("theta_ss_rad", "theta_ss nominal [rad]"), ("theta_ss_min_rad", "theta_ss solar min [rad]"),
    ("theta_ss_mean_rad", "theta_ss solar mean [rad]"),
    ("theta_ss_max_rad", "theta_ss solar max [rad]"), ("trail_m", "trail [m]"))
VERIFY_COLUMNS = (
    ("verified", "verified"), ("fine_verdict", "finer run's verdict"),
    ("fine_life_h", "finer run's shortest usable life [h]"),
    ("fine_worst_case", "finer run's shortest-life solar case"), ("check_rtol", "finer rtol"),
    ("epsilon", "trail strength epsilon [1]"), ("decay_life_h", "bound: decay life [h]"),
    ("settle_min_h", "bound: fastest settling [h]"),
    ("bound_ratio", "bound: settling/life >= [1]"), ("settle_over_life", "settling/life [1]"),
    ("respects_bound", "respects the bound"), ("peak_tension_1_N", "peak tension 1 [N]"),
    ("peak_tension_2_N", "peak tension 2 [N]"),
    ("tension_margin", "tension margin 1 - peak/breaking load [1]"))


def _columns(spec) -> tuple:
    """The CSV columns: the design variables in their edge units, the row, the checks."""
    from tethersim.model.params import unit
    return (tuple((n, f"{n} [{unit(n)}]") for n in spec.names) + ROW_COLUMNS
            + VERIFY_COLUMNS)


def _summary(spec, res) -> None:
    from tethersim.experiments.design_search import no_design_reason
    print(f"{len(res['evaluations'])} design(s) evaluated ({res['replayed']} read from the "
          f"store)")
    if not res["pareto"]:
        print(no_design_reason(spec, res["evaluations"]))
        return
    for r in res["pareto"]:
        values = ", ".join(f"{n}={r[n]:.4g}" for n in spec.names)
        verified = ("verified" if r["verified"] else r["fine_verdict"] if r["verified"] is None
                    else f"NOT verified ({r['fine_verdict']})")
        tension = r.get("tension_margin", math.nan)
        strength = f", tension margin {tension:.3g}" if math.isfinite(tension) else ""
        print(f"  {values}: margin {r['margin_h']:.3g} h, worst |theta_ss| "
              f"{r['worst_theta_ss_rad']:.3g} rad{strength}, {verified}; trail bound "
              f"{r['bound_ratio']:.3g} <= settling/life {r['settle_over_life']:.3g}")
