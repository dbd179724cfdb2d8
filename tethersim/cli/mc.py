"""``tethersim mc``: Monte Carlo over what is uncertain (docs/montecarlo.md).

Each sample draws the epoch over the bundled space-weather history (so its runs see a
real daily F10.7/Ap sequence), CD, balloon area, tether moduli and damping, and the
deployment state, each from its own random stream; runs the held circular orbit to
settle and the free orbit to re-entry; and the summary gives P(settles before re-entry),
P(tumbles), quantiles of settling time and lifetime with 95 % intervals and, with
``--sobol N``, Sobol' indices.  Resumable: run the same command again.
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options, parallel

HELP = "Monte Carlo over space weather, drag, inflation, tethers and deployment"


def _range(text: str) -> tuple:
    """``NAME=LOW:HIGH`` -> (name, low, high); numbers, or ISO days for epoch."""
    name, sep, band = text.partition("=")
    low, sep2, high = band.partition(":")
    if not (sep and sep2 and name.strip() and low.strip() and high.strip()):
        raise options.UsageError(f"--range {text}: expected NAME=LOW:HIGH, e.g. CD=0.9:1.1 "
                                 f"or epoch=1996-05-01:2008-12-31")
    name = name.strip()
    if name == "epoch":
        return name, low.strip(), high.strip()
    try:
        return name, float(low), float(high)
    except ValueError:
        raise options.UsageError(f"--range {text}: LOW and HIGH must be numbers") from None


def add_parser(sub) -> None:
    """Declare ``mc`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "mc", help=HELP,
        description="Monte Carlo over what is uncertain: the epoch (each run reads the "
                    "bundled table's real daily F10.7/Ap along its days), drag coefficient, "
                    "balloon area, tether moduli and damping, and the deployment (pitch, "
                    "pitch rate, separation speed), each drawn from its own random stream "
                    "(bands: docs/montecarlo.md).  Per sample: the held circular orbit for "
                    "--periods orbits (settling) and the free orbit in per-body NRLMSISE-00 "
                    "air until it re-enters or loses its balloon (life).  Writes samples.csv, "
                    "summary.csv, distributions.png (and sobol.png) and a resumable store "
                    "under --out; the same seed gives the same store at any thread or worker "
                    "count.")
    options.add_satellite(p)
    p.add_argument("--n", type=options.int_range(1, 100_000), default=200, metavar="N",
                   help="random samples (default 200; 1..100000)")
    p.add_argument("--seed", type=options.int_range(0, 2 ** 63 - 1), default=0, metavar="S",
                   help="seed of every input's stream and the Sobol' design (default 0)")
    options.add_periods(p, help="orbits of each settling run (default 50: three days)")
    p.add_argument("--max-lifetime", type=options.positive_float, default=240.0, metavar="H",
                   help="cap on the free run [h] (default 240), at least the settling run's "
                        "length; a life past it is reported as '>= cap'")
    p.add_argument("--sobol", type=options.int_range(0, 2 ** 16), default=0, metavar="N",
                   help="base size of a Sobol' design (a power of two, e.g. 64: N x (inputs + "
                        "2) more runs) for first-order and total indices (default 0: none)")
    p.add_argument("--range", action="append", default=[], metavar="NAME=LOW:HIGH",
                   help="replace an input's band, in its unit of docs/montecarlo.md (a factor "
                        "for CD, A3, E1, E2, c1, c2; deg, deg/s, m/s offsets for theta0, "
                        "theta_dot0, delta_x_dot0; ISO days for epoch); repeatable")
    p.add_argument("--rtol", type=options.rtol_float, default=1e-9,
                   help="DOP853 relative tolerance of every run (default 1e-9)")
    options.add_model(p)
    parallel.add_parallel(p)
    options.add_out(p, "results/<satellite>/mc-seed<S>")
    options.add_quiet(p)
    options.add_overrides(p)
    p.set_defaults(func=run, interrupted_hint="run the same command again to continue")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``mc``.

    Returns
    -------
    int
        0; an interrupted run raises (main reports it, exit 130).
    """
    import math

    from tethersim.cli import preflight
    from tethersim.cli.overrides import refuse
    from tethersim.experiments.mc import MCSpec, run_mc, summarise, summary_rows
    from tethersim.experiments.mc.run import column
    from tethersim.experiments.mc.spec import OWN_FIELDS
    from tethersim.model.registry import BY_NAME
    from tethersim.output.plots.mc import plot_distributions, plot_sobol
    from tethersim.output.tables import write_rows, write_table

    if BY_NAME[args.model].orbit == "free":
        raise options.UsageError(f"--model {args.model}: mc takes a circular-orbit model; it "
                                 f"runs the settling on the held circular orbit and the life "
                                 f"with the model's free twin")
    parallel.check_parallel(args)
    refuse(args, [*OWN_FIELDS, "atmosphere", "density"],
           lambda n: f"the Monte Carlo sets {n} per sample (held circular and free orbit, "
                     f"drawn epoch, the table's daily indices): drop it")
    ranges = tuple(_range(t) for t in args.range)
    if len({r[0] for r in ranges}) < len(ranges):
        raise options.UsageError("--range: one band per input")
    sat = options.satellite(args)
    names = {"periods": "--periods", "max_lifetime_h": "--max-lifetime", "n": "--n",
             "seed": "--seed", "sobol": "--sobol", "range of": "--range"}
    try:
        spec = MCSpec(sat, n=args.n, seed=args.seed, periods=args.periods,
                      max_lifetime_h=args.max_lifetime, sobol=args.sobol, model=args.model,
                      rtol=args.rtol, ranges=ranges)
    except ValueError as exc:  # name the option, not the field
        text = str(exc)
        for field, option in names.items():
            if text.startswith(field):
                raise options.UsageError(f"{option}: {text}") from None
        raise
    out = Path(args.out) if args.out else options.default_out(args, f"mc-seed{args.seed}")
    files = ("samples.csv", "summary.csv", "distributions.png", "sobol.png")
    preflight.check_files(out, files)
    preflight.check_subfolder(out, "store")
    if args.force:
        import shutil
        shutil.rmtree(out / "store", ignore_errors=True)
    total = spec.n + spec.size("sobol")
    if not args.quiet:
        print(f"{total} samples ({spec.n} random, {spec.size('sobol')} Sobol' design), each a "
              f"{spec.periods:g}-orbit settling run and a free run capped at "
              f"{spec.max_lifetime_h:g} h (model {spec.model}, rtol {spec.rtol:g}) -> "
              f"{out / 'store'}")
    rows = run_mc(spec, out / "store", workers=args.workers, scheduler=args.scheduler,
                  dask_workers=args.dask_workers, progress=options.progress(args))
    s = summarise(rows, spec)
    inputs = [column(n) for n in spec.names]
    cols = ["part", "i", *inputs, "class", "settling_time_s", "theta_ss_rad", "tumbled",
            "circular_status", "free_status", "lifetime_s", "life_end", "settles",
            "settles_in_life"]
    written = [write_table(out / "samples.csv", rows, [(c, c) for c in cols])]
    table = summary_rows(s)
    written.append(write_rows(out / "summary.csv", table))
    run_h = spec.periods * sat.period / 3600
    written.append(plot_distributions(rows, out / "distributions.png", run_h=run_h,
                                      cap_h=spec.max_lifetime_h,
                                      title=f"{sat.name}: {spec.n} samples, seed {spec.seed}"))
    if s["sobol"]:
        written.append(plot_sobol(s["sobol"], out / "sobol.png",
                                  title=f"{sat.name}: Sobol' indices, N = {spec.sobol}"))

    def fmt(x, beyond):
        return beyond if x == math.inf else "-" if x == -math.inf else f"{x:.4g}"

    print(f"{'quantity':<40} {'estimate':>10} {'95% CI':>24}")
    for r in table:
        if r["quantity"].startswith(("S1 ", "ST ")):
            continue
        # inf: a censored value, beyond the settling run (never settled) or the cap
        b = "> run" if "settling" in r["quantity"] else "> cap"
        ci = f"[{fmt(r['ci_low'], b)}, {fmt(r['ci_high'], b)}]"
        print(f"{r['quantity']:<40} {fmt(r['estimate'], b):>10} {ci:>24}")
    for output, idx in s["sobol"].items():
        print(f"Sobol' {output}: " + ", ".join(f"{k} S1 {v['S1']:.2f} ST {v['ST']:.2f}"
                                               for k, v in idx.items()))
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
