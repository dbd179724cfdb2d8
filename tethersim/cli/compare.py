"""``tethersim compare``: one satellite under several model variants, plotted together.

Runs the same satellite (with --set/--scale) under each model variant; writes
compare.png (theta, delta_x, delta_y and theta differences from the first
model) and compare.csv (metrics per model) into ``results/<satellite>/compare``
(or ``--out``), prints the table and says where the outcome classes differ.
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options
from tethersim.model.registry import THESIS_VARIANTS

HELP = "run a satellite under several model variants, plot them together"


def add_parser(sub) -> None:
    """Declare ``compare`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "compare", help=HELP,
        description="Run the same satellite (with --set/--scale) under each model variant; "
                    "write compare.png (theta, delta_x, delta_y and theta differences from "
                    "the first model) and compare.csv (metrics per model), print the table "
                    "and say where the outcome classes differ.")
    options.add_satellite(p)
    options.add_models(p, THESIS_VARIANTS)
    options.add_periods(p)
    options.add_integrator(p)
    options.add_out(p, "results/<satellite>/compare")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``compare``.

    Returns
    -------
    int
        0; a failed or interrupted variant raises :class:`options.RunFailed` or
        :class:`options.Interrupted` after the output is written.
    """
    from tethersim.analysis.classify import CLASSES, describe
    from tethersim.cli import preflight
    from tethersim.experiments.compare import (
        COLUMNS,
        compare,
        comparison_table,
        describe_runs,
        format_table,
        outcome_differences,
    )
    from tethersim.output.plots.compare import plot_compare
    from tethersim.output.tables import write_table

    models = options.models(args)  # before the runs: a bad name costs nothing
    sat = options.satellite(args)
    from tethersim.cli.overrides import refuse_unused
    refuse_unused(args, sat, models)  # a setting no variant uses would change nothing
    how = options.integrator(args)
    out = Path(args.out) if args.out else options.default_out(args, "compare")
    preflight.check_run_size(args, how, "--periods/--steps", check=True)
    preflight.check_files(out, ("compare.csv", "compare.png", "satellite.json"))
    record = options.claim_folder(out, args, sat)
    results = compare(sat, models, periods=args.periods, method=how.method, steps=how.steps,
                      samples=how.samples, rtol=how.rtol, locate_switches=how.locate, check=True,
                      progress=options.progress(args))
    rows = comparison_table(results)
    notes = outcome_differences(rows)
    written = [write_table(out / "compare.csv", rows, COLUMNS)]
    heading = describe_runs(results, " ".join(options.overrides(args)))
    title = heading + "\n" + (notes[0] if notes else "all variants end in the same outcome class")
    written.append(plot_compare(results, out, title=title))
    written.append(options.write_provenance(out, record, written))
    print(heading)
    print(how.describe(sat.period, args.periods))
    print(format_table(rows))
    print("\n".join(notes) if notes else "all variants end "
          + describe(CLASSES.index(rows[0]["class"])))
    print("wrote " + ", ".join(str(p) for p in written))
    if any(r["status"] == "interrupted" for r in rows):
        raise options.Interrupted("the output holds the runs finished so far")
    bad = [f"{m}: {res.message}" for m, res in results if res.status != "ok"]
    if bad:
        raise options.RunFailed("; ".join(bad))
    return 0
