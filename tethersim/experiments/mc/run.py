"""Run a Monte Carlo's samples into a resumable store, on threads or a Dask cluster.

The store is a folder: ``spec.json`` (the :class:`MCSpec`, refused if another spec
is there) and ``rows.jsonl``, one finished sample a line (its inputs and outcomes, as
:func:`sample_rows` makes them).  Lines are appended as samples finish, in whatever
order the workers finish them; when the last sample is in, the file is rewritten in
sample order, so a finished store is the same bytes whether it ran on 1 or 2 threads,
on a Dask cluster, or was interrupted and resumed (a row is a function of the spec and
its sample alone: tethersim.experiments.sweep.batch).  A line cut by an interruption
is dropped on reading and its sample runs again.  One writer at a time (StoreLock).
"""
from __future__ import annotations

import concurrent.futures as cf
from functools import lru_cache
from pathlib import Path

from tethersim.analysis.classify import CLASSES, STABLE
from tethersim.engine.result import STATUSES
from tethersim.experiments.mc.inputs import sample_satellites
from tethersim.experiments.mc.spec import PARTS, MCSpec
from tethersim.experiments.sweep.lines import LineStore, read_lines
from tethersim.experiments.sweep.point import STATUS

ROWS_FILE = "rows.jsonl"
# how a free run ended -> the row's life_end ("balloon-lost": the model's domain, a
# tether stretched 20x, docs/feasibility.md; "capped": still flying at max_lifetime_h)
LIFE_END = {"re-entered": "re-entry", "left-domain": "balloon-lost", "ok": "capped"}
# an input's column in the rows: name + edge unit of the satellite field
_COLUMN = {"epoch": "epoch_utc", "A3": "A3_m2", "E1": "E1_N", "E2": "E2_N",
           "c1": "c1_N_s_per_m", "c2": "c2_N_s_per_m", "theta0": "theta0_rad",
           "theta_dot0": "theta_dot0_rad_s", "delta_x_dot0": "delta_x_dot0_m_s"}


def column(name: str) -> str:
    """The rows' column of input ``name`` (its unit in the name)."""
    return _COLUMN.get(name, name)


class MCInterrupted(KeyboardInterrupt):
    """Ctrl-C during a Monte Carlo; every finished sample is in the store."""

    def __init__(self, out: Path, done: int, total: int):
        super().__init__(f"mc interrupted: {done} of {total} samples are in {out}; the same "
                         f"Monte Carlo resumes from them")


@lru_cache(maxsize=4)
def _spec(text: str) -> MCSpec:
    return MCSpec.from_json(text)  # once per process (a Dask worker gets the text)


def sample_rows(spec_json: str, part: str, idx: list) -> list:
    """[(i, row)] of samples ``idx`` of ``part``: the task a thread or a Dask worker runs.

    Both runs of every sample go through the compiled blocks of a plan of many
    (batch.run_satellites); the free run's second stage only for samples still flying
    at the first stage's end.
    """
    from tethersim.experiments.sweep.batch import run_satellites
    spec = _spec(spec_json)
    units = _units(spec_json, part)
    samples = sample_satellites(spec.satellite, spec.inputs, units[list(idx)], spec.model)
    circ = run_satellites(spec.circular_plan, [s[1] for s in samples])
    free = run_satellites(spec.free_plans[0], [s[2] for s in samples])
    for plan in spec.free_plans[1:]:
        again = [j for j, r in enumerate(free) if r["status"] == STATUS["ok"]]
        for j, r in zip(again, run_satellites(plan, [samples[j][2] for j in again])):
            free[j] = r
    cap = spec.max_lifetime_h * 3600
    return [(i, _row(part, i, s[0], c, f, cap)) for i, s, c, f in zip(idx, samples, circ, free)]


@lru_cache(maxsize=4)
def _units(spec_json: str, part: str):
    return _spec(spec_json).units(part)


