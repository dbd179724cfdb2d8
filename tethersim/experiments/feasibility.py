"""Feasibility atlas: balloon lost, re-entry, settling and trim across altitudes (and areas).

Per point (altitude h, balloon area A3), from the satellite with those two set:

* **balloon lost, re-entry** -- a free orbit (``orbit = "free"``, ``density =
  "per-body"``: each body in Vallado's air at its own altitude, so the decay speeds
  up as the orbit falls), run until it re-enters or for ``max_lifetime_h`` at most.
  The run ends earlier when the balloon leaves the model's domain (a tether stretched
  20x as the air thickens, engine/domain.py): the balloon is lost there
  (``balloon_lost_h``), and the tether, beyond any elastic tether, is taken to break:
  the boom alone continues from that state until it re-enters (``reentry_h``,
  tethersim.engine.release).  The usable life, which the verdict uses, ends at
  whichever comes first;
* **settling** -- the nominal circular run (thesis: orbit held, uniform Vallado
  density at h, ``periods`` orbits);
* **trim** -- circular runs with ``density_scale`` = ρ_MSIS(case) / ρ_Vallado(h) for
  each solar case (min, mean, max of tethersim.model.air.SOLAR_CYCLE; MSIS averaged
  over 24 local times on the equator at the March equinox).

* **across the solar cycle** -- the same free orbit in NRLMSISE-00 air per body
  (altitude, longitude and time of each body, in the compiled loop) with each solar
  case's indices, from the same epoch (``balloon_lost_<case>_h``, ``reentry_<case>_h``).

Every run that decides the verdict (free, nominal, trims) runs at the spec's ``rtol``
and again at ``rtol / CHECK_FACTOR`` (the convergence check's factor): a verdict that
differs between the two is ``sensitive`` (tethersim.analysis.feasibility.combine).
The runs of a point and the points of a grid are capped as a sweep's grid is
(:func:`tethersim.engine.guards.check_runs`, ``TETHERSIM_MAX_SWEEP_POINTS``).

A point's nominal and trim runs at one tolerance are one plan of many (sweep.batch
``run_satellites``: one compiled call, SIMD lanes where the scheme has them; each record
is simulate() then outcome() bit for bit; sweep.point ``outcome_of_record``).  Each free
orbit is a plan of one (simulate): a record carries neither its end altitude nor, for
the release continuation after a lost balloon, its final state.

Why not the sweep store: a point is up to eighteen runs of four kinds, and its row mixes
their results.  A resumable store of its own (one JSON line per finished point, a lock,
the spec beside it) keeps finished points across an interruption; every point's tasks
(point_tasks) go to one pool of threads (the compiled loops release the GIL).
"""
from __future__ import annotations

import json
import math
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass
from functools import partial
from pathlib import Path

from tethersim.analysis.feasibility import (
    combine,
    periods_to_decide,
    settling_time,
    verdict,
)
from tethersim.engine.arguments import check_scheme
from tethersim.engine.release import continue_released
from tethersim.engine.simulate import RTOL_RANGE, SAMPLES_PER_PERIOD, simulate
from tethersim.engine.start import atol_floor
from tethersim.experiments.sweep.batch import run_satellites
from tethersim.experiments.sweep.lines import LineStore
from tethersim.experiments.sweep.plan import ATOL_PER_RTOL, Plan
from tethersim.experiments.sweep.point import outcome_of_record
from tethersim.model import atmosphere
from tethersim.model.air import solar_cycle_densities
from tethersim.model.air.model import SOLAR_CYCLE, SOLAR_CYCLE_EPOCH
from tethersim.model.satellite import Satellite

SOLAR_CASES = ("min", "mean", "max")
POINTS_FILE = "points.jsonl"
CHECK_FACTOR = 100  # the second tolerance is rtol / this (as SimResult.estimate_error)
METHODS = ("adaptive", "implicit")  # the schemes that locate the switches and stops
MIN_RTOL = RTOL_RANGE[0]  # simulate's floor: below CHECK_FACTOR x this the check runs coarser
# the satellite fields every point sets itself (the circular and free runs, the solar
# cases): a satellite that gives another value is refused rather than silently overridden
ATLAS_FIELDS = ("orbit", "j2", "eccentricity", "density_mode", "atmosphere", "density_scale",
                "f107", "f107a", "ap", "epoch")


