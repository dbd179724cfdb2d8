"""One sweep point: run, measure, classify.  The work function shipped to threads and Dask workers.

Everything here is deterministic: the same spec and point give the same
record bit for bit, whichever thread, process or machine runs it, which is
what makes a resumed or distributed sweep identical to an uninterrupted one.
"""
from __future__ import annotations

import math
from functools import lru_cache

from tethersim.analysis.classify import FAILED
from tethersim.analysis.metrics import PitchMetrics
from tethersim.analysis.outcome import Outcome, outcome
from tethersim.engine.linearise import rk4_amplification
from tethersim.engine.result import STATUSES
from tethersim.engine.simulate import FAITHFUL_STEPS_PER_PERIOD, simulate
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL, SCHEMES
from tethersim.experiments.sweep.spec import SweepSpec

# (name, dtype, units, long name): the record of one point, in this order
VARIABLES = (
    ("stability_class", "int8", "1", "stability class (docs/metrics.md)"),
    ("mean_pitch", "float64", "rad", "mean pitch over the run"),
    ("steady_state_pitch", "float64", "rad", "mean pitch over the last fifth, wrapped"),
    ("settling_time", "float64", "s", "settling time to +-tol (NaN: never)"),
    ("tumbled", "int8", "1", "pitch passed +-pi"),
    ("upside_down", "int8", "1", "|steady-state pitch| > 3 pi/4"),
    ("trail_delta_x", "float64", "m", "balloon delta_x, mean over the last fifth"),
    ("trail_delta_y", "float64", "m", "balloon delta_y, mean over the last fifth"),
    ("max_force_delta_x", "float64", "N", "largest |Q| of one force family on delta_x"),
    ("max_force_delta_y", "float64", "N", "largest |Q| of one force family on delta_y"),
    ("max_force_theta", "float64", "N m", "largest |Q| of one force family on theta"),
    ("drag_makeup", "float64", "m/s/day",
     "velocity per day that holds the circular orbit against drag (NaN: a free orbit)"),
    ("rk4_amplification", "float64", "1",
     "largest RK4 growth per thesis step (26.55 s at 200 km) over the initial linear modes; > 1: unstable"),
    ("status", "int8", "1", "run status: " + ", ".join(f"{i} {s}" for i, s in enumerate(STATUSES))),
    ("nfev", "int64", "1", "right-hand-side evaluations"),
    ("end_time", "float64", "s", "when the run ended: its last sample, a stopping event's located time"),
)
NAMES = tuple(v[0] for v in VARIABLES)
#: the engine's status names (tethersim.engine.result.STATUSES) and their stored codes
STATUS = {name: code for code, name in enumerate(STATUSES)}


def run_point(spec: SweepSpec, k: int) -> dict:
    """Simulate flat grid point k of ``spec`` and return its record (SI).

    simulate() then outcome(), in Python: the definition of a record.  A sweep
    runs every point in compiled blocks (tethersim.experiments.sweep.batch),
    which give these records bit for bit (the tests check it).
    """
    sat = spec.satellite_at(k)
    if spec.method == "faithful":
        steps = max(1, round(spec.steps_per_period * spec.periods))
        res = simulate(sat, spec.periods, steps=steps, method="rk4", model=spec.model,
                       locate_switches=False, check=False, progress=False, step_warning=False)
    else:
        n_out = max(2, round(spec.samples_per_period * spec.periods))
        res = simulate(sat, spec.periods, method=SCHEMES[spec.method], model=spec.model,
                       rtol=spec.rtol, atol=spec.rtol * ATOL_PER_RTOL, samples=n_out,
                       check=False, progress=False)
    if res.status == "interrupted":  # Ctrl-C in the calling thread: stop, do not record
        raise KeyboardInterrupt
    thesis_step = sat.period / FAITHFUL_STEPS_PER_PERIOD
    out = outcome(res, tol=spec.tol)
    m = out.metrics
    return record(STATUS[res.status], res.nfev,
                  # at the run's start (res.satellite: a real line's equilibrium, engine/start.py)
                  rk4_amplification(res.satellite, thesis_step, spec.model), out.stability_class,
                  None if not out.counts else dict(
                      mean_pitch=m.mean_pitch, steady_state_pitch=m.steady_state_pitch,
                      settling_time=m.settling_time, tumbled=int(m.tumbled),
                      upside_down=int(m.upside_down), trail_delta_x=out.trail_delta_x,
                      trail_delta_y=out.trail_delta_y, max_force_delta_x=out.max_force[0],
                      max_force_delta_y=out.max_force[1], max_force_theta=out.max_force[2],
                      drag_makeup=out.drag_makeup),
                  # the last sample of the metrics grid: a located stop's time (simulate)
                  float((res.fine_t if res.fine_t is not None else res.t)[-1]))


def record(status: int, nfev: int, amplification: float, stability_class: int,
           measured: dict | None, end_time: float) -> dict:
    """One point's record: a run that does not count (outcome.py) keeps its class, status,
    nfev, amplification and end time only; ``measured`` holds the rest of a run that counts."""
    rec = dict.fromkeys(NAMES, math.nan)
    rec.update(tumbled=0, upside_down=0, status=status, nfev=nfev,
               rk4_amplification=amplification, stability_class=stability_class,
               end_time=end_time)
    if measured is not None:
        rec.update(measured)
    return rec


def outcome_of_record(rec: dict) -> Outcome:
    """The Outcome a record stands for (the inverse of :func:`record`): status, class,
    pitch metrics, trail and drag make-up; a run that does not count keeps no metrics
    (its record has none), and the force peaks are not carried."""
    status = STATUSES[int(rec["status"])]
    cls = int(rec["stability_class"])
    counts = status == "ok" and cls != FAILED
    m = None
    if math.isfinite(rec["mean_pitch"]):
        m = PitchMetrics(rec["mean_pitch"], rec["steady_state_pitch"], rec["settling_time"],
                         bool(rec["tumbled"]), bool(rec["upside_down"]))
    return Outcome(status, "" if counts else status, cls, m, rec["trail_delta_x"],
                   rec["trail_delta_y"], (math.nan,) * 3, None, None,
                   drag_makeup=rec["drag_makeup"])


@lru_cache(maxsize=8)
def _spec(spec_json: str) -> SweepSpec:
    # the text is of a spec whose points were checked when it was made (SweepSpec): its
    # copy does not check them again (a second of 54 us satellites per 20,000 points)
    return SweepSpec.from_json(spec_json, check=False)


def run_points(spec_json: str, ks: list) -> list:
    """[(k, record)] for flat points ks: the task a thread or Dask worker runs.

    The points run in compiled blocks (batch.run_block); the records do not
    depend on how the points are grouped.
    """
    from tethersim.experiments.sweep.batch import run_block
    return run_block(_spec(spec_json), list(ks))
