"""Command line: ``tethersim run | validate | equilibrium | show``.  ``tethersim CMD --help`` for each."""
from __future__ import annotations

import argparse
import json
import math
import sys
import warnings
from pathlib import Path

from .models import DEFAULT_MODEL

PRESET_HELP = "preset name (satI, satII, dumbsat; any case) or path to a satellite .toml file"


def _sat(arg):
    from .presets import resolve
    return resolve(arg)


def _model_names():
    from generated.dispatch import MODEL_NAMES
    return MODEL_NAMES


def cmd_run(args) -> int:
    from .plots import plot_result
    from .simulation import STEPS_PER_PERIOD, simulate

    sat = _sat(args.satellite)
    if args.faithful:
        method, locate = "rk4", False
    else:
        method, locate = args.method, (True if args.locate_switches else None)
    out = Path(args.out)
    try:  # before the run, so a bad folder costs nothing
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {args.out}: cannot create the output folder: {exc.strerror}") from None
    steps = args.steps
    if method == "rk4" and steps is None:
        steps = max(1, round(STEPS_PER_PERIOD * args.periods))
    res = simulate(sat, periods=args.periods, steps=steps, method=method, model=args.model,
                   rtol=args.rtol, locate_switches=locate, check=not args.no_check,
                   progress=None if not args.quiet else False)
    res.to_csv(out / "timeseries.csv")
    res.to_netcdf(out / "timeseries.nc")
    written = [out / "timeseries.csv", out / "timeseries.nc"]
    if not args.no_plots:
        written += plot_result(res, out)
    summary = res.summary()
    strict = {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
              for k, v in summary.items()}  # NaN is not JSON: null means "never settled"
    (out / "summary.json").write_text(json.dumps(strict, indent=2, default=str) + "\n")
    written.append(out / "summary.json")
    if method == "rk4":
        print(f"step size: {res.step:.4g} s ({res.step:.2f} sec/step), "
              f"{args.periods:g} periods in {steps} steps")
    for k, v in summary.items():
        print(f"  {k:<32} {v:.6g}" if isinstance(v, float) else f"  {k:<32} {v}")
    print("wrote " + ", ".join(str(p) for p in written))
    if res.status == "interrupted":
        print(f"interrupted: the output holds the run up to t = {res.t[-1]:.6g} s", file=sys.stderr)
        return 130
    if res.status != "ok":
        print(f"error: {res.message}", file=sys.stderr)
        return 1
    return 0


def cmd_validate(args) -> int:
    from .validation import format_tables, validate

    names = args.satellites or ["satI", "satII", "dumbsat"]
    rows = [validate(_sat(n), periods=args.periods) for n in names]
    print(format_tables(rows))
    return 0


def cmd_show(args) -> int:
    from .satellite import UNITS

    sat = _sat(args.satellite)
    print(f"{sat.name}  ({sat.source})")
    for k, v in sat.to_dict().items():
        if k in UNITS:
            print(f"  {k:<12} {v:<14.6g} {UNITS[k]}")
    names = ("delta_x [m]", "delta_y [m]", "theta [rad]", "delta_x_dot [m/s]",
             "delta_y_dot [m/s]", "theta_dot [rad/s]")
    for n, v in zip(names, sat.initial):
        print(f"  {n:<18} {v:.6g}")
    print(f"  r0 {sat.r0:.6g} m, omega {sat.omega:.6g} rad/s, period {sat.period:.6g} s, "
          f"rho {sat.rho:.4g} kg/m^3, density {sat.density_mode}")
    return 0


def cmd_equilibrium(args) -> int:
    from .equilibrium import find_equilibrium, format_equilibrium

    print(format_equilibrium(find_equilibrium(_sat(args.satellite), model=args.model)))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tethersim",
        description="Gravity-gradient satellite with a tethered drag balloon (Maramba, AFIT 2005). "
                    "SI units inside; conventions in docs/conventions.md.")
    sub = parser.add_subparsers(dest="command", required=True)

    run = sub.add_parser("run", help="simulate a satellite, write time series, plots and a summary",
                         description="Simulate a satellite; write timeseries.csv, timeseries.nc "
                                     "(NetCDF), theta/delta_x/delta_y/overview PNGs and summary.json.")
    run.add_argument("satellite", help=PRESET_HELP)
    run.add_argument("--periods", type=float, default=50.0, help="orbits to simulate (default 50)")
    run.add_argument("--steps", type=int, default=None,
                     help="RK4: number of steps (default 300 per orbit, as the thesis); "
                          "adaptive: number of output samples (default 200 per orbit)")
    run.add_argument("--method", choices=("adaptive", "rk4"), default="adaptive",
                     help="adaptive DOP853 (default, converged) or fixed-step RK4")
    run.add_argument("--faithful", action="store_true",
                     help="the thesis's scheme: fixed-step RK4, tether switches not located")
    run.add_argument("--locate-switches", action="store_true",
                     help="RK4: split steps at taut/slack switches")
    run.add_argument("--model", choices=_model_names(), default=DEFAULT_MODEL,
                     help=f"model variant (default {DEFAULT_MODEL}; see docs/errata.md)")
    run.add_argument("--rtol", type=float, default=1e-10, help="adaptive relative tolerance")
    run.add_argument("--out", default="results", help="output folder (default ./results)")
    run.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    run.add_argument("--no-check", action="store_true",
                     help="skip the convergence check (a second run at half step / rtol/100)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")
    run.set_defaults(func=cmd_run)

    val = sub.add_parser("validate", help="thesis Sec 4.4 validation: Tables 4.4 and 4.5",
                         description="No drag, no tethers, theta0 = pi/6: principal moments "
                                     "(Table 4.4), predicted vs simulated pitch frequency "
                                     "(Table 4.5), and the exact nonlinear libration frequency.")
    val.add_argument("satellites", nargs="*", help=PRESET_HELP + " (default: all three presets)")
    val.add_argument("--periods", type=float, default=2.0, help="orbits to simulate (default 2)")
    val.set_defaults(func=cmd_validate)

    eq = sub.add_parser("equilibrium", help="steady configuration, its modes and stability",
                        description="Solve for the balloon trail and pitch where the "
                                    "accelerations vanish; print which tethers are taut, the "
                                    "linear modes and a predicted settling time.")
    eq.add_argument("satellite", help=PRESET_HELP)
    eq.add_argument("--model", choices=_model_names(), default=DEFAULT_MODEL,
                    help=f"model variant (default {DEFAULT_MODEL})")
    eq.set_defaults(func=cmd_equilibrium)

    show = sub.add_parser("show", help="print a preset's parameters with units")
    show.add_argument("satellite", help=PRESET_HELP)
    show.set_defaults(func=cmd_show)
    return parser


def main(argv=None) -> int:
    from .satellite import SatelliteError

    args = build_parser().parse_args(argv)

    def show(message, category, filename, lineno, file=None, line=None):
        print(f"tethersim: warning: {category.__name__}: {message}", file=sys.stderr, flush=True)

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.showwarning = show
            return args.func(args)
    except (SatelliteError, ValueError, OSError) as exc:
        print(f"tethersim: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