@dataclass(frozen=True)
class FeasibilitySpec:
    """What a feasibility atlas computes.

    Attributes
    ----------
    satellite : Satellite
        The design (its altitude and A3 are replaced per point).
    altitudes_km : tuple of float
        Start altitudes [km] (circular; the free orbit's perigee is the same).
    areas : tuple of float
        Balloon areas A3 [m^2] (default: the satellite's own).
    solar : tuple of str
        Solar cases of the trim runs (subset of min, mean, max).
    periods : float
        Orbits of each circular run.
    max_lifetime_h : float
        Cap on the free run [h].
    model : str
        Thesis model (the free run uses its free twin).
    rtol : float
        Adaptive tolerance of every run; the verdict's runs are repeated at
        :attr:`check_rtol`.
    method : {"adaptive", "implicit"}
        The scheme of every run with tethers: DOP853, or Radau IIA for real (stiff)
        lines (engine/integrators/radau.py); their atol is at least the lines' floor
        (engine/start.py atol_floor).
    """

    satellite: Satellite
    altitudes_km: tuple
    areas: tuple = ()
    solar: tuple = SOLAR_CASES
    periods: float = 50.0
    max_lifetime_h: float = 240.0
    model: str = "derived"
    rtol: float = 1e-10
    method: str = "adaptive"

    def __post_init__(self):
        from tethersim.engine.guards import check_runs  # before validating 10^5 points
        check_runs(len(self.altitudes_km) * max(1, len(self.areas)),
                   self.runs_per_point(), "feasibility grid",
                   "--altitude and --A3" if self.areas else "--altitude")
        if not (isinstance(self.rtol, (int, float)) and MIN_RTOL <= self.rtol <= RTOL_RANGE[1]):
            raise ValueError(f"rtol = {self.rtol!r}: allowed range {MIN_RTOL:g} <= rtol <= "
                             f"{RTOL_RANGE[1]:g}")
        if self.method not in METHODS:
            raise ValueError(f"method = {self.method!r}: allowed values {', '.join(METHODS)}")
        _check_atlas_fields(self.satellite)
        if not self.areas:
            object.__setattr__(self, "areas", (self.satellite.A3,))
        bad = [s for s in self.solar if s not in SOLAR_CASES]
        if bad or not self.solar:
            raise ValueError(f"solar = {','.join(self.solar)}: allowed cases "
                             f"{', '.join(SOLAR_CASES)} (one or more)")
        if not (self.max_lifetime_h > 0 and math.isfinite(self.max_lifetime_h)):
            raise ValueError(f"max_lifetime_h = {self.max_lifetime_h!r}: must be > 0 h")
        self._check_sizes()
        for h in self.altitudes_km:  # every point a valid satellite, before any run
            for a3 in self.areas:
                self.circular(h, a3)
                for case in (None, *self.solar):
                    self.free(h, a3, case)

    def _check_sizes(self) -> None:
        """Refuse runs whose arrays would not fit (engine/guards.py), before any point runs:
        the circular runs of ``periods`` and the free runs of ``max_lifetime_h``, counted
        at the lowest altitude (the shortest orbit, so the most orbits)."""
        from tethersim.engine.guards import check_simulation
        from tethersim.model.constants import MU_EARTH, R_EARTH
        check_simulation(self.periods, check=False, subject="periods")
        lowest = min(self.altitudes_km, default=math.nan) * 1e3
        if lowest > -R_EARTH:  # else the satellite's own check names the altitude
            period = 2 * math.pi * math.sqrt((R_EARTH + lowest) ** 3 / MU_EARTH)
            check_simulation(self.max_lifetime_h * 3600 / period, check=False,
                             subject="max_lifetime_h")

    def runs_per_point(self) -> int:
        """Simulations of one point: free, nominal and trims at two tolerances, the MSIS
        free runs, and a continuation after each free run that loses its balloon."""
        n = len(self.solar)
        return 2 * (3 + n) + 2 * n  # (free, release, nominal, n trims) x 2; n MSIS + release

    @property
    def check_rtol(self) -> float:
        """The second tolerance: rtol / CHECK_FACTOR, or x CHECK_FACTOR near the floor."""
        finer = self.rtol / CHECK_FACTOR
        return finer if finer >= MIN_RTOL else self.rtol * CHECK_FACTOR

    def points(self) -> list:
        """(altitude_km, A3) of every point, altitude fastest."""
        return [(float(h), float(a)) for a in self.areas for h in self.altitudes_km]

    def circular(self, h_km: float, a3: float, scale: float = 1.0) -> Satellite:
        """The circular-orbit satellite of a point (uniform density times ``scale``)."""
        return self.satellite.replace(altitude=h_km * 1e3, A3=a3, orbit="circular", j2=False,
                                      eccentricity=0.0, density_mode="uniform",
                                      atmosphere="vallado", density_scale=scale)

    def free(self, h_km: float, a3: float, case: str | None = None) -> Satellite:
        """The free-orbit satellite of a point: per-body Vallado air, or NRLMSISE-00 with
        the indices of solar ``case`` (:data:`~tethersim.model.air.model.SOLAR_CYCLE`)."""
        sat = self.satellite.replace(altitude=h_km * 1e3, A3=a3, orbit="free",
                                     density_mode="per-body", atmosphere="vallado",
                                     density_scale=1.0, f107=None, f107a=None, ap=None)
        if case is None:
            return sat
        f107, f107a, ap = SOLAR_CYCLE[case]
        return sat.replace(atmosphere="nrlmsise00", epoch=SOLAR_CYCLE_EPOCH, f107=f107,
                           f107a=f107a, ap=ap)

    def run_options(self, rtol: float) -> dict:
        """simulate()'s integrator options of every run at ``rtol``."""
        return dict(method=self.method, rtol=rtol,
                    atol=max(rtol * ATOL_PER_RTOL, atol_floor(self.satellite)))

    def plan(self, rtol: float) -> Plan:
        """The plan of the circular runs at ``rtol``: :meth:`run_options` and simulate()'s
        default output (``SAMPLES_PER_PERIOD`` an orbit), so that each record is the
        outcome of simulate() with those options."""
        opts = self.run_options(rtol)
        return Plan(periods=self.periods, method=opts["method"], model=self.model,
                    rtol=rtol, atol=opts["atol"], samples_per_period=SAMPLES_PER_PERIOD)

    def to_json(self) -> str:
        d = asdict(self)
        if d["method"] == "adaptive":  # a store written before the method existed resumes
            del d["method"]
        d["satellite"] = self.satellite.to_dict()
        d["satellite"]["initial"] = list(d["satellite"]["initial"])
        return json.dumps(d, sort_keys=True, default=list)


