"""Feasibility atlas: lifetime, settling and trim across altitudes (and balloon areas).

Per point (altitude h, balloon area A3), from the satellite with those two set:

* **lifetime** -- a free orbit (``orbit = "free"``, ``density = "per-body"``: each
  body in Vallado's air at its own altitude, so the decay speeds up as the orbit
  falls), run until it re-enters or for ``max_lifetime_h`` at most.  The run also
  ends when the balloon leaves the model's domain (a tether stretched 20x as the
  air thickens, engine/domain.py); that end counts as the end of life;
* **settling** -- the nominal circular run (thesis: orbit held, uniform Vallado
  density at h, ``periods`` orbits);
* **trim** -- circular runs with ``density_scale`` = ρ_MSIS(case) / ρ_Vallado(h) for
  each solar case (min, mean, max of tethersim.model.air.SOLAR_CYCLE; MSIS averaged
  over 24 local times on the equator at the March equinox).

* **lifetime across the solar cycle** -- the same free orbit in NRLMSISE-00 air per
  body (altitude, longitude and time of each body, in the compiled loop) with each
  solar case's indices, from the same epoch (``lifetime_<case>_h`` columns).

Why not the sweep store: a point here is up to eight runs of three kinds (free,
nominal, scaled), not one run of one kind, and its row mixes their results.  A
small resumable store of its own (one JSON line per finished point, a lock as
the sweep stores take, the spec beside it) keeps finished points across an
interruption; points run on threads (the compiled loops release the GIL).
"""
from __future__ import annotations

import json
import math
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass
from pathlib import Path

from tethersim.analysis.feasibility import settling_time, verdict
from tethersim.analysis.outcome import outcome
from tethersim.engine.simulate import simulate
from tethersim.experiments.sweep.lock import StoreLock
from tethersim.model import atmosphere
from tethersim.model.air import solar_cycle_densities
from tethersim.model.air.model import SOLAR_CYCLE, SOLAR_CYCLE_EPOCH
from tethersim.model.satellite import Satellite

