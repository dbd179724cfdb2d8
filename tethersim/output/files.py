"""Every file tethersim writes is complete or absent: written under a temporary name in
its own folder, then renamed into place.

A Ctrl-C (or SIGTERM, or a full disk) while a file is being written used to leave it
truncated beside complete ones (issue 19: a half ``timeseries.csv``).  ``os.replace``
within one folder is atomic on POSIX and Windows, so a reader sees the old file or the
new one, never part of one; the temporary file is removed if the writer fails.  The
temporary name starts with a dot and keeps the file's suffix (matplotlib and PIL choose
the format from it).
"""
from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from pathlib import Path

TEMPORARY_MARK = ".partial-"  # in every temporary name: .timeseries.partial-<pid>.csv


def temporary_name(path) -> Path:
    """The temporary file a write of ``path`` goes through (same folder, same suffix)."""
    path = Path(path)
    return path.with_name(f".{path.stem}{TEMPORARY_MARK}{os.getpid()}{path.suffix}")


@contextlib.contextmanager
def replacing(path) -> Iterator[Path]:
    """Write to the yielded temporary path; on success it replaces ``path``.

    Parameters
    ----------
    path : str or Path
        The file to write.

    Yields
    ------
    Path
        A temporary path beside ``path``.  If the block raises (KeyboardInterrupt
        included) the temporary file is removed and ``path`` is left as it was.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> target = Path(tempfile.mkdtemp()) / "a.txt"
    >>> with replacing(target) as tmp:
    ...     _ = tmp.write_text("done")
    >>> target.read_text()
    'done'
    """
    path = Path(path)
    tmp = temporary_name(path)
    try:
        yield tmp
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise


def write_text(path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` through :func:`replacing`; return the path."""
    with replacing(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def save_figure(fig, path, **savefig_kwargs) -> Path:
    """``fig.savefig`` to ``path`` through :func:`replacing`; return the path."""
    with replacing(path) as tmp:
        fig.savefig(tmp, **savefig_kwargs)
    return Path(path)