def _check_atlas_fields(sat: Satellite) -> None:
    """Refuse a satellite that sets a field of :data:`ATLAS_FIELDS` (one line naming it)."""
    from dataclasses import fields
    defaults = {f.name: f.default for f in fields(Satellite)}
    given = [f for f in ATLAS_FIELDS if f != "density_mode" and getattr(sat, f) != defaults[f]]
    if not sat.density_auto:
        given.append("density_mode")
    if given:
        shown = ", ".join(f"{'density' if f == 'density_mode' else f} = {getattr(sat, f)!r}"
                          for f in given)
        raise ValueError(f"feasibility: {shown}: the atlas sets these itself (circular orbit "
                         f"in uniform Vallado air scaled per solar case, free orbit in per-body "
                         f"Vallado and NRLMSISE-00 air of each solar case); leave "
                         f"{', '.join(ATLAS_FIELDS[:-1]).replace('density_mode', 'density')} "
                         f"and epoch at their defaults")


def solar_scales(h_km: float, cases=SOLAR_CASES) -> dict:
    """{case: ρ_MSIS(case) / ρ_Vallado} at altitude ``h_km`` (24-local-time mean)."""
    rho = solar_cycle_densities(h_km * 1e3, local_time_h=None)
    nominal = atmosphere.density(h_km * 1e3)
    return {c: rho[c] / nominal for c in cases}