SOLAR_CASES = ("min", "mean", "max")
POINTS_FILE = "points.jsonl"
SPEC_FILE = "spec.json"


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
    """

    satellite: Satellite
    altitudes_km: tuple
    areas: tuple = ()
    solar: tuple = SOLAR_CASES
    periods: float = 50.0
    max_lifetime_h: float = 240.0
    model: str = "derived"

    def __post_init__(self):
        if not self.areas:
            object.__setattr__(self, "areas", (self.satellite.A3,))
        bad = [s for s in self.solar if s not in SOLAR_CASES]
        if bad or not self.solar:
            raise ValueError(f"solar = {','.join(self.solar)}: allowed cases "
                             f"{', '.join(SOLAR_CASES)} (one or more)")
        if not (self.max_lifetime_h > 0 and math.isfinite(self.max_lifetime_h)):
            raise ValueError(f"max_lifetime_h = {self.max_lifetime_h!r}: must be > 0 h")
        for h in self.altitudes_km:  # every point a valid satellite, before any run
            for a3 in self.areas:
                self.circular(h, a3)
                for case in (None, *self.solar):
                    self.free(h, a3, case)

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

    def to_json(self) -> str:
        d = asdict(self)
        d["satellite"] = self.satellite.to_dict()
        d["satellite"]["initial"] = list(d["satellite"]["initial"])
        return json.dumps(d, sort_keys=True, default=list)


def solar_scales(h_km: float, cases=SOLAR_CASES) -> dict:
    """{case: ρ_MSIS(case) / ρ_Vallado} at altitude ``h_km`` (24-local-time mean)."""
    rho = solar_cycle_densities(h_km * 1e3, local_time_h=None)
    nominal = atmosphere.density(h_km * 1e3)
    return {c: rho[c] / nominal for c in cases}


def _lifetime(spec: FeasibilitySpec, sat: Satellite) -> tuple:
    """(lifetime [s] or inf when capped, how the free run ended, the run)."""
    free = simulate(sat, periods=spec.max_lifetime_h * 3600 / sat.period, model=spec.model,
                    progress=False)
    if free.status == "ok":
        return math.inf, "capped", free
    return (free.reentry_time if free.reentry_time is not None else float(free.t[-1]),
            free.status, free)


def run_point(spec: FeasibilitySpec, h_km: float, a3: float) -> dict:
    """Every run of one point and its row (keys name their units)."""
    kw = dict(model=spec.model, progress=False)
    life, end, free = _lifetime(spec, spec.free(h_km, a3))
    nominal = outcome(simulate(spec.circular(h_km, a3), periods=spec.periods, **kw),
                      forces=False)
    scales = solar_scales(h_km, spec.solar)
    trims = {c: outcome(simulate(spec.circular(h_km, a3, k), periods=spec.periods, **kw),
                        forces=False) for c, k in scales.items()}
    cap = spec.max_lifetime_h * 3600
    row = {"altitude_km": h_km, "A3_m2": a3, "lifetime_h": min(life, cap) / 3600,
           "lifetime_capped": not math.isfinite(life), "free_end": end,
           "end_altitude_km": float(free.altitude[-1] / 1e3),
           "settling_h": settling_time(nominal) / 3600, "nominal_class": nominal.class_name,
           "theta_ss_rad": _theta_ss(nominal), "drag_makeup_m_s_day": nominal.drag_makeup}
    for c, k in scales.items():
        row[f"scale_{c}"] = k
        row[f"theta_ss_{c}_rad"] = _theta_ss(trims[c])
        row[f"class_{c}"] = trims[c].class_name
        life_c, _, _ = _lifetime(spec, spec.free(h_km, a3, c))
        row[f"lifetime_{c}_h"] = min(life_c, cap) / 3600
        row[f"lifetime_{c}_capped"] = not math.isfinite(life_c)
    row["verdict"] = verdict(life, nominal, trims.values())
    return row


def _theta_ss(out) -> float:
    return out.metrics.steady_state_pitch if out.metrics is not None else math.nan


def _key(row) -> tuple:
    return (round(float(row["altitude_km"]), 9), round(float(row["A3_m2"]), 12))


def run_feasibility(spec: FeasibilitySpec, out, workers: int | None = None,
                    log=print) -> list:
    """Run (or resume) every point into ``out``; the rows in point order.

    Parameters
    ----------
    spec : FeasibilitySpec
        What to compute.
    out : path-like
        Store folder: ``spec.json`` and ``points.jsonl`` (one finished point a line).
    workers : int, optional
        Threads (default 1).
    log : callable, optional
        One line per finished point.

    Returns
    -------
    list of dict
        One row per point, in :meth:`FeasibilitySpec.points` order.

    Raises
    ------
    ValueError
        When ``out`` holds another spec's points (one line, naming the folder).
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    with StoreLock(out / POINTS_FILE):
        spec_path, points_path = out / SPEC_FILE, out / POINTS_FILE
        text = spec.to_json()
        if spec_path.exists() and spec_path.read_text() != text:
            raise ValueError(f"{out} holds a feasibility atlas of other settings: use another "
                             f"--out or remove it")
        spec_path.write_text(text)
        done = {}
        if points_path.exists():
            for line in points_path.read_text().splitlines():
                try:
                    row = json.loads(line)
                except ValueError:  # a line cut by an interruption: that point reruns
                    continue
                done[_key(row)] = row
        todo = [p for p in spec.points() if _key({"altitude_km": p[0], "A3_m2": p[1]}) not in done]
        with ThreadPoolExecutor(max_workers=workers or 1) as pool, points_path.open("a") as fh:
            for row in pool.map(lambda p: run_point(spec, *p), todo):
                fh.write(json.dumps(row) + "\n")
                fh.flush()
                done[_key(row)] = row
                log(f"feasibility: {row['altitude_km']:g} km, A3 {row['A3_m2']:g} m^2: "
                    f"{row['verdict']}")
    return [done[_key({"altitude_km": h, "A3_m2": a})] for h, a in spec.points()]