def _row(part: str, i: int, values: dict, circ: dict, free: dict, cap: float) -> dict:
    row = {"part": part, "i": int(i)}
    row.update({column(k): v for k, v in values.items()})
    ts = circ["settling_time"]
    settles = circ["stability_class"] == STABLE
    status = STATUSES[free["status"]]
    life = cap if status == "ok" else free["end_time"]
    row.update({"class": CLASSES[circ["stability_class"]], "settling_time_s": ts,
                "theta_ss_rad": circ["steady_state_pitch"], "tumbled": bool(circ["tumbled"]),
                "circular_status": STATUSES[circ["status"]], "free_status": status,
                "lifetime_s": life, "life_end": LIFE_END.get(status, status),
                "settles": settles,
                # a capped life outlasts the settling run (max_lifetime_h >= its length)
                "settles_in_life": bool(settles and ts < life)})
    return row


def _key(row: dict) -> tuple:
    return PARTS.index(row["part"]), row["i"]


def read_rows(out) -> dict:
    """{(part index, i): row} of the store at ``out`` (cut lines dropped)."""
    return {_key(row): row for row in read_lines(Path(out) / ROWS_FILE)}


def run_mc(spec: MCSpec, out, *, workers: int | None = None, scheduler: str | None = None,
           dask_workers: int | None = None, progress: bool | None = None,
           stop_after: int | None = None) -> list:
    """Run (or resume) every sample of ``spec`` into the store ``out``; the rows in order.

    Parameters
    ----------
    spec : MCSpec
        What to compute.
    out : path-like
        Store folder (``spec.json``, ``rows.jsonl``).
    workers : int, optional
        Threads (default: every core).
    scheduler, dask_workers : optional
        A Dask scheduler's address, or a local cluster of that many worker processes
        (runner.executor, as sweeps run there).
    progress : bool or None, optional
        A progress bar (None: when the run takes over a second).
    stop_after : int, optional
        Simulate Ctrl-C after that many samples (tests).

    Returns
    -------
    list of dict
        The rows: random samples by index, then the Sobol' design's rows.

    Raises
    ------
    ValueError
        When ``out`` holds another spec's samples (one line naming the folder).
    MCInterrupted
        On Ctrl-C (a KeyboardInterrupt); everything finished is in the store.
    """
    out = Path(out)
    text = spec.to_json()
    with LineStore(out, ROWS_FILE, text, "a Monte Carlo",
                   "use another --out, or remove it") as store:
        done = {_key(row): row for row in store.rows()}
        keys = [(p, i) for p, part in enumerate(PARTS) for i in range(spec.size(part))]
        todo = [k for k in keys if k not in done]
        if todo:
            _fill(spec, text, store, done, todo, len(keys), workers, scheduler, dask_workers,
                  progress, stop_after)
        rows = [done[k] for k in keys]
        store.rewrite(rows)  # sample order: the same bytes however it ran
    return rows


def _fill(spec, text, store, done, todo, total, workers, scheduler, dask_workers, progress,
          stop_after) -> None:
    from tqdm.auto import tqdm

    from tethersim.experiments.sweep.runner import _blocks, block_size, executor
    count = 0
    with executor(workers, scheduler, dask_workers) as (ex, minimum, n):
        # one sample is a settling run plus a free run (hours, at most max_lifetime_h)
        size = block_size(spec.periods + spec.free_plans[0].periods, len(todo), n, minimum)
        futures = []
        for p, part in enumerate(PARTS):
            ks = [i for q, i in todo if q == p]
            futures += [ex.submit(sample_rows, text, part, b) for b in _blocks(ks, size, n, minimum)]
        bar = tqdm(total=total, initial=total - len(todo), desc=f"mc {spec.satellite.name}",
                   unit="sample", disable=progress is False, delay=0 if progress else 1.0,
                   smoothing=0.05)

        def keep(pairs):
            for _, row in pairs:
                if _key(row) not in done:
                    store.put(row, flush=False)
                    done[_key(row)] = row
            store.flush()

        try:
            for fut in cf.as_completed(futures):
                pairs = fut.result()
                keep(pairs)
                count += len(pairs)
                bar.update(len(pairs))
                if stop_after is not None and count >= stop_after:
                    raise KeyboardInterrupt
        except BaseException as exc:
            for f in futures:  # queued blocks are cancelled; running ones are kept
                f.cancel()
            for f in futures:
                if not f.cancelled():
                    try:
                        keep(f.result())
                    except (cf.CancelledError, Exception):  # noqa: BLE001 - first error wins
                        pass
            bar.close()
            if isinstance(exc, KeyboardInterrupt):
                raise MCInterrupted(store.folder, len(done), total) from None
            raise
        bar.close()

