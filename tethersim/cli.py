"""Command line: ``tethersim run | validate | equilibrium | show | compare | forces | sweep | tune | report | headlines``.

``tethersim CMD --help`` for each.  Units at this edge: docs/conventions.md; --set/--scale units: tethersim.params.
"""
from __future__ import annotations

import argparse
import contextlib
import json
import math
import signal
import sys
import threading
import time
import warnings
from pathlib import Path

from .models import DEFAULT_MODEL

PRESET_HELP = "preset name (satI, satII, dumbsat; any case) or path to a satellite .toml file"


def _sat(arg, allow_implausible=False):
    from .presets import resolve
    return resolve(arg, allow_implausible)


def _sat_args(args):
    """The satellite of ``args.satellite`` with --set/--scale applied (edge units)."""
    from .params import apply_overrides
    sat = _sat(args.satellite, getattr(args, "allow_implausible", False))
    return apply_overrides(sat, getattr(args, "set", None) or (),
                           getattr(args, "scale", None) or ())


def add_override_args(parser) -> None:
    """--set NAME=VALUE and --scale NAME=FACTOR (units: tethersim.params.EDGE_UNITS)."""
    parser.add_argument("--set", action="append", metavar="NAME=VALUE", default=[],
                        help="change a parameter, in preset units (E1, E2 in N/mm^2, "
                             "altitude in km, else SI); repeatable")
    parser.add_argument("--scale", action="append", metavar="NAME=FACTOR", default=[],
                        help="multiply a parameter, e.g. --scale c1=10 --scale c2=10; repeatable")
    parser.add_argument("--allow-implausible", action="store_true",
                        help="run values outside the plausible ranges (tethersim.plausibility); "
                             "the summary lists them")


def _add_model_arg(parser, note: str = "") -> None:
    parser.add_argument("--model", choices=_model_names(), default=DEFAULT_MODEL,
                        help=f"model variant (default {DEFAULT_MODEL}{note})")


def _model_names():
    from generated.dispatch import MODEL_NAMES
    return MODEL_NAMES


def cmd_run(args) -> int:
    from .plots import plot_result
    from .simulation import STEPS_PER_PERIOD, simulate

    sat = _sat_args(args)
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
    if _interrupted_early(res):
        return 130
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


def _interrupted_early(res) -> bool:
    """Ctrl-C before a second output sample: nothing to summarise; say so in one line."""
    if res.status == "interrupted" and res.t.size < 2:
        print(f"tethersim: interrupted at t = {res.t[-1]:.6g} s, before the first output "
              f"sample: nothing written", file=sys.stderr)
        return True
    return False


def cmd_validate(args) -> int:
    from .validation import format_tables, validate

    names = args.satellites or ["satI", "satII", "dumbsat"]
    rows = [validate(_sat(n), periods=args.periods) for n in names]
    print(format_tables(rows))
    return 0


def cmd_show(args) -> int:
    from .satellite import UNITS

    sat = _sat_args(args)
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
    for line in (sat.implausible if sat.allow_implausible else ()):
        print(f"  implausible (allowed): {line}")
    return 0


def cmd_equilibrium(args) -> int:
    from .equilibrium import find_equilibrium, format_equilibrium

    print(format_equilibrium(find_equilibrium(_sat_args(args), model=args.model)))
    return 0


def cmd_compare(args) -> int:
    """Run one satellite under several model variants; write compare.png, compare.csv."""
    from .compare import (
        compare,
        comparison_table,
        describe_runs,
        format_table,
        outcome_differences,
        parse_models,
        write_csv,
    )
    from .plot_compare import plot_compare
    from .simulation import STEPS_PER_PERIOD

    models = parse_models(args.models)  # before the runs: a bad name costs nothing
    sat = _sat_args(args)
    method = "rk4" if args.faithful else args.method
    out = Path(args.out or _default_out(args.satellite, "compare"))
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {out}: cannot create the output folder: {exc.strerror}") from None
    steps = args.steps
    if method == "rk4" and steps is None:
        steps = max(1, round(STEPS_PER_PERIOD * args.periods))
    results = compare(sat, models, periods=args.periods, steps=steps, method=method,
                      rtol=args.rtol, locate_switches=False if args.faithful else None,
                      progress=None if not args.quiet else False)
    rows = comparison_table(results)
    notes = outcome_differences(rows)
    written = [write_csv(rows, out / "compare.csv")]
    overrides = " ".join([f"--set {a}" for a in args.set] + [f"--scale {a}" for a in args.scale])
    heading = describe_runs(results, overrides)
    title = heading + "\n" + (notes[0] if notes else "all variants end in the same outcome class")
    written.append(plot_compare(results, out, title=title))
    print(heading)
    print(format_table(rows))
    print("\n".join(notes) if notes else f"all variants end {rows[0]['class']}")
    print("wrote " + ", ".join(str(p) for p in written))
    statuses = [r["status"] for r in rows]
    if "interrupted" in statuses:
        print("interrupted: the output holds the runs finished so far", file=sys.stderr)
        return 130
    bad = [f"{m}: {res.message}" for m, res in results if res.status != "ok"]
    if bad:
        print("error: " + "; ".join(bad), file=sys.stderr)
        return 1
    return 0