def free_ends(spec: FeasibilitySpec, sat: Satellite, rtol: float) -> dict:
    """How a point's free orbit ends: balloon lost and re-entry [s], and how.

    Returns
    -------
    dict
        ``lost`` (when the balloon left the domain [s], NaN if it did not),
        ``reentry`` (when the COM re-entered [s], after the release if the
        balloon was lost first; inf past the cap; NaN if the run failed),
        ``life`` (the usable life: the first of the two, inf past the cap, the
        run's end for a failed run), ``end`` (the free run's status, or
        ``"capped"``) and ``end_altitude`` [m] (where the free run ended).
    """
    cap = spec.max_lifetime_h * 3600
    free = _finished(simulate(sat, periods=cap / sat.period, model=spec.model, progress=False,
                              **spec.run_options(rtol)))
    lost, reentry = math.nan, math.nan
    if free.status == "ok":
        reentry = math.inf
    elif free.status == "re-entered":
        reentry = free.reentry_time
    elif free.status == "left-domain":
        lost = float(free.t[-1])
        if lost < cap:
            t, cont = continue_released(free, cap)
            _finished(cont)
            reentry = math.inf if t is None else t
        else:
            reentry = math.inf
    life = (lost if math.isfinite(lost) else reentry if not math.isnan(reentry)
            else float(free.t[-1]))
    return {"lost": lost, "reentry": reentry, "life": life,
            "end": "capped" if free.status == "ok" else free.status,
            "end_altitude": float(free.altitude[-1])}


def _finished(res):
    """The run, unless Ctrl-C stopped it: a truncated run is not recorded as an outcome."""
    if res.status == "interrupted":
        raise KeyboardInterrupt
    return res


def _decide(spec: FeasibilitySpec, h_km: float, a3: float, rtol: float) -> dict:
    """The verdict runs of a point at one tolerance: the free orbit, and the nominal and
    trim runs as one plan of many (records: simulate() then outcome(), bit for bit)."""
    ends = free_ends(spec, spec.free(h_km, a3), rtol)
    sat = spec.circular(h_km, a3)
    scales = solar_scales(h_km, spec.solar)
    sats = [sat] + [spec.circular(h_km, a3, k) for k in scales.values()]
    records = run_satellites(spec.plan(rtol), sats)
    nominal, *trims = (outcome_of_record(r) for r in records)
    v = verdict(ends["life"], nominal, trims, run_s=spec.periods * sat.period,
                cap_s=spec.max_lifetime_h * 3600, lost=math.isfinite(ends["lost"]))
    return {"ends": ends, "nominal": nominal, "trims": dict(zip(scales, trims)),
            "scales": scales, "verdict": v, "period": sat.period}


def _hours(t_s: float, cap_s: float) -> float:
    return min(t_s, cap_s) / 3600


def point_tasks(spec: FeasibilitySpec, h_km: float, a3: float) -> dict:
    """The independent runs of one point, {name: callable}: the verdict runs at the two
    tolerances and each solar case's free orbit; :func:`point_row` joins their results.
    run_feasibility runs every point's tasks in one pool, so a point's runs spread over
    the threads as the points do."""
    return {"main": partial(_decide, spec, h_km, a3, spec.rtol),
            "check": partial(_decide, spec, h_km, a3, spec.check_rtol),
            **{c: partial(free_ends, spec, spec.free(h_km, a3, c), spec.rtol)
               for c in spec.solar}}


