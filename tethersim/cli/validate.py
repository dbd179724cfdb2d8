"""``tethersim validate``: the thesis's Sec 4.4 validation, Tables 4.4 and 4.5.

No drag, no tethers, theta0 = pi/6: principal moments (Table 4.4), predicted
against simulated pitch frequency (Table 4.5), and the exact nonlinear
libration frequency.
"""
from __future__ import annotations

from tethersim.cli import options

HELP = "thesis Sec 4.4 validation: Tables 4.4 and 4.5"


def add_parser(sub) -> None:
    """Declare ``validate`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "validate", help=HELP,
        description="No drag, no tethers, theta0 = pi/6: principal moments (Table 4.4), "
                    "predicted vs simulated pitch frequency (Table 4.5), and the exact "
                    "nonlinear libration frequency.")
    p.add_argument("satellites", nargs="*",
                   help=options.PRESET_HELP + " (default: all three presets)")
    options.add_periods(p, default=2.0)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``validate``.

    Returns
    -------
    int
        0.
    """
    from tethersim.analysis.validation import format_tables, validate
    from tethersim.model.presets import resolve

    names = args.satellites or ["satI", "satII", "dumbsat"]
    sats = [resolve(n) for n in names]  # all before the first run: a bad name costs nothing
    rows = [validate(sat, periods=args.periods) for sat in sats]
    print(format_tables(rows))
    return 0
