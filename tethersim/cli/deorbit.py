"""``tethersim deorbit``: the balloon as a de-orbit device (docs/deorbit.md).

Time to re-entry from each start altitude of ``--from LOW:HIGH:N`` with and without
the balloon, over epochs drawn as ``tethersim mc`` draws them (P10/P50/P90 with 95 %
intervals), their ratio, the 25-year (IADC/ISO 24113) and 5-year (FCC 2024) verdicts,
and the altitude where the towed balloon turns from trailing to hanging; with
``--runs K``, short coupled runs at K of the altitudes (trail angle against the closed
form, peak tether tensions, the host's pitch-rate envelope).
"""
from __future__ import annotations

import math
from pathlib import Path

from tethersim.cli import options
from tethersim.model.registry import BY_NAME

HELP = "lifetime with and without the balloon, trail or hang, 25/5-year verdicts"


def _from(text: str) -> tuple:
    """``LOW:HIGH:N`` [km, km, count] -> (low m, high m, n)."""
    parts = text.split(":")
    try:
        if len(parts) != 3:
            raise ValueError
        low, high, n = float(parts[0]), float(parts[1]), int(parts[2])
    except ValueError:
        raise options.UsageError(f"--from {text}: expected LOW:HIGH:N (km, km, a count), "
                                 f"e.g. 300:800:11") from None
    return low * 1e3, high * 1e3, n


def add_parser(sub) -> None:
    """Declare ``deorbit`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "deorbit", help=HELP,
        description="The balloon as a de-orbit device: the orbit-averaged circular decay "
                    "(da/dt = -rho B sqrt(mu a)(1 - wE/n)^2) from each start altitude to "
                    "re-entry in NRLMSISE-00 air averaged over the orbit, each UTC day with "
                    "its own F10.7/Ap from the bundled table, over --n epochs drawn as mc "
                    "draws them; with the balloon (B = CD (A1+A2+A3)/(m1+m2+m3), the balloon "
                    "keeping its frontal area) and without (the host alone).  --runs K adds "
                    "short coupled runs (trail angle, tether loads, pitch rates).  Writes "
                    "deorbit.csv, lifetimes.csv, deorbit.png (and runs.csv) under --out "
                    "(docs/deorbit.md).")
    options.add_satellite(p)
    p.add_argument("--from", dest="span", type=_from, default=_from("300:800:11"),
                   metavar="LOW:HIGH:N",
                   help="start altitudes [km]: N evenly from LOW to HIGH (default 300:800:11)")
    p.add_argument("--n", type=options.int_range(1, 10_000), default=100, metavar="EPOCHS",
                   help="epochs drawn over the bundled history (default 100; 1..10000)")
    p.add_argument("--seed", type=options.int_range(0, 2 ** 63 - 1), default=0, metavar="S",
                   help="seed of the epoch stream (mc's; default 0)")
    p.add_argument("--max-years", type=options.positive_float, default=200.0, metavar="Y",
                   help="cap on a lifetime [years] (default 200; at most 1000): a longer one "
                        "is reported as '> cap'")
    p.add_argument("--line-length", type=options.positive_float, default=None, metavar="M",
                   help="the balloon's distance from the centre of mass [m] for trail or hang "
                        "(default: the design's start offset)")
    p.add_argument("--runs", type=options.int_range(0, 20), default=0, metavar="K",
                   help="coupled runs at K of the altitudes (evenly picked, 0..20; default 0): "
                        "trail angle against the closed form, peak tether tensions, the host's "
                        "pitch-rate envelope (runs.csv)")
    options.add_periods(p, default=6.0, help="orbits of each coupled run (default 6)")
    p.add_argument("--model", choices=[m for m in options.model_names()
                                       if BY_NAME[m].orbit == "circular" and BY_NAME[m].geometry == "planar"],
                   default="objective-damper",
                   help="planar model of the coupled runs (default objective-damper: the "
                        "thesis damper pulls a balloon at rest across its line)")
    options.add_out(p, "results/<satellite>/deorbit-seed<S>")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run)


def _years(x: float, cap: float) -> str:
    return f"> {cap:g}" if math.isinf(x) else f"{x / (365.25 * 86400):.3g}"


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``deorbit``.

    Returns
    -------
    int
        0.
    """
    import numpy as np

    from tethersim.cli import preflight
    from tethersim.experiments.deorbit import check_altitudes, deorbit
    from tethersim.output.plots.deorbit import plot_deorbit
    from tethersim.output.tables import write_rows

    sat = options.satellite(args)
    if args.max_years > 1000:
        raise options.UsageError(f"--max-years {args.max_years:g}: at most 1000 years")
    try:
        h = check_altitudes(sat, *args.span)
    except ValueError as exc:
        raise options.UsageError(f"--{exc}") from None
    out = Path(args.out) if args.out else options.default_out(args, f"deorbit-seed{args.seed}")
    files = ("deorbit.csv", "lifetimes.csv", "deorbit.png", "runs.csv")
    if args.runs > h.size:
        raise options.UsageError(f"--runs {args.runs}: at most the {h.size} altitudes of --from")
    preflight.check_files(out, files)
    if not args.quiet:
        print(f"{sat.name}: {h.size} altitudes x {args.n} epochs, with and without the "
              f"balloon (B = {sat.CD * (sat.A1 + sat.A2 + sat.A3) / (sat.m1 + sat.m2 + sat.m3):.4g}"
              f" / {sat.CD * (sat.A1 + sat.A2) / (sat.m1 + sat.m2):.4g} m^2/kg)")
    r = deorbit(sat, h, n=args.n, seed=args.seed, max_years=args.max_years,
                line_length=args.line_length, progress=options.progress(args))
    cap = r["max_years"]
    table = []
    for row in r["rows"]:
        t = {"altitude_km": row["altitude"] / 1e3}
        for k in ("with", "without"):
            for p in ("p10", "p50", "p90"):
                est, lo, hi = row[f"{k}_{p}"]
                t[f"{k}_{p}_years"] = est / (365.25 * 86400)
                t[f"{k}_{p}_ci_low_years"] = lo / (365.25 * 86400)
                t[f"{k}_{p}_ci_high_years"] = hi / (365.25 * 86400)
        t["ratio_p50"] = row["ratio_p50"][0]
        for k in ("with", "without"):
            for y in (25, 5):
                t[f"{k}_{y}y_rule"] = row[f"{k}_{y}y"]
        table.append(t)
    out.mkdir(parents=True, exist_ok=True)
    written = [write_rows(out / "deorbit.csv", table)]
    epochs = [str(np.datetime64(int(e), "s")) for e in r["epochs"]]
    life_rows = [{"altitude_km": hh / 1e3, "epoch_utc": e,
                  "with_years": r["life"]["with"][i, j] / (365.25 * 86400),
                  "without_years": r["life"]["without"][i, j] / (365.25 * 86400)}
                 for i, hh in enumerate(h) for j, e in enumerate(epochs)]
    written.append(write_rows(out / "lifetimes.csv", life_rows))
    written.append(plot_deorbit(r, out / "deorbit.png",
                                title=f"{sat.name}: {args.n} epochs, seed {args.seed}"))
    print(f"{'alt km':>7} {'with P10/P50/P90 [y]':>24} {'alone P10/P50/P90 [y]':>24} "
          f"{'ratio':>6}  25y with/alone  5y with/alone")
    for row in r["rows"]:
        q = {k: "/".join(_years(row[f"{k}_{p}"][0], cap) for p in ("p10", "p50", "p90"))
             for k in ("with", "without")}
        ratio = row["ratio_p50"][0]
        print(f"{row['altitude'] / 1e3:7.0f} {q['with']:>24} {q['without']:>24} "
              f"{'>cap' if math.isinf(ratio) else f'{ratio:.3g}':>6}  "
              f"{row['with_25y']}/{row['without_25y']}  {row['with_5y']}/{row['without_5y']}")
    t = r["trail"]
    print(f"trail or hang (line {r['line_length']:.3g} m): trails below "
          f"{t['median'] / 1e3:.0f} km and hangs above it in the median day's air "
          f"({t['thin'] / 1e3:.0f} km on a thin day, {t['dense'] / 1e3:.0f} km on a dense one)")
    print("verdicts: met = P90 within the rule, failed = P10 beyond it, else epoch-dependent")
    if args.runs:
        written.append(_runs(args, sat, h, out))
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