def point_row(spec: FeasibilitySpec, h_km: float, a3: float, done: dict) -> dict:
    """The row of one point (keys name their units) from its tasks' results ``done``."""
    main, check = done["main"], done["check"]
    ends, nominal, cap = main["ends"], main["nominal"], spec.max_lifetime_h * 3600
    horizon = ends["life"] if math.isfinite(ends["life"]) else cap
    row = {"altitude_km": h_km, "A3_m2": a3,
           "balloon_lost_h": ends["lost"] / 3600,
           "reentry_h": _hours(ends["reentry"], cap),
           "reentry_capped": ends["reentry"] == math.inf,
           "free_end": ends["end"], "end_altitude_km": ends["end_altitude"] / 1e3,
           "settling_h": settling_time(nominal) / 3600, "nominal_status": nominal.status,
           "nominal_class": nominal.class_name,
           "theta_ss_rad": _theta_ss(nominal), "drag_makeup_m_s_day": nominal.drag_makeup}
    for c, k in main["scales"].items():
        row[f"scale_{c}"] = k
        row[f"theta_ss_{c}_rad"] = _theta_ss(main["trims"][c])
        row[f"class_{c}"] = main["trims"][c].class_name
        e = done[c]
        row[f"balloon_lost_{c}_h"] = e["lost"] / 3600
        row[f"reentry_{c}_h"] = _hours(e["reentry"], cap)
        row[f"reentry_{c}_capped"] = e["reentry"] == math.inf
    row.update({"rtol": spec.rtol, "verdict_rtol": main["verdict"],
                "check_rtol": spec.check_rtol, "verdict_check_rtol": check["verdict"],
                "theta_ss_check_rad": _theta_ss(check["nominal"]),
                "periods_to_decide": periods_to_decide(horizon, main["period"]),
                "verdict": combine((main["verdict"], check["verdict"]))})
    return row


def _theta_ss(out) -> float:
    return out.metrics.steady_state_pitch if out.metrics is not None else math.nan


def _key(row) -> tuple:
    return (round(float(row["altitude_km"]), 9), round(float(row["A3_m2"]), 12))


def run_feasibility(spec: FeasibilitySpec, out, workers: int | None = None,
                    log=print, progress: bool | None = None) -> list:
    """Run (or resume) every point into ``out``; the rows in point order.

    Parameters
    ----------
    spec : FeasibilitySpec
        What to compute.
    out : path-like
        Store folder: ``spec.json`` and ``points.jsonl`` (one finished point a line).
    workers : int, optional
        Threads (default: every core, as sweeps: the runs release the GIL); the rows
        do not depend on it.
    log : callable, optional
        One line per finished point.
    progress : bool or None, optional
        A progress bar over the points (None: when the run takes over a second;
        False: none).  With a bar, pass ``log=tqdm.write`` to keep the lines apart.

    Returns
    -------
    list of dict
        One row per point, in :meth:`FeasibilitySpec.points` order.

    Raises
    ------
    ValueError
        When ``out`` holds another spec's points (one line, naming the folder).
    """
    check_scheme(spec.satellite, spec.method)  # real lines: before any store or run
    out = Path(out)
    with LineStore(out, POINTS_FILE, spec.to_json(), "a feasibility atlas") as store:
        done = {_key(row): row for row in store.rows()}
        todo = [p for p in spec.points() if _key({"altitude_km": p[0], "A3_m2": p[1]}) not in done]
        from tqdm.auto import tqdm

        bar = tqdm(total=len(spec.points()), initial=len(spec.points()) - len(todo),
                   desc="feasibility", unit="point", disable=progress is False,
                   delay=0.0 if progress else 1.0, leave=False)
        with ThreadPoolExecutor(max_workers=workers or os.cpu_count() or 1) as pool, bar:
            # every point's runs in one queue, a point's in order: the threads stay busy
            # to the end, and the points finish (and are stored) about in order
            futures = [{k: pool.submit(task) for k, task in point_tasks(spec, *p).items()}
                       for p in todo]
            for p, fs in zip(todo, futures):
                row = point_row(spec, *p, {k: f.result() for k, f in fs.items()})
                bar.update(1)
                store.put(row)
                done[_key(row)] = row
                log(f"feasibility: {row['altitude_km']:g} km, A3 {row['A3_m2']:g} m^2: "
                    f"{row['verdict']}")
    return [done[_key({"altitude_km": h, "A3_m2": a})] for h, a in spec.points()]
