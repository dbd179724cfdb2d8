"""One writer per sweep store: a lock file beside the store, naming its holder.

Two ``tethersim sweep`` processes creating the same new store at once used to
leave it corrupt (one deleted what the other was writing).  A writer now takes
an exclusive ``filelock`` lock on ``<store>.lock`` before it looks at the store
and holds it until the sweep ends; a second writer stops at once with a message
naming the first (pid, host, start time) read from ``<store>.lock.json``.  The
operating system drops the lock when its holder dies, even by SIGKILL, so a
stale owner file never blocks anyone.
"""
from __future__ import annotations

import json
import os
import socket
import time
from pathlib import Path

from filelock import FileLock, Timeout


class StoreLocked(ValueError):
    """Another process is writing the store; the message names it."""


def _owner_path(store: Path) -> Path:
    return store.with_name(store.name + ".lock.json")


def _read_owner(store: Path):
    try:
        info = json.loads(_owner_path(store).read_text())
        pid, host, since = int(info["pid"]), str(info["host"]), float(info["since"])
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if host == socket.gethostname():
        try:
            os.kill(pid, 0)  # signal 0: only asks whether the process exists
        except ProcessLookupError:
            return None  # a dead holder's file: the live one has not written yet
        except PermissionError:
            pass  # exists, another user's
    return pid, host, since


def holder(store, wait: float = 2.0) -> str:
    """Who holds the lock of ``store`` (best effort).

    The holder writes its name just after taking the lock, so a writer refused in that
    instant waits up to ``wait`` seconds for it.

    Parameters
    ----------
    store : path-like
        The store directory.
    wait : float
        Seconds to wait for a live holder's name.

    Returns
    -------
    str
        E.g. ``'pid 123 on host h since 2026-12-01 12:00:00 UTC'``.
    """
    deadline = time.monotonic() + wait
    while (owner := _read_owner(Path(store))) is None and time.monotonic() < deadline:
        time.sleep(0.02)
    if owner is None:
        return "a process that has not written its name"
    pid, host, since = owner
    return f"pid {pid} on host {host} since {time.strftime('%Y-%m-%d %H:%M:%S UTC', time.gmtime(since))}"


class StoreLock:
    """Exclusive writer lock of a sweep store (context manager; re-entrant within one object).

    Parameters
    ----------
    store : path-like
        The store directory (``.../sweep.zarr``); the lock is ``.../sweep.zarr.lock``.
    """

    def __init__(self, store):
        self.store = Path(store)
        self._lock = FileLock(str(self.store.with_name(self.store.name + ".lock")))

    def acquire(self) -> StoreLock:
        """Take the lock or raise :class:`StoreLocked` naming the holder; never waits."""
        self.store.parent.mkdir(parents=True, exist_ok=True)
        try:
            self._lock.acquire(timeout=0)
        except Timeout:
            raise StoreLocked(
                f"{self.store} is being written by another tethersim process "
                f"({holder(self.store)}): wait for it to finish, or stop it, then run again"
            ) from None
        info = {"pid": os.getpid(), "host": socket.gethostname(), "since": time.time()}
        _owner_path(self.store).write_text(json.dumps(info) + "\n")
        return self

    def release(self) -> None:
        """Release the lock and remove the owner file (a killed holder's file is ignored)."""
        if self._lock.is_locked:
            try:
                _owner_path(self.store).unlink()
            except OSError:
                pass
            self._lock.release()

    def __enter__(self):
        return self.acquire()

    def __exit__(self, *exc):
        self.release()
