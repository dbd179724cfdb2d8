"""``tethersim show``: a satellite's parameters in the units ``--set`` takes.

Every settable parameter is printed in its edge unit (tethersim.model.params:
E1, E2 in N/mm^2, altitude in km, else SI) as the shortest text that converts
back to the same SI value, so a printed value fed back through ``--set
NAME=VALUE`` gives the same satellite; a value with no such text of 12 digits
(a product of ``--scale``) is rounded to 12 (tethersim.model.params.edge_text).
"""
from __future__ import annotations

from tethersim.cli import options

HELP = "print a satellite's parameters in the units --set takes"


def add_parser(sub) -> None:
    """Declare ``show`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "show", help=HELP,
        description="Print a satellite's parameters in the units --set and --scale take "
                    "(E1, E2 in N/mm^2, altitude in km, else SI), the end-body moments of "
                    "the 3-D models, then its initial state and derived orbit (SI).")
    options.add_satellite(p)
    options.add_overrides(p)
    p.add_argument("--toml", metavar="FILE", default=None,
                   help="also write the satellite (with --set/--scale) as a preset TOML file, "
                        "to edit and run: tethersim run FILE")
    p.set_defaults(func=run)


def exact(value: float) -> str:
    """Short text for ``value`` that reads back as the same float (15 digits, else repr)."""
    text = f"{value:.15g}"
    return text if float(text) == value else repr(float(value))


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``show``.

    Returns
    -------
    int
        0.
    """
    from tethersim.model import params

    sat = options.satellite(args)
    print(f"{sat.name}  ({sat.source})")
    print("  parameters in the units --set takes (E1, E2 in N/mm^2, altitude in km, else SI):")
    from tethersim.model.bead_layout import attachment_points
    held = dict(zip(("s1", "s2"), attachment_points(sat)))  # None: the boom's end
    for name in params.NAMES:
        if name in held:
            print(f"  {name:<12} {exact(held[name]):<22} {params.unit(name)}")
            continue
        if getattr(sat, name) is None:  # an unset MSIS index: the bundled table's
            continue
        print(f"  {name:<12} {params.edge_text(sat, name):<22} {params.unit(name)}")
    print(f"  options: orbit {sat.orbit}, j2 {str(sat.j2).lower()}, atmosphere "
          f"{sat.atmosphere}, epoch {sat.epoch}"
          + ("" if sat.f107 is not None else " (f107, f107a, ap unset: the bundled table)"))
    from tethersim.model.inertia import AXES, body_inertias
    moments = body_inertias(sat)
    print(f"  end-body moments of the 3-D models (--set inertia=boxes|points, "
          f"--set I1=roll,pitch,yaw or none): inertia {sat.inertia}")
    for k in (1, 2):
        src = ("set" if getattr(sat, f"I{k}") is not None else
               "point mass" if sat.inertia == "points" else "box, thesis Eq 4.4")
        print(f"  I{k:<11} {','.join(exact(moments[f'I{k}_{a}']) for a in AXES):<22} "
              f"kg m^2 [roll,pitch,yaw] ({src})")
    print("  initial state (SI):")
    names = ("delta_x [m]", "delta_y [m]", "theta [rad]", "delta_x_dot [m/s]",
             "delta_y_dot [m/s]", "theta_dot [rad/s]")
    for n, v in zip(names, sat.initial):
        print(f"  {n:<18} {v:.6g}")
    print(f"  r0 {sat.r0:.6g} m, omega {sat.omega:.6g} rad/s, period {sat.period:.6g} s, "
          f"rho {sat.rho:.4g} kg/m^3, density {sat.density_mode}"
          + (" (follows the orbit)" if sat.density_auto else ""))
    from tethersim.model.options import density_text
    print(f"  air density of a run: {density_text(sat)}")
    for line in (sat.implausible if sat.allow_implausible else ()):
        print(f"  implausible (allowed): {line}")
    if args.toml:
        _write_toml(sat, args)
    return 0


def _write_toml(sat, args) -> None:
    """Write ``sat`` to ``args.toml`` in the preset layout (tethersim.model.presets.write)."""
    from pathlib import Path

    from tethersim.model.presets.write import dumps
    path = Path(args.toml)
    if path.suffix != ".toml":
        raise ValueError(f"--toml {args.toml}: the file name must end in .toml")
    header = f"{sat.name}: written by tethersim show {args.satellite} " + " ".join(
        options.overrides(args))
    try:
        path.write_text(dumps(sat, header=header.strip()))
    except OSError as exc:
        raise ValueError(f"--toml {args.toml}: cannot write the file: {exc.strerror}") from None
    print(f"wrote {path}")