def _runs(args, sat, h, out):
    """The coupled runs at ``args.runs`` of the altitudes ``h``: runs.csv and one line each."""
    import numpy as np
    from tqdm.auto import tqdm

    from tethersim.experiments.deorbit_runs import coupled_runs
    from tethersim.output.tables import write_rows

    pick = h[np.unique(np.round(np.linspace(0, h.size - 1, args.runs)).astype(int))]
    method = "implicit" if args.tethers else "adaptive"  # real lines are stiff
    with tqdm(total=pick.size, desc="coupled runs", unit="run", leave=False,
              disable=args.quiet, delay=1.0) as bar:
        runs = coupled_runs(sat, pick, args.periods, args.model, method, bar)
    rows = [{"altitude_km": r["altitude"] / 1e3, "status": r["status"],
             "trail_angle_deg": math.degrees(r["trail_angle"]),
             "closed_form_angle_deg": math.degrees(r["closed_form_angle"]),
             "trail_length_m": r["trail_length"], "epsilon": r["epsilon"],
             "peak_tension_1_N": r["peak_tension_1"], "peak_tension_2_N": r["peak_tension_2"],
             "max_pitch_rate_deg_s": math.degrees(r["max_rate"]),
             "settled_pitch_rate_deg_s": math.degrees(r["settled_rate"])} for r in runs]
    print(f"coupled runs ({args.periods:g} orbits, {args.model}, {method}; angle from the "
          f"vertical, 90 = level behind):")
    for r in rows:
        print(f"  {r['altitude_km']:5.0f} km {r['status']}: trail {r['trail_angle_deg']:5.1f} deg "
              f"(closed form {r['closed_form_angle_deg']:5.1f} at {r['trail_length_m']:.3g} m, "
              f"eps {r['epsilon']:.3g}), peak tension {r['peak_tension_1_N']:.3g} / "
              f"{r['peak_tension_2_N']:.3g} N, pitch rate max {r['max_pitch_rate_deg_s']:.3g} "
              f"settled {r['settled_pitch_rate_deg_s']:.3g} deg/s")
    return write_rows(out / "runs.csv", rows)
