"""``tethersim equilibrium``: the steady configuration, its modes and stability.

Solves for the balloon trail and pitch where the accelerations vanish; prints
which tethers are taut, the linear modes and a predicted settling time.
"""
from __future__ import annotations

from tethersim.cli import options

HELP = "steady configuration, its modes and stability"


def add_parser(sub) -> None:
    """Declare ``equilibrium`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "equilibrium", help=HELP,
        description="Solve for the balloon trail and pitch where the accelerations vanish; "
                    "print which tethers are taut, the linear modes and a predicted "
                    "settling time.")
    options.add_satellite(p)
    options.add_model(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``equilibrium``.

    Returns
    -------
    int
        0.
    """
    from tethersim.analysis.equilibrium import find_equilibrium, format_equilibrium
    from tethersim.cli.overrides import refuse_unused
    sat = options.satellite(args)
    refuse_unused(args, sat, (args.model,))
    print(format_equilibrium(find_equilibrium(sat, model=args.model)))
    return 0
