"""Checks a command makes before any work or file: sizes, worker counts, output paths.

A refusal after an hour of runs (an output path that is a directory, a run too
large for memory) costs the hour; each check here is cheap arithmetic or a stat,
and its error is one line naming the option and what is allowed.
"""
from __future__ import annotations

import os
from pathlib import Path

from tethersim.cli.options import UsageError

# --workers/--dask-workers: threads or processes beyond a few per core only add memory and
# start-up (each Dask worker is a process with its own import and JIT cache load); at
# 1000 on 2 cores the local cluster failed with tracebacks from distributed
WORKERS_PER_CORE = 4


def max_workers() -> int:
    """The most workers a command accepts: :data:`WORKERS_PER_CORE` x the machine's cores."""
    return WORKERS_PER_CORE * (os.cpu_count() or 1)


def check_workers(args, *names: str) -> None:
    """Refuse a --workers-like option above :func:`max_workers`, naming it and the cap.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options.
    names : str
        Attribute names of the options (``"workers"``, ``"dask_workers"``).

    Raises
    ------
    UsageError
        One line: the option, its value and the allowed range.
    """
    cap = max_workers()
    for name in names:
        n = getattr(args, name, None)
        if n is not None and n > cap:
            raise UsageError(f"--{name.replace('_', '-')} {n}: allowed 1..{cap} "
                             f"({WORKERS_PER_CORE} per core, {os.cpu_count() or 1} cores)")


def check_run_size(args, how, subject: str, samples=None, check: bool = False) -> None:
    """simulate()'s output-size refusal, before the folder is made, naming ``subject``.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options (``args.periods``).
    how : tethersim.cli.options.Integrator
        The resolved integrator.
    subject : str
        The options that set the size, e.g. ``"--periods/--steps"``.
    samples : int, optional
        Adaptive output samples, if the command sets its own (else ``how.samples``).
    check : bool
        Whether the run includes the convergence check's rerun.
    """
    from tethersim.engine.guards import check_simulation
    check_simulation(args.periods, how.steps, how.method,
                     samples if samples is not None else how.samples, check, subject=subject)


def _first_existing(path: Path) -> Path:
    p = path
    while not p.exists() and p != p.parent:
        p = p.parent
    return p


def check_folder(out: Path, option: str = "--out") -> None:
    """Refuse an output folder that is a file, or that cannot be created or written.

    Raises
    ------
    ValueError
        One line naming the option, the path and what is wrong.
    """
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise ValueError(f"{option} {out}: is a file, not a folder; give a folder")
    base = _first_existing(out)
    if not base.is_dir():
        raise ValueError(f"{option} {out}: {base} is a file, so the folder cannot be created; "
                         f"give another {option}")
    if not os.access(base, os.W_OK | os.X_OK):
        raise ValueError(f"{option} {out}: {base} is not writable; give another {option}")


def check_file(path: Path, option: str = "--out") -> None:
    """Refuse a file path the command could not write: a folder, read-only, or under a file.

    Raises
    ------
    ValueError
        One line naming the option, the path and what is wrong.
    """
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{option} {path}: is a folder, not a file; remove it or give "
                         f"another {option}")
    if path.exists() and not os.access(path, os.W_OK):
        raise ValueError(f"{option} {path}: is not writable; give another {option}")
    base = _first_existing(path.parent)
    if not base.is_dir():
        raise ValueError(f"{option} {path}: {base} is a file, so its folder cannot be created; "
                         f"give another {option}")
    if not os.access(base, os.W_OK | os.X_OK):
        raise ValueError(f"{option} {path}: {base} is not writable; give another {option}")


def check_files(out: Path, names, option: str = "--out") -> None:
    """Refuse a command whose files in ``out`` could not be written, before it runs.

    Parameters
    ----------
    out : pathlib.Path
        The output folder (checked with :func:`check_folder`).
    names : iterable of str
        The files the command will write there.
    option : str
        The option that named the folder.

    Raises
    ------
    ValueError
        One line naming the option and the file that is a folder or not writable.
    """
    check_folder(out, option)
    for name in names:
        path = Path(out) / name
        if path.is_dir():
            raise ValueError(f"{option} {out}: {path} is a folder, so the command could not "
                             f"write it; remove it or give another {option}")
        if path.exists() and not os.access(path, os.W_OK):
            raise ValueError(f"{option} {out}: {path} is not writable; give another {option}")


def check_subfolder(out: Path, name: str, option: str = "--out") -> None:
    """Refuse ``out/name``, a folder the command writes (a store), when it is a file."""
    path = Path(out) / name
    if path.exists() and not path.is_dir():
        raise ValueError(f"{option} {out}: {path} is a file, not a folder; remove it or give "
                         f"another {option}")