def _default_out(satellite: str, suffix: str) -> str:
    """results/<preset>-<suffix>: the preset's file stem (satI, satII, dumbsat) or the .toml's."""
    from .presets import PRESET_NAMES
    stem = Path(PRESET_NAMES.get(satellite.lower(), satellite)).stem
    return str(Path("results") / f"{stem}-{suffix}")


def cmd_forces(args) -> int:
    """Force breakdown per coordinate (thesis Figs 5.7-5.20, pp. 5-8 to 5-17)."""
    from .forces import SAMPLES_PER_PERIOD, format_table, largest_forces, write_csv
    from .plot_forces import plot_forces
    from .simulation import FAITHFUL_STEPS_PER_PERIOD, simulate

    sat = _sat_args(args)  # before the run: a bad --set costs nothing
    out = Path(args.out or _default_out(args.satellite, "forces"))
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {out}: cannot create the output folder: {exc.strerror}") from None
    if args.faithful:  # the thesis's RK4, 26.55 s per step (50 orbits in 10,000 steps)
        steps = max(1, round(FAITHFUL_STEPS_PER_PERIOD * args.periods))
        res = simulate(sat, periods=args.periods, steps=steps, method="rk4", model=args.model,
                       locate_switches=False, progress=None if not args.quiet else False)
    else:
        res = simulate(sat, periods=args.periods, model=args.model,
                       samples=max(2, round(SAMPLES_PER_PERIOD * args.periods)),
                       progress=None if not args.quiet else False)
    if _interrupted_early(res):
        return 130
    Q = res.forces
    rows = largest_forces(res)
    written = [write_csv(rows, out / "forces.csv")] + plot_forces(res, out, Q=Q)
    print(res.label)
    print(format_table(rows))
    print("wrote " + ", ".join(str(p) for p in written))
    if res.status == "interrupted":
        print(f"interrupted: the output holds the run up to t = {res.t[-1]:.6g} s", file=sys.stderr)
        return 130
    if res.status != "ok":
        print(f"error: {res.message}", file=sys.stderr)
        return 1
    return 0


def _raise_interrupt(signum, frame):
    raise KeyboardInterrupt


