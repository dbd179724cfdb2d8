"""A store of finished rows, one JSON line each, beside the ``spec.json`` that made them.

The feasibility atlas (``points.jsonl``), the Monte Carlo (``rows.jsonl``) and the
design search (``evaluations.jsonl``) keep what they finish the same way, so one class
does it: the folder is locked for one writer (:class:`~tethersim.experiments.sweep.lock.
StoreLock`), a folder holding another spec's rows is refused in one line, each finished
row is appended and flushed at once (an interrupted run loses nothing finished), and a
line cut by an interruption is dropped on reading (that row reruns).
"""
from __future__ import annotations

import json
import os
from pathlib import Path

from tethersim.experiments.sweep.lock import StoreLock

SPEC_FILE = "spec.json"


def read_lines(path) -> list:
    """The rows of a JSON-lines file (none if it is absent; a cut line is dropped)."""
    path = Path(path)
    rows = []
    if path.exists():
        for line in path.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except ValueError:  # a line cut by an interruption: that row reruns
                continue
    return rows


class LineStore:
    """``folder/spec.json`` and ``folder/<rows>``: a context manager holding the lock.

    Parameters
    ----------
    folder : path-like
        The store folder (created).
    rows : str
        The rows' file name (``*.jsonl``).
    spec_text : str
        The spec as JSON: written on a new store, compared on a resumed one.
    what : str
        What the store holds, for the refusal (``"a Monte Carlo"``).
    remedy : str
        The refusal's advice.

    Raises
    ------
    ValueError
        On entering, when ``folder`` holds another spec's rows (one line naming it).
    """

    def __init__(self, folder, rows: str, spec_text: str, what: str,
                 remedy: str = "use another --out or remove it"):
        self.folder = Path(folder)
        self.path = self.folder / rows
        self.spec_text, self.what, self.remedy = spec_text, what, remedy
        self.fh = None

    def __enter__(self) -> LineStore:
        self.folder.mkdir(parents=True, exist_ok=True)
        self.lock = StoreLock(self.path)
        self.lock.__enter__()
        try:
            spec_path = self.folder / SPEC_FILE
            if spec_path.exists() and spec_path.read_text() != self.spec_text:
                raise ValueError(f"{self.folder} holds {self.what} of other settings: "
                                 f"{self.remedy}")
            spec_path.write_text(self.spec_text)
        except BaseException:
            self.lock.__exit__(None, None, None)
            raise
        return self

    def rows(self) -> list:
        """The finished rows on file, in the order written."""
        return read_lines(self.path)

    def put(self, row: dict, flush: bool = True) -> None:
        """Append one finished row (flushed unless ``flush`` is False)."""
        if self.fh is None:
            self.fh = self.path.open("a")
        self.fh.write(json.dumps(row) + "\n")
        if flush:
            self.fh.flush()

    def flush(self) -> None:
        """Flush what :meth:`put` wrote with ``flush=False``."""
        if self.fh is not None:
            self.fh.flush()

    def rewrite(self, rows: list) -> None:
        """Hold exactly ``rows``, in that order (a temporary file renamed over the rows'), so
        a store has the same bytes however its rows were computed; unchanged files are left."""
        if self.fh is not None:
            self.fh.close()
            self.fh = None
        lines = "".join(json.dumps(r) + "\n" for r in rows)
        if (self.path.read_text() if self.path.exists() else "") != lines:
            tmp = self.path.with_suffix(".tmp")
            tmp.write_text(lines)
            os.replace(tmp, self.path)

    def __exit__(self, *exc) -> None:
        try:
            if self.fh is not None:
                self.fh.close()
                self.fh = None
        finally:
            self.lock.__exit__(*exc)
