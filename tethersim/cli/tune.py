"""``tethersim tune``: the nominal E2 (centre of the stable band) and damping, as a preset.

Finds, by converged simulation, the E2 at the centre of the stable band for a
given E1 and the damping factor that settles fastest without turning over
(thesis p. 5-7, 5-18); writes the tuned satellite as a preset TOML to
``results/<satellite>/tuned.toml`` (or ``--out``).  A file tuned from another
satellite or other --set/--scale is not replaced unless ``--force``.
"""
from __future__ import annotations

from pathlib import Path

from tethersim.cli import options

HELP = "nominal E2 (centre of the stable band) and damping, written as a preset"


def add_parser(sub) -> None:
    """Declare ``tune`` and its options on the subparsers ``sub``."""
    p = sub.add_parser(
        "tune", help=HELP,
        description="Find, by converged simulation, the E2 at the centre of the stable band for "
                    "a given E1 and the damping factor that settles fastest without turning "
                    "over (thesis p. 5-7, 5-18); write the tuned satellite as a preset TOML.")
    options.add_satellite(p)
    p.add_argument("--E1", type=options.positive_float, default=None, metavar="VALUE",
                   help="E1 [N/mm^2] (default: the satellite's)")
    options.add_periods(p, help="orbits per run (default 50)")
    options.add_model(p)
    p.add_argument("--workers", type=options.positive_int, default=None, metavar="N",
                   help="threads (default: every core; at most 4 per core)")
    options.add_out(p, "results/<satellite>/tuned.toml; a file, not a folder")
    options.add_overrides(p)
    p.set_defaults(func=run)


def _check_target(out: Path, origin: str, force: bool) -> None:
    """Refuse to replace a preset tuned from another satellite (its header names the origin)."""
    if force or not out.is_file():
        return
    try:
        text = out.read_text()
    except OSError:
        return
    if origin not in text:
        first = text.splitlines()[0] if text else "(empty)"
        raise options.UsageError(
            f"--out {out} holds another preset ({first.lstrip('# ')}), not one tuned {origin}: "
            f"give another --out, or --force to replace it")


def run(args) -> int:
    """Run the command.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options of ``tune``.

    Returns
    -------
    int
        0.
    """
    from tethersim.cli import preflight
    from tethersim.experiments.tune import tune
    from tethersim.model.params import from_si, to_si
    from tethersim.model.presets.write import dumps
    from tethersim.output.files import write_text

    preflight.check_workers(args, "workers")
    sat = options.satellite(args)
    from tethersim.cli.overrides import refuse_unused
    refuse_unused(args, sat, (args.model,))
    out = Path(args.out) if args.out else options.default_out(args, "tuned.toml")
    preflight.check_file(out)
    record = options.provenance(args, sat)
    origin = " ".join([f"from {record['from']}", *record["overrides"]])
    _check_target(out, origin, args.force)
    try:  # before the runs, so a bad folder costs nothing
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {out}: cannot create its folder: {exc.strerror}") from None
    r = tune(sat, E1=None if args.E1 is None else to_si("E1", args.E1), periods=args.periods,
             model=args.model, workers=args.workers)
    t = r.satellite
    lo, hi = (from_si("E2", v) for v in r.band)
    print(f"{t.name}: stable band at E1 = {from_si('E1', t.E1):.6g} N/mm^2 and the chosen "
          f"damping: E2 = {lo:.6g} .. {hi:.6g} N/mm^2 (|theta_ss| <= 0.05 rad)")
    print(f"  E2 (band centre) = {from_si('E2', t.E2):.6g} N/mm^2, E2/E1 = {t.E2 / t.E1:.4g} "
          f"(b/a = {t.b / t.a:.4g})")
    print("  damping factor   class        settling [h]   theta_ss [rad]  "
          "(band centre before damping)")
    for k, name, ts, th in r.damping_scan:
        mark = "  <- chosen" if k == r.damping_factor else ""
        print(f"  {k:14.4g}   {name:<12} {ts / 3600:10.4g}   {th:+12.4f}{mark}")
    print(f"  c1 = {t.c1:.4g} N s/m, c2 = {t.c2:.4g} N s/m; {r.runs} runs of "
          f"{args.periods:g} orbits")
    how = f"tethersim tune ({args.periods:g}-orbit converged runs, model {args.model})"
    notes = {"E1": "given", "E2": f"centre of the stable band {lo:.6g}..{hi:.6g} N/mm^2 ({how})",
             "c1": f"fastest stable settling (|theta_ss| <= 0.025 rad) over k x base damping, "
                   f"k = {r.damping_factor:.4g}; E2 then re-centred",
             "c2": "same factor as c1"}
    write_text(out, dumps(t, notes, header=f"{t.name} tuned by {how} {origin}"))
    print(f"wrote {out}")
    return 0
