"""``tethersim headlines``: the thesis's headline results, faithful and converged.

Reruns the thesis's SatI headlines (nominal settling, E1 +50 % tumble, ~pi/2
offsets at 10 % off, damping x10 upside down) with RK4 at the thesis's step,
1/2 and 1/4 of it, and adaptive DOP853, for each model variant; prints a
verdict per claim; writes headlines.csv, headlines_verdicts.csv and a
theta(t) PNG per case into ``results/<satellite>/headlines`` (or ``--out``).
"""
from __future__ import annotations

import json
from pathlib import Path

from tethersim.cli import options

HELP = "the thesis's headline results, faithful and converged"
DEFAULT_MODELS = ("derived", "printed", "objective-damper")
# tethersim.experiments.headlines.BY_NAME, written out so that `tethersim --help` does not
# import the experiments (~1 s); tests/cli/test_headlines.py checks they agree
CASES = ("nominal", "moduli-nominal", "E1+50%", "E1-10%", "E1+10%", "E2-10%", "E2+10%",
         "damping-x10")


def add_parser(sub) -> None:
    """Declare ``headlines`` and its options on the subparsers ``sub``."""
    # descriptions are not %-formatted by argparse (help strings are): a plain % here
    p = sub.add_parser(
        "headlines", help=HELP,
        description="Rerun the thesis's SatI headlines (nominal settling, E1 +50 % tumble, "
                    "~pi/2 offsets at 10 % off, damping x10 upside down) with RK4 at the "
                    "thesis's step, 1/2 and 1/4 of it, and adaptive DOP853, for each model "
                    "variant; print a verdict per claim; write headlines.csv, "
                    "headlines_verdicts.csv and a theta(t) PNG per case (docs/headlines.md).")
    options.add_satellite(p, optional_default="satI",
                          note=" (default satI; the claims are the thesis's for SatI)")
    options.add_models(p, DEFAULT_MODELS)
    # help strings are %-formatted by argparse: a literal % is written %%
    p.add_argument("--cases", nargs="+", default=None, metavar="CASE",
                   help="headline cases (default all): "
                        + ", ".join(CASES).replace("%", "%%"))
    options.add_periods(p, default=None,
                        help="run every case for this many orbits at the thesis's step size "
                             "(default: the thesis's 5 or 50; for quick checks)")
    p.add_argument("--scan", action="store_true",
                   help="also scan the damping factor (1..10,000) and the RK4 step "
                        "(damping x10); ~30 s")
    options.add_out(p, "results/<satellite>/headlines")
    p.add_argument("--no-plots", action="store_true", help="skip the PNGs")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``headlines``.

    Returns
    -------
    int
        0.
    """
    from tethersim.cli import preflight
    from tethersim.experiments import headlines as hl
    from tethersim.output.plots.headlines import plot_cases, plot_damping_scan, plot_step_scan
    from tethersim.output.tables import write_rows

    sat = options.satellite(args)
    models = options.models(args)
    unknown = [c for c in args.cases or () if c not in hl.BY_NAME]
    if unknown:
        raise options.UsageError(f"--cases {' '.join(unknown)}: allowed values "
                                 f"{', '.join(hl.BY_NAME)}")
    repeated = sorted({c for c in args.cases or () if args.cases.count(c) > 1})
    if repeated:  # as compare's --models: each case runs once (the list is then bounded)
        raise options.UsageError(f"--cases {' '.join(repeated)}: given more than once")
    out = Path(args.out) if args.out else options.default_out(args, "headlines")
    preflight.check_files(out, ("headlines.csv", "headlines_verdicts.csv", "satellite.json",
                                "headlines_scan_damping.csv", "headlines_scan_step.csv"))
    record = options.claim_folder(out, args, sat)
    progress = not args.quiet
    rows = hl.run_headlines(sat, models=models, progress=progress,
                            cases=args.cases or None, periods=args.periods)
    vs = hl.verdicts(rows)
    print(hl.format_verdicts(vs))
    written = [write_rows(out / "headlines.csv", rows),
               write_rows(out / "headlines_verdicts.csv",
                          [{k: (json.dumps(v, ensure_ascii=False) if isinstance(v, dict) else v)
                            for k, v in x.items()} for x in vs])]
    if not args.no_plots:
        written += plot_cases(rows, out)
    if args.scan:
        ds = hl.damping_scan(sat, models=models, progress=progress)
        written.append(write_rows(out / "headlines_scan_damping.csv", ds))
        ss = hl.step_scan(sat, "damping-x10", models=models, progress=progress)
        written.append(write_rows(out / "headlines_scan_step.csv", ss))
        if not args.no_plots:
            written += [plot_damping_scan(ds, out / "headlines_scan_damping.png"),
                        plot_step_scan(ss, out / "headlines_scan_step.png")]
    written.append(options.write_provenance(out, record, written))
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
