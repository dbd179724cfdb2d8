"""Output folders: one per satellite, never silently holding another's results.

Each command writes into ``results/<satellite>/...`` (or ``--out``) and records in
the folder (summary.json for ``run``, satellite.json for the others) whose results
it holds — satellite, source file, --set/--scale, model — and which files it wrote.
A command for another satellite, parameters or model is refused unless ``--force``;
a command that writes into the folder removes the files the previous record listed
that it did not write again, so no plot of another run is left beside a summary.
The commands reach these through :mod:`tethersim.cli.options`.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

RESULTS = Path("results")
# the files that record whose results a folder holds; `run` records it in summary.json
PROVENANCE_FILES = ("summary.json", "satellite.json")


def satellite_key(arg: str) -> str:
    """A folder name for the satellite argument: the preset's name as shipped (satI, satII,
    dumbsat) or the TOML file's stem, with anything but letters, digits, '.', '_', '-'
    replaced by '_'."""
    from tethersim.model.presets import PRESET_NAMES
    stem = Path(PRESET_NAMES.get(arg.lower(), arg)).stem
    return re.sub(r"[^A-Za-z0-9._-]", "_", stem) or "satellite"


def default_out(args, *parts: str) -> Path:
    """results/<satellite>/<parts...>: one folder per satellite (see :func:`satellite_key`)."""
    return RESULTS.joinpath(satellite_key(args.satellite), *parts)


def provenance(args, sat) -> dict:
    """Whose results a folder holds: the satellite's name, where it came from, the overrides,
    the model (or ``--models``).

    What changes the results' meaning: another satellite, other parameters, other
    equations.  The integrator options and ``--periods`` are not in it: a rerun of the
    same question more accurately (``run satI --faithful`` after ``run satI``) replaces
    the folder's run; its summary.json says which integrator made it.
    """
    from tethersim.cli.options import models, overrides
    from tethersim.model.presets import PRESET_NAMES
    key = args.satellite.lower()
    origin = (Path(PRESET_NAMES[key]).stem if key in PRESET_NAMES
              else str(Path(args.satellite).resolve()))
    model = ",".join(models(args)) if getattr(args, "models", None) else getattr(args, "model",
                                                                                 None)
    return {"satellite": sat.name, "from": origin, "overrides": overrides(args), "model": model}


def _describe(p: dict) -> str:
    if not p.get("satellite"):  # written before tethersim recorded it
        return "an unrecorded satellite"
    text = f"{p['satellite']} ({p.get('from') or '?'})"
    text += f" model {p['model']}" if p.get("model") else ""
    return text + (" " + " ".join(p["overrides"]) if p.get("overrides") else "")


def claim_folder(out: Path, args, sat) -> dict:
    """Create ``out`` for this satellite's results, refusing one that holds another's.

    The folder's ``summary.json`` (run) or ``satellite.json`` (other commands)
    records whose results it holds; unless ``--force``, a folder of another
    satellite, source, --set/--scale or model stops the command before anything
    runs.  The files a previous run wrote and this one does not are removed when
    this one writes its record (:func:`write_record`).

    Returns
    -------
    dict
        This run's provenance, to write with :func:`write_provenance` (or into summary.json).

    Raises
    ------
    UsageError
        The folder holds results of another satellite (one line naming both).
    ValueError
        The folder cannot be created.
    """
    from tethersim.cli.options import UsageError
    mine = provenance(args, sat)
    if not args.force:
        for name in PROVENANCE_FILES:
            path = out / name
            if not path.is_file():
                continue
            try:
                theirs = json.loads(path.read_text())
            except (OSError, ValueError):
                theirs = {}
            if not isinstance(theirs, dict):
                theirs = {}
            if theirs and "model" not in theirs:  # written before the model was recorded
                theirs["model"] = mine["model"]
            theirs = {k: theirs.get(k) for k in mine}
            theirs["overrides"] = theirs["overrides"] or []
            if theirs != mine:
                raise UsageError(
                    f"--out {out} holds results of {_describe(theirs)}, not "
                    f"{_describe(mine)}: give another --out, or --force to replace them")
    try:  # before the run, so a bad folder costs nothing
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"--out {out}: cannot create the output folder: {exc.strerror}") from None
    return mine


def write_provenance(out: Path, record: dict, written=()) -> Path:
    """Write ``out/satellite.json`` (whose results the folder holds, and the files
    ``written``); see :func:`write_record`."""
    return write_record(out, "satellite.json", record, written)


def write_record(out: Path, name: str, record: dict, written=()) -> Path:
    """Write the folder's record ``out/name`` (summary.json, satellite.json), listing
    the files this command wrote, after removing those the previous record listed
    that this command did not write again.

    A 3-D run's roll.png and yaw.png are not left beside a planar run's summary that
    replaced it.  Only files named in the previous record are removed (regular files
    inside ``out``), never anything else in the folder.

    Parameters
    ----------
    out : Path
        The output folder.
    name : str
        The record's file name (one of :data:`PROVENANCE_FILES`).
    record : dict
        What to write (JSON; values it cannot encode as text).
    written : sequence of Path
        The files (or folders) this command wrote into ``out``.

    Returns
    -------
    Path
        The record.
    """
    from tethersim.output.files import write_text
    path = out / name
    mine = [f for f in (_inside(out, p) for p in written) if f] + [name]
    for stale in set(_listed(path)) - set(mine):
        target = out / stale
        if target.is_file() and not target.is_symlink():
            target.unlink()
    return write_text(path, json.dumps({**record, "files": sorted(set(mine))}, indent=2,
                                       default=str) + "\n")


def _inside(out: Path, p) -> str | None:
    """``p`` relative to ``out`` (posix), or None for a file outside it."""
    try:
        return Path(p).resolve().relative_to(out.resolve()).as_posix()
    except ValueError:
        return None


def _listed(record: Path) -> list:
    """The files a folder's record lists: relative paths inside the folder only (a hand-
    edited record naming '../x' or an absolute path lists nothing to remove)."""
    try:
        files = json.loads(record.read_text()).get("files") or []
    except (OSError, ValueError, AttributeError):
        return []
    return [f for f in files if isinstance(f, str) and f and not Path(f).is_absolute()
            and ".." not in Path(f).parts]