@contextlib.contextmanager
def _sigterm_as_interrupt():
    """SIGTERM (kill) handled like Ctrl-C while inside: finished work is written."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGTERM, _raise_interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def cmd_sweep(args) -> int:
    from . import params
    from .plot_sweep import plot_stability_map
    from .sweep import SweepInterrupted, SweepSpec, run_sweep
    from .sweep.analysis import band_slope, class_counts

    sat = _sat_args(args)
    axes = [(n, params.parse_grid(n, getattr(args, n))) for n in params.NAMES
            if getattr(args, n) is not None]
    from .guards import check_sweep
    check_sweep([len(v) for _, v in axes], [n for n, _ in axes])  # at once, before any work
    if not 1 <= len(axes) <= 2:
        raise ValueError(f"give one or two grids, e.g. --E1 0:0.02:41 --E2 0:0.06:41; got "
                         f"{len(axes)} ({', '.join(n for n, _ in axes) or 'none'})")
    if sum(x is not None for x in (args.workers, args.dask_workers, args.scheduler)) > 1:
        raise ValueError("--workers, --dask-workers and --scheduler are alternatives: give one")
    if args.workers is not None and args.workers < 1:
        raise ValueError(f"--workers {args.workers}: must be >= 1")
    if args.dask_workers is not None and args.dask_workers < 1:
        raise ValueError(f"--dask-workers {args.dask_workers}: must be >= 1")
    spec = SweepSpec(sat, tuple(axes), periods=args.periods,
                     method="faithful" if args.faithful else "adaptive", model=args.model,
                     rtol=args.rtol)
    out = Path(args.out or _default_out(
        args.satellite, f"sweep-{'-'.join(spec.names)}{'-faithful' if args.faithful else ''}"))
    out.mkdir(parents=True, exist_ok=True)
    print(f"{spec.size} runs of {spec.periods:g} orbits "
          f"({'thesis RK4, 26.55 s steps' if args.faithful else f'DOP853, rtol {spec.rtol:g}'}, "
          f"model {spec.model}) -> {out / 'sweep.zarr'}")
    try:
        with _sigterm_as_interrupt():
            store = run_sweep(spec, out / "sweep.zarr", workers=args.workers,
                              scheduler=args.scheduler, dask_workers=args.dask_workers,
                              restart=args.restart, progress=None if not args.quiet else False)
    except SweepInterrupted as exc:
        print(f"tethersim: {exc}", file=sys.stderr)
        return 130
    ds = store.dataset()
    ds.drop_vars("done").to_dataframe().to_csv(out / "sweep.csv")
    written = [out / "sweep.zarr", out / "sweep.csv"]
    slope = band_slope(ds) if spec.names == ("E1", "E2") else float("nan")
    if len(spec.names) == 2 and not args.no_plots:
        nominal = {n: params.edge_value(sat, n) for n in spec.names}
        written.append(plot_stability_map(ds, out / "stability_map.png", nominal=nominal,
                                          band_slope=slope))
    for name, n in class_counts(ds).items():
        print(f"  {name:<12} {n}")
    failed = int((ds.status.values[ds.done.values] != 0).sum())
    if failed:  # their NaN metrics have a reason: say it, and how to see the message
        print(f"  {failed} point(s) failed (status attribute: diverged or integrator_failed; "
              f"metrics NaN): 'tethersim run' one with --set for its message")
    if math.isfinite(slope):
        print(f"  stable band centre: {spec.names[1]} = {slope:.4g} x {spec.names[0]}")
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


def cmd_tune(args) -> int:
    from .params import from_si, to_si
    from .presets.write import dumps
    from .tune import tune

    sat = _sat_args(args)
    if args.E1 is not None and not (math.isfinite(args.E1) and args.E1 > 0):
        raise ValueError(f"--E1 {args.E1}: must be a number > 0 (N/mm^2)")
    out = Path(args.out or _default_out(args.satellite, "tuned.toml"))
    out.parent.mkdir(parents=True, exist_ok=True)
    r = tune(sat, E1=None if args.E1 is None else to_si("E1", args.E1), periods=args.periods,
             model=args.model, workers=args.workers)
    t = r.satellite
    lo, hi = (from_si("E2", v) for v in r.band)
    print(f"{t.name}: stable band at E1 = {from_si('E1', t.E1):.6g} N/mm^2 and the chosen damping: "
          f"E2 = {lo:.6g} .. {hi:.6g} N/mm^2 (|theta_ss| <= 0.05 rad)")
    print(f"  E2 (band centre) = {from_si('E2', t.E2):.6g} N/mm^2, E2/E1 = {t.E2 / t.E1:.4g} "
          f"(b/a = {t.b / t.a:.4g})")
    print("  damping factor   class        settling [h]   theta_ss [rad]  (band centre before damping)")
    for k, name, ts, th in r.damping_scan:
        mark = "  <- chosen" if k == r.damping_factor else ""
        print(f"  {k:14.4g}   {name:<12} {ts / 3600:10.4g}   {th:+12.4f}{mark}")
    print(f"  c1 = {t.c1:.4g} N s/m, c2 = {t.c2:.4g} N s/m; {r.runs} runs of {args.periods:g} orbits")
    how = f"tethersim tune ({args.periods:g}-orbit converged runs, model {args.model})"
    notes = {"E1": "given", "E2": f"centre of the stable band {lo:.6g}..{hi:.6g} N/mm^2 ({how})",
             "c1": f"fastest stable settling (|theta_ss| <= 0.025 rad) over k x base damping, "
                   f"k = {r.damping_factor:.4g}; E2 then re-centred",
             "c2": "same factor as c1"}
    out.write_text(dumps(t, notes, header=f"{t.name} tuned by {how} from {sat.source or sat.name}"))
    print(f"wrote {out}")
    return 0


def cmd_report(args) -> int:
    from .report import build_report
    from .sweep import SweepInterrupted

    t0 = time.perf_counter()
    try:
        with _sigterm_as_interrupt():
            path = build_report(args.out, grid=args.grid, periods=args.periods,
                                workers=args.workers, progress=None if not args.quiet else False)
    except (SweepInterrupted, KeyboardInterrupt) as exc:
        print(f"tethersim: report interrupted ({exc or 'Ctrl-C'}); the finished sweeps are kept "
              f"under {args.out}/sweeps: run the same command again to continue", file=sys.stderr)
        return 130
    print(f"wrote {path} in {time.perf_counter() - t0:.0f} s")
    return 0


def cmd_headlines(args) -> int:
    from . import headlines as hl
    from .plot_headlines import plot_cases, plot_damping_scan, plot_step_scan

    sat = _sat_args(args)
    unknown = [c for c in args.cases or () if c not in hl.BY_NAME]
    if unknown:
        raise ValueError(f"--cases {' '.join(unknown)}: allowed values {', '.join(hl.BY_NAME)}")
    if args.periods is not None and not (math.isfinite(args.periods) and args.periods > 0):
        raise ValueError(f"--periods {args.periods}: must be a finite number > 0")
    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {args.out}: cannot create the output folder: {exc.strerror}") from None
    rows = hl.run_headlines(sat, models=tuple(args.models), progress=not args.quiet,
                            cases=args.cases or None, periods=args.periods)
    vs = hl.verdicts(rows)
    print(hl.format_verdicts(vs))
    written = [hl.write_csv(rows, out / "headlines.csv"),
               hl.write_csv([{k: (json.dumps(v, ensure_ascii=False) if isinstance(v, dict) else v)
                              for k, v in x.items()} for x in vs], out / "headlines_verdicts.csv")]
    if not args.no_plots:
        written += plot_cases(rows, out)
    if args.scan:
        ds = hl.damping_scan(sat, models=tuple(args.models), progress=not args.quiet)
        written.append(hl.write_csv(ds, out / "headlines_scan_damping.csv"))
        ss = hl.step_scan(sat, "damping-x10", models=tuple(args.models), progress=not args.quiet)
        written.append(hl.write_csv(ss, out / "headlines_scan_step.csv"))
        if not args.no_plots:
            written += [plot_damping_scan(ds, out / "headlines_scan_damping.png"),
                        plot_step_scan(ss, out / "headlines_scan_step.png")]
    print("wrote " + ", ".join(str(p) for p in written))
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
                          "adaptive: number of output samples (default 200 per orbit); output "
                          "memory is limited (TETHERSIM_MAX_OUTPUT_BYTES, default 2 GiB)")
    run.add_argument("--method", choices=("adaptive", "rk4"), default="adaptive",
                     help="adaptive DOP853 (default, converged) or fixed-step RK4")
    run.add_argument("--faithful", action="store_true",
                     help="the thesis's scheme: fixed-step RK4, tether switches not located")
    run.add_argument("--locate-switches", action="store_true",
                     help="RK4: split steps at taut/slack switches")
    _add_model_arg(run, "; see docs/errata.md")
    run.add_argument("--rtol", type=float, default=1e-10, help="adaptive relative tolerance")
    run.add_argument("--out", default="results", help="output folder (default ./results)")
    run.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    run.add_argument("--no-check", action="store_true",
                     help="skip the convergence check (a second run at half step / rtol/100)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")
    add_override_args(run)
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
    _add_model_arg(eq)
    add_override_args(eq)
    eq.set_defaults(func=cmd_equilibrium)

    sw = sub.add_parser(
        "sweep", help="stability map over one or two parameters (thesis Figs 5.13, 5.21-5.28)",
        description="Run a grid of simulations over one or two preset parameters, classify "
                    "each point (docs/metrics.md) and draw the stability map.  Grids: "
                    "START:STOP:COUNT (ends included) or a comma list, in preset units (E in "
                    "N/mm^2, altitude in km, else SI).  Results go to a resumable Zarr store: "
                    "run the same command again after an interruption to continue.")
    sw.add_argument("satellite", help=PRESET_HELP)
    from .params import NAMES, unit
    for n in NAMES:
        sw.add_argument(f"--{n}", metavar="GRID", default=None,
                        help=argparse.SUPPRESS if n not in ("E1", "E2", "c1", "c2") else
                        f"grid of {n} [{unit(n)}], e.g. 0:0.02:41 (any parameter of "
                        f"'tethersim show' works the same way)")
    sw.add_argument("--periods", type=float, default=50.0,
                    help="orbits per run (default 50: three days, thesis p. 5-6)")
    sw.add_argument("--faithful", action="store_true",
                    help="the thesis's fixed RK4 step (26.55 s at 200 km) instead of DOP853")
    _add_model_arg(sw)
    sw.add_argument("--rtol", type=float, default=1e-9, help="DOP853 relative tolerance (default 1e-9)")
    sw.add_argument("--workers", type=int, default=None,
                    help="threads on this machine (default: every core)")
    sw.add_argument("--dask-workers", type=int, default=None, metavar="N",
                    help="start a local Dask cluster of N worker processes")
    sw.add_argument("--scheduler", default=None, metavar="ADDR",
                    help="Dask scheduler address, e.g. tcp://10.0.0.5:8786")
    sw.add_argument("--out", default=None, help="output folder (default results/<sat>-sweep-<axes>)")
    sw.add_argument("--restart", action="store_true", help="discard a previous store in --out")
    sw.add_argument("--no-plots", action="store_true", help="skip the stability map PNG")
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    add_override_args(sw)
    sw.set_defaults(func=cmd_sweep)

    tn = sub.add_parser(
        "tune", help="nominal E2 (centre of the stable band) and damping, written as a preset",
        description="Find, by converged simulation, the E2 at the centre of the stable band for "
                    "a given E1 and the damping factor that settles fastest without turning "
                    "over (thesis p. 5-7, 5-18); write the tuned satellite as a preset TOML.")
    tn.add_argument("satellite", help=PRESET_HELP)
    tn.add_argument("--E1", type=float, default=None, help="E1 [N/mm^2] (default: the preset's)")
    tn.add_argument("--periods", type=float, default=50.0, help="orbits per run (default 50)")
    _add_model_arg(tn)
    tn.add_argument("--workers", type=int, default=None, help="threads (default: every core)")
    tn.add_argument("--out", default=None, help="preset file to write (default results/<sat>-tuned.toml)")
    add_override_args(tn)
    tn.set_defaults(func=cmd_tune)

    rp = sub.add_parser(
        "report", help="the whole of thesis chapter 5 as one HTML page",
        description="Validation tables, nominal runs, SatI's headline cases faithful and "
                    "converged, force breakdowns, six stability maps (converged, faithful, "
                    "predicted) and a table of the thesis's statements beside ours.  Sweeps "
                    "are resumable: run again after an interruption.")
    rp.add_argument("--out", default="results/report", help="output folder (default results/report)")
    rp.add_argument("--grid", type=int, default=41,
                    help="points per map axis (default 41, the thesis's sweep, p. 5-18)")
    rp.add_argument("--periods", type=float, default=50.0,
                    help="orbits per run of the nominal runs, forces and maps (default 50); "
                         "the headline cases keep the thesis's own run lengths")
    rp.add_argument("--workers", type=int, default=None, help="threads (default: every core)")
    rp.add_argument("--quiet", action="store_true", help="no progress bars")
    rp.set_defaults(func=cmd_report)

    show = sub.add_parser("show", help="print a preset's parameters with units")
    show.add_argument("satellite", help=PRESET_HELP)
    add_override_args(show)
    show.set_defaults(func=cmd_show)

    cmp_ = sub.add_parser("compare", help="run a satellite under several model variants, plot "
                                          "them together",
                          description="Run the same satellite (with --set/--scale) under each "
                                      "model variant; write compare.png (theta, delta_x, delta_y "
                                      "and theta differences from the first model) and "
                                      "compare.csv (metrics per model), print the table and "
                                      "say where the outcome classes differ.")
    cmp_.add_argument("satellite", help=PRESET_HELP)
    cmp_.add_argument("--models", default=",".join(_model_names()),
                      help=f"comma-separated model variants, the first is the reference "
                           f"(default and allowed: {','.join(_model_names())})")
    cmp_.add_argument("--periods", type=float, default=50.0, help="orbits to simulate (default 50)")
    cmp_.add_argument("--steps", type=int, default=None,
                      help="RK4: number of steps (default 300 per orbit); adaptive: number of "
                           "output samples (default 200 per orbit); output memory is limited "
                           "(TETHERSIM_MAX_OUTPUT_BYTES, default 2 GiB)")
    cmp_.add_argument("--method", choices=("adaptive", "rk4"), default="adaptive",
                      help="adaptive DOP853 (default, converged) or fixed-step RK4")
    cmp_.add_argument("--faithful", action="store_true",
                      help="the thesis's scheme: fixed-step RK4, tether switches not located")
    cmp_.add_argument("--rtol", type=float, default=1e-10, help="adaptive relative tolerance")
    cmp_.add_argument("--out", default=None,
                      help="output folder (default results/<sat>-compare)")
    cmp_.add_argument("--quiet", action="store_true", help="no progress bar")
    add_override_args(cmp_)
    cmp_.set_defaults(func=cmd_compare)
    frc = sub.add_parser("forces", help="generalized force of each family on each coordinate",
                         description="Simulate, then plot every force family's generalized "
                                     "force on delta_x [N], delta_y [N] and theta [N m] "
                                     "(thesis Figs 5.7-5.20) with a zoomed panel for the small "
                                     "families; write forces_delta_x/delta_y/theta.png and "
                                     "forces.csv (largest force per coordinate).")
    frc.add_argument("satellite", help=PRESET_HELP)
    frc.add_argument("--periods", type=float, default=50.0, help="orbits to simulate (default 50)")
    _add_model_arg(frc)
    frc.add_argument("--faithful", action="store_true",
                     help="the thesis's scheme: fixed-step RK4, 200 steps per orbit (26.55 s "
                          "at 200 km), tether switches not located")
    frc.add_argument("--out", default=None,
                     help="output folder (default ./results/<preset>-forces)")
    frc.add_argument("--quiet", action="store_true", help="no progress bar")
    add_override_args(frc)
    frc.set_defaults(func=cmd_forces)

    hdl = sub.add_parser("headlines", help="the thesis's headline results, faithful and converged",
                         description="Rerun the thesis's SatI headlines (nominal settling, "
                                     "E1 +50 %% tumble, ~pi/2 offsets at 10 %% off, damping x10 "
                                     "upside down) with RK4 at the thesis's step, 1/2 and 1/4 of "
                                     "it, and adaptive DOP853, for each model variant; print a "
                                     "verdict per claim; write headlines.csv, "
                                     "headlines_verdicts.csv and a theta(t) PNG per case "
                                     "(docs/headlines.md).")
    hdl.add_argument("satellite", nargs="?", default="satI",
                     help=PRESET_HELP + " (default satI; the claims are the thesis's for SatI)")
    hdl.add_argument("--out", default="results/headlines", help="output folder "
                     "(default ./results/headlines)")
    hdl.add_argument("--models", nargs="+", choices=_model_names(),
                     default=["derived", "printed", "objective-damper"],
                     help="model variants (default: derived, printed, objective-damper)")
    hdl.add_argument("--cases", nargs="+", default=None, metavar="CASE",
                     help="headline cases (default all): nominal, moduli-nominal, E1+50%%, "
                          "E1-10%%, E1+10%%, E2-10%%, E2+10%%, damping-x10")
    hdl.add_argument("--periods", type=float, default=None,
                     help="run every case for this many orbits at the thesis's step size "
                          "(default: the thesis's 5 or 50; for quick checks)")
    hdl.add_argument("--scan", action="store_true",
                     help="also scan the damping factor (1..10,000) and the RK4 step "
                          "(damping x10); ~30 s")
    hdl.add_argument("--no-plots", action="store_true", help="skip the PNGs")
    hdl.add_argument("--quiet", action="store_true", help="no progress lines")
    add_override_args(hdl)
    hdl.set_defaults(func=cmd_headlines)
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
    except KeyboardInterrupt:  # Ctrl-C outside a run that keeps its own partial output
        print("tethersim: interrupted (Ctrl-C)", file=sys.stderr)
        return 130


if __name__ == "__main__":
    raise SystemExit(main())
