"""Run a sweep's pending points on threads or a Dask cluster, flushing to the store.

Local: a thread pool (each task is a block of points run in one compiled,
nogil call, so threads use every core with no process start-up).  Distributed:
a Dask client's concurrent.futures executor — the same task function
(point.run_points) and the same result loop, so both paths write identical data.
"""
from __future__ import annotations

import concurrent.futures as cf
import math
import os
import time
from contextlib import contextmanager, nullcontext, suppress

from tqdm.auto import tqdm

from tethersim.experiments.sweep.plan import Plan
from tethersim.experiments.sweep.point import run_points
from tethersim.experiments.sweep.spec import SweepSpec
from tethersim.experiments.sweep.store import SweepStore

FLUSH_SECONDS = 2.0
# a task integrates about this many orbits (8 points of 5 orbits), and holds at least
# the points one compiled step advances together (the SIMD lanes, batch.lane_width):
# enough to amortise the Python work around a compiled block, short enough (~10-300 ms)
# that Ctrl-C, the progress bar and the last tasks' balance across threads do not notice
BLOCK_ORBITS = 40
BALANCE = 4  # at least this many tasks per worker, so no worker idles at the end
MAX_BLOCK = 64


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C or SIGTERM during a sweep; everything finished was written.

    A :class:`KeyboardInterrupt` (``except Exception`` lets it through, as it does a
    plain Ctrl-C) that names the store and that it resumes (the command line adds how).
    """

    def __init__(self, store: SweepStore):
        n = int(store.done.sum())
        super().__init__(f"sweep interrupted: {n} of {store.done.size} points are in {store.path}; "
                         f"the same sweep resumes from them")
        self.store = store


@contextmanager
def executor(workers: int | None = None, scheduler: str | None = None, dask_workers: int | None = None):
    """(executor, smallest block, workers): threads by default, Dask with an address or a
    local cluster."""
    if scheduler is not None or dask_workers is not None:
        from distributed import Client, LocalCluster

        if scheduler is not None:
            client = Client(scheduler)
            cluster = None
        else:
            # the diagnostics server on a free port: None means distributed's fixed 8787,
            # and a second sweep (or any Dask user) holding it made this one warn
            cluster = LocalCluster(n_workers=dask_workers, threads_per_worker=1, processes=True,
                                   dashboard_address=":0")
            client = Client(cluster)
        try:
            # blocks of points amortise Dask's per-task cost (~1 ms) over ~0.1 s runs
            yield client.get_executor(pure=False), 4, dask_workers or 2
        finally:
            if cluster is not None:
                with suppress(Exception):  # a log filter: a worker already gone needs none
                    client.run(_quiet_heartbeat_race)
            client.close()
            if cluster is not None:
                cluster.close()
    else:
        n = workers or os.cpu_count() or 1
        if n < 1:
            raise ValueError(f"workers = {n}: must be >= 1")
        with cf.ThreadPoolExecutor(max_workers=n, thread_name_prefix="tethersim-sweep") as ex:
            yield ex, 1, n


def _not_heartbeat_race(record) -> bool:
    """A logging filter: drops a worker's "Failed to communicate with scheduler during
    heartbeat" record.

    Closing a local cluster races a worker's periodic heartbeat against the scheduler
    closing its comms (dask/distributed#7105, open): the worker logs the closed stream as
    an ERROR with two tracebacks after every result is in.  Installed only as the
    cluster closes, so a heartbeat failure during a sweep is still printed.
    """
    return "during heartbeat" not in record.getMessage()


def _quiet_heartbeat_race() -> None:
    """Run on each worker of a closing local cluster (Client.run)."""
    import logging

    logging.getLogger("distributed.worker").addFilter(_not_heartbeat_race)


def block_size(periods: float, points: int, workers: int, minimum: int = 1,
               lanes: int = 1) -> int:
    """Points per task: about BLOCK_ORBITS orbits of integration but at least ``lanes``
    (a block of fewer points than the SIMD lanes leaves lanes idle: 50-orbit maps ran
    one point per block, point by point), at least BALANCE tasks per worker, at least
    ``minimum``.  Records do not depend on it."""
    by_work = max(lanes, round(BLOCK_ORBITS / periods))
    by_balance = max(1, math.ceil(points / (BALANCE * max(1, workers))))
    return max(minimum, min(by_work, by_balance, MAX_BLOCK))


def _blocks(ks: list, size: int, workers: int = 1, minimum: int = 1) -> list:
    """ks in tasks of ``size`` points, in order; the last tasks shrink (at most the points
    left over 2 x workers, at least ``minimum``) so the workers finish together: with
    equal tasks, one thread idled for most of a task at the end (~20 ms of a 0.4 s sweep)."""
    out, i = [], 0
    while i < len(ks):
        n = max(minimum, min(size, math.ceil((len(ks) - i) / (2 * workers))))
        out.append(ks[i:i + n])
        i += n
    return out


def _tasks(ks: list, periods: float, workers: int, minimum: int, lanes: int,
           size: int | None = None) -> list:
    """ks in blocks of ``size`` points (default: block_size), the last ones shrinking
    (_blocks) but not below the lanes, so that every block but the remainder fills them."""
    size = size or block_size(periods, len(ks), workers, minimum, lanes)
    return _blocks(ks, size, workers, max(minimum, min(lanes, size)))


def run_plan(plan: Plan, sats: list, *, workers: int | None = None,
             scheduler: str | None = None, dask_workers: int | None = None,
             progress: bool | None = None, desc: str = "runs", pool=None) -> list:
    """Records of every satellite's run under ``plan``, in order: a plan of many.

    The satellites run in compiled blocks (batch.run_satellites) on threads, or on a
    Dask cluster (``scheduler``/``dask_workers``, as run_sweep); a record does not
    depend on the block, thread or worker that ran it.  Ctrl-C cancels the queued blocks.

    Parameters
    ----------
    plan : Plan
        How every run integrates.
    sats : list of Satellite
        The runs.
    workers : int, optional
        Threads (default: every core).
    scheduler, dask_workers : optional
        A Dask scheduler's address, or a local cluster of that many worker processes.
    progress : bool or None, optional
        A progress bar (None: when the runs take over a second; False: none).
    desc : str, optional
        The bar's label.
    pool : tuple, optional
        An open :func:`executor` (what its ``with`` yields), for a caller that runs many
        plans on one pool or cluster (a search's generations); then ``workers``,
        ``scheduler`` and ``dask_workers`` are not used.

    Returns
    -------
    list of dict
        One record per satellite (point.VARIABLES).

    Examples
    --------
    >>> import tethersim as ts
    >>> sat = ts.load_preset("satI")
    >>> recs = ts.run_plan(ts.Plan(periods=1), [sat, sat.replace(A3=6.0)], workers=1,
    ...                    progress=False)
    >>> [r["end_time"] == sat.period for r in recs]
    [True, True]
    """
    from tethersim.experiments.sweep.batch import lane_width, run_satellites

    sats = list(sats)
    idx = list(range(len(sats)))
    with (nullcontext(pool) if pool is not None
          else executor(workers, scheduler, dask_workers)) as (ex, minimum, n):
        blocks = _tasks(idx, plan.periods, n, minimum, lane_width(plan))
        futures = {ex.submit(run_satellites, plan, [sats[i] for i in b]): b for b in blocks}
        out = [None] * len(sats)
        with tqdm(total=len(sats), desc=desc, unit="run", disable=progress is False,
                  delay=0 if progress else 1.0, leave=False) as bar:
            try:
                for fut in cf.as_completed(futures):
                    for i, rec in zip(futures[fut], fut.result()):
                        out[i] = rec
                    bar.update(len(futures[fut]))
            except BaseException:
                for f in futures:  # Ctrl-C or an error: do not run the queued blocks
                    f.cancel()
                raise
    return out


def map_points(spec: SweepSpec, ks=None, workers: int | None = None) -> list:
    """Records of flat points ks (default: all) of ``spec``, in order, on threads; no store."""
    ks = list(range(spec.size)) if ks is None else list(ks)
    return run_plan(spec.plan, [spec.satellite_at(k) for k in ks], workers=workers,
                    progress=False)


def run_sweep(spec: SweepSpec, out, *, workers: int | None = None, scheduler: str | None = None,
              dask_workers: int | None = None, restart: bool = False, progress: bool | None = None,
              block: int | None = None, stop_after: int | None = None) -> SweepStore:
    """Compute every pending point of ``spec`` into the store at ``out``.

    Resumes a store made by the same spec (verified first: damaged points are
    recomputed, tethersim.experiments.sweep.verify).  Ctrl-C writes every
    finished point and raises :class:`SweepInterrupted`; any other error also
    writes them first.  A second writer to the same store stops at once
    (``StoreLocked``, naming the first).

    Parameters
    ----------
    spec : SweepSpec
        What to compute.
    out : str or Path
        The Zarr store (created, or resumed).
    workers : int, optional
        Threads (default: every core).
    scheduler : str, optional
        Address of a Dask scheduler to run the points on.
    dask_workers : int, optional
        Start a local Dask cluster with this many workers.
    restart : bool, optional
        Discard a store made by another spec or code instead of refusing it.
    progress : bool or None, optional
        Progress bar (None: when the sweep takes over a second).
    block : int, optional
        Points per task (default: runner.block_size; the data do not depend on it).
    stop_after : int, optional
        Simulate an interruption after that many points (tests).

    Returns
    -------
    SweepStore
        The store; ``.dataset()`` gives the labelled xarray data set.

    Examples
    --------
    >>> import tempfile, tethersim as ts
    >>> spec = ts.SweepSpec(ts.load_preset("satI"), (("E1", (0.003, 0.004)),), periods=1)
    >>> ds = ts.run_sweep(spec, tempfile.mkdtemp() + "/s.zarr", workers=1,
    ...                   progress=False).dataset()
    >>> int(ds.done.sum())
    2
    """
    from tethersim.experiments.sweep.batch import check_point_size
    check_point_size(spec)  # a run that cannot fit is refused before the store exists
    store = SweepStore(out, spec, restart=restart)  # takes the store's writer lock
    try:
        return _fill(store, spec, workers, scheduler, dask_workers, progress, block, stop_after)
    finally:
        store.close()


def _fill(store, spec, workers, scheduler, dask_workers, progress, block, stop_after):
    """run_sweep's work on an open, locked store."""
    from tethersim.experiments.sweep.batch import lane_width
    pending = store.pending()
    if not pending:
        return store
    spec_json = spec.to_json()
    with executor(workers, scheduler, dask_workers) as (ex, minimum, n):
        futures = [ex.submit(run_points, spec_json, b) for b in
                   _tasks(pending, spec.periods, n, minimum, lane_width(spec.plan), block)]
        bar = tqdm(total=spec.size, initial=spec.size - len(pending), unit="run",
                   desc=f"sweep {spec.satellite.name} {' x '.join(spec.names)}",
                   disable=progress is False, delay=0 if progress else 1.0, smoothing=0.05)
        last, count = time.monotonic(), 0
        try:
            for fut in cf.as_completed(futures):
                records = fut.result()
                store.put(records)
                count += len(records)
                bar.update(len(records))
                if time.monotonic() - last > FLUSH_SECONDS:
                    store.flush()
                    last = time.monotonic()
                if stop_after is not None and count >= stop_after:
                    raise KeyboardInterrupt
        except BaseException as exc:
            # keep everything finished: queued points are cancelled; on threads the
            # blocks running finish (one block each) and are kept; Dask cancels its own
            for f in futures:
                f.cancel()
            for f in futures:
                if f.cancelled():
                    continue
                try:
                    store.put([(k, rec) for k, rec in f.result() if not store.done[k]])
                except (cf.CancelledError, Exception):  # noqa: BLE001 - the first error wins
                    pass
            store.flush()
            bar.close()
            if isinstance(exc, KeyboardInterrupt):
                raise SweepInterrupted(store) from None
            raise
        store.flush()
        bar.close()
    return store
