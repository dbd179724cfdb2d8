"""``tethersim forces``: the generalized force of each family on each coordinate.

Simulates, then plots every force family's generalized force on delta_x [N],
delta_y [N] and theta [N m] (thesis Figs 5.7-5.20, pp. 5-8 to 5-17) with a
zoomed panel for the small families; writes forces_<coordinate>.png (delta_x,
delta_y, theta; a 3-D model adds delta_z, phi, psi, a free orbit r, nu)
and forces.csv (largest force per coordinate) into
``results/<satellite>/forces`` (or ``--out``).
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options

HELP = "generalized force of each family on each coordinate"


def add_parser(sub) -> None:
    """Declare ``forces`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "forces", help=HELP,
        description="Simulate, then plot every force family's generalized force on delta_x "
                    "[N], delta_y [N] and theta [N m] (thesis Figs 5.7-5.20) with a zoomed "
                    "panel for the small families; write forces_<coordinate>.png (a 3-D model "
                    "adds delta_z, phi, psi; a free orbit r, nu) and forces.csv (largest "
                    "force per coordinate).")
    options.add_satellite(p)
    options.add_periods(p)
    options.add_integrator(p)
    options.add_model(p)
    options.add_out(p, "results/<satellite>/forces")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``forces``.

    Returns
    -------
    int
        0; a diverged or interrupted run raises :class:`options.RunFailed` or
        :class:`options.Interrupted` after its output is written.
    """
    from tethersim.analysis.force_peaks import (
        COLUMNS,
        SAMPLES_PER_PERIOD,
        format_table,
        largest_forces,
        table_rows,
    )
    from tethersim.cli import preflight
    from tethersim.engine.simulate import simulate
    from tethersim.output.plots.forces import plot_forces
    from tethersim.output.tables import write_table

    sat = options.satellite(args)  # before the run: a bad --set costs nothing
    from tethersim.cli.overrides import refuse_unused
    refuse_unused(args, sat, (args.model,))
    how = options.integrator(args)
    out = Path(args.out) if args.out else options.default_out(args, "forces")
    # adaptive: the force peaks need a dense output grid unless --steps says otherwise
    samples = how.samples or max(2, round(SAMPLES_PER_PERIOD * args.periods))
    preflight.check_run_size(args, how, "--periods/--steps",
                             samples=None if how.method == "rk4" else samples)
    preflight.check_files(out, ("forces.csv", "satellite.json", "forces_theta.png",
                                "forces_delta_x.png", "forces_delta_y.png"))
    record = options.claim_folder(out, args, sat)
    res = simulate(sat, periods=args.periods, method=how.method, model=args.model,
                   steps=how.steps, samples=None if how.method == "rk4" else samples,
                   rtol=how.rtol, locate_switches=how.locate, progress=options.progress(args))
    options.interrupted_early(res)
    rows = largest_forces(res)
    written = [write_table(out / "forces.csv", table_rows(rows), COLUMNS)]
    written += plot_forces(res, out, Q=res.forces)
    written.append(options.write_provenance(out, record, written))
    print(res.label)
    print(how.describe(sat.period, args.periods))
    print(format_table(rows))
    print("wrote " + ", ".join(str(p) for p in written))
    options.check_status(res)
    return 0
