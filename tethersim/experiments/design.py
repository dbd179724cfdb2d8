"""Design search: what is searched, and the verdict of one design from a plan of many.

A design is the preset with some parameters set (``--vary NAME=LOW:HIGH``, ``--choice
NAME=v1,v2``, edge units of tethersim/model/params.py).  Each design is judged as a
feasibility point (tethersim/experiments/feasibility.py builds its runs, and
tethersim/analysis/feasibility.py gives the verdict): a free orbit in per-body Vallado air
(its usable life), the nominal circular run (its settling time) and circular runs with
the air scaled to NRLMSISE-00's solar minimum, mean and maximum (its trim).  A generation
of designs runs as two plans of many (tethersim.experiments.sweep.runner.run_plan): every
circular run in one, every free run in the other.

Objectives (both minimised): ``-margin`` (margin = usable life − settling time [h]) and
the worst |θ_ss| [rad] across the nominal and solar runs.  Constraints: the verdict is
``feasible`` (settles before the life ends, trim inside the band in all three airs);
where breaking loads are set, every run uses them divided by ``safety``, so a design
whose tether tension comes within that factor of its strength breaks and is infeasible.
A design the plan cannot run (a tether too stiff for the explicit scheme: run the search
with method "implicit"; an impossible satellite) is recorded infeasible with the reason,
not run.
"""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass
from functools import lru_cache

from tethersim.analysis.feasibility import FEASIBLE, verdict
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.engine.result import STATUSES
from tethersim.experiments.feasibility import ATLAS_FIELDS, SOLAR_CASES, FeasibilitySpec, solar_scales
from tethersim.experiments.sweep.plan import CLASS_RTOL, SCHEMES, Plan
from tethersim.experiments.sweep.point import outcome_of_record
from tethersim.model import params
from tethersim.model.constants import MU_EARTH, R_EARTH
from tethersim.model.registry import model_for_orbit
from tethersim.model.satellite import Satellite, SatelliteError

PENALTY = 1e6  # objective of a design that did not run: worse than any that did
REFUSED = "refused"
# parameters the search may not vary: the feasibility runs set the air and orbit themselves
FIXED = tuple(n for n in params.PARAMETERS
              if n in ATLAS_FIELDS or n in ("density_scale", "f107", "f107a", "ap"))


@dataclass(frozen=True)
class DesignSpec:
    """What ``tethersim design`` searches.

    Attributes
    ----------
    satellite : Satellite
        The preset the designs start from.
    variables : tuple of (str, float, float)
        (name, low, high) in edge units: continuous design variables.
    choices : tuple of (str, tuple of float)
        (name, values) in edge units: discrete design variables.
    budget : int
        Designs evaluated at most (the search runs ``budget // population`` generations).
    seed : int
        Seed of the search (same seed, same designs, same Pareto set).
    population : int
        Designs per generation (0: min(budget, 16)).
    periods : float
        Orbits of each circular run.
    max_lifetime_h : float
        Cap on the free run [h].
    model : str
        Thesis model (the free run uses its free twin).
    rtol : float
        Tolerance of the search's runs (default: the plans' CLASS_RTOL for runs that only
        need a verdict, docs/tolerances.md); the reported designs are re-verified at
        rtol / 100.
    method : str
        Plan method of every run (tethersim.experiments.sweep.plan.METHODS): "adaptive"
        (DOP853; refuses tethers too stiff for it) or "implicit" (Radau: real tethers).
    tol : float
        Settling and trim band [rad].
    safety : float
        Breaking loads are divided by this in every run (where they are set).
    verify : int
        Pareto designs re-verified at most.
    """

    satellite: Satellite
    variables: tuple = ()
    choices: tuple = ()
    budget: int = 32
    seed: int = 0
    population: int = 0
    periods: float = 50.0
    max_lifetime_h: float = 240.0
    model: str = "derived"
    rtol: float = CLASS_RTOL
    method: str = "adaptive"
    tol: float = SETTLING_TOL
    safety: float = 1.5
    verify: int = 10

    def __post_init__(self):
        seen = set()
        for name, low, high in self.variables:
            _check_variable(name, seen, "--vary")
            _check_value(name, low, f"--vary {name}")
            _check_value(name, high, f"--vary {name}")
            if not low < high:
                raise ValueError(f"--vary {name}={low:g}:{high:g}: LOW must be below HIGH")
        for name, values in self.choices:
            _check_variable(name, seen, "--choice")
            if len(values) < 2 or len(set(values)) != len(values):
                raise ValueError(f"--choice {name}: give two or more distinct values")
            for v in values:
                _check_value(name, v, f"--choice {name}")
        if not seen:
            raise ValueError("design: give at least one --vary NAME=LOW:HIGH or --choice "
                             "NAME=v1,v2")
        for key in ("budget", "seed", "population", "verify"):
            v = getattr(self, key)
            lo = 1 if key == "budget" else 0
            if isinstance(v, bool) or not isinstance(v, int) or v < lo:
                raise ValueError(f"{key} = {v!r}: must be an integer >= {lo}")
        if not (isinstance(self.safety, (int, float)) and 1 <= self.safety <= 10):
            raise ValueError(f"safety = {self.safety!r}: allowed range 1..10")
        if self.population == 0:
            object.__setattr__(self, "population", min(self.budget, 16))
        if self.population > self.budget:
            raise ValueError(f"population = {self.population}: must be <= budget "
                             f"({self.budget})")
        from tethersim.engine.guards import check_runs
        check_runs(self.budget, 2 + len(SOLAR_CASES), "design search", "--budget")
        Plan(periods=self.periods, method=self.method, model=self.model, rtol=self.rtol,
             tol=self.tol)
        self.feasibility(self.satellite)  # the preset itself: atlas fields, sizes, rtol

    @property
    def names(self) -> tuple:
        return tuple(v[0] for v in self.variables) + tuple(c[0] for c in self.choices)

    @property
    def bounds(self) -> tuple:
        """(lower, upper) of the search's real vector: choices as indices in [0, n)."""
        lo = [v[1] for v in self.variables] + [0.0] * len(self.choices)
        hi = [v[2] for v in self.variables] + [float(len(c[1])) for c in self.choices]
        return lo, hi

    @property
    def generations(self) -> int:
        return max(1, self.budget // self.population)

    def values(self, x) -> dict:
        """{name: edge value} of the search vector ``x`` (a choice: its value at floor(x))."""
        out = {name: float(x[i]) for i, (name, _, _) in enumerate(self.variables)}
        k = len(self.variables)
        for j, (name, vals) in enumerate(self.choices):
            out[name] = float(vals[min(len(vals) - 1, max(0, int(math.floor(x[k + j]))))])
        return out

    def design(self, x) -> Satellite:
        """The satellite of ``x``, breaking loads divided by ``safety`` (SatelliteError if it
        is not a valid satellite)."""
        sat = params.with_values(self.satellite, self.values(x))
        weak = {f: getattr(sat, f) / self.safety for f in ("Fb1", "Fb2") if getattr(sat, f)}
        return sat.replace(**weak) if weak else sat

    def feasibility(self, sat: Satellite) -> FeasibilitySpec:
        """The feasibility point of a design (its runs, and the check tolerance)."""
        return FeasibilitySpec(sat, (sat.altitude / 1e3,), (sat.A3,), SOLAR_CASES,
                               periods=self.periods, max_lifetime_h=self.max_lifetime_h,
                               model=self.model, rtol=self.rtol,
                               method="implicit" if self.method == "implicit" else "adaptive")

    def lowest_altitude(self) -> float:
        """The lowest start altitude [m] a design can have (the most orbits per free run)."""
        h = [self.satellite.altitude]
        for name, low, _ in self.variables:
            h += [params.to_si(name, low)] if name == "altitude" else []
        for name, vals in self.choices:
            h += [params.to_si(name, min(vals))] if name == "altitude" else []
        return min(h)

    def plans(self, rtol: float | None = None) -> tuple:
        """(circular plan, free plan) at ``rtol`` (default: the spec's): the free plan runs
        long enough to cover the cap from the lowest altitude."""
        r = self.rtol if rtol is None else rtol
        period = 2 * math.pi * math.sqrt((R_EARTH + self.lowest_altitude()) ** 3 / MU_EARTH)
        free_periods = self.max_lifetime_h * 3600 / period
        kw = dict(method=self.method, model=self.model, rtol=r, tol=self.tol)
        return Plan(periods=self.periods, **kw), Plan(periods=free_periods, **kw)

    def to_json(self) -> str:
        d = asdict(self)
        del d["verify"]  # how many to re-verify does not change what the store holds
        d["satellite"] = self.satellite.to_dict()
        d["satellite"]["initial"] = list(d["satellite"]["initial"])
        return json.dumps(d, sort_keys=True, default=list)


def _check_variable(name: str, seen: set, flag: str) -> None:
    if name not in params.PARAMETERS:
        what = "an option" if name in params.OPTIONS else "not a parameter"
        raise ValueError(f"{flag} {name}: {what}, not a design variable; allowed: "
                         f"{', '.join(n for n in params.PARAMETERS if n not in FIXED)}")
    if name in FIXED:
        raise ValueError(f"{flag} {name}: the search sets {name} itself (free orbit in "
                         f"per-body air, circular runs scaled per solar case); allowed: "
                         f"{', '.join(n for n in params.PARAMETERS if n not in FIXED)}")
    if name in seen:
        raise ValueError(f"--vary/--choice {name}: given twice")
    seen.add(name)


def _check_value(name: str, v, what: str) -> None:
    p = params.PARAMETERS[name]
    ok = isinstance(v, (int, float)) and math.isfinite(v)
    if ok and (p.low <= v <= p.high or (p.zero_ok and v == 0)):
        return
    zero = "0 or " if p.zero_ok else ""
    shown = f"{v:g}" if isinstance(v, (int, float)) else repr(v)
    raise ValueError(f"{what}: {shown} {p.unit} is outside {name}'s plausible range "
                     f"{zero}{p.low:g}..{p.high:g} {p.unit} ({p.why})")


@lru_cache(maxsize=256)
def solar_scale_items(h_km: float) -> tuple:
    return tuple(solar_scales(h_km).items())


def build_runs(spec: DesignSpec, x) -> tuple:
    """(circular satellites, free satellite) of design ``x``, or (None, reason) when the
    design cannot run in a plan."""
    from tethersim.engine.arguments import check_scheme
    from tethersim.engine.start import check_given_start, resolved_mode
    try:
        sat = spec.design(x)
        fs = spec.feasibility(sat)
        h, a3 = fs.points()[0]
        circ = [fs.circular(h, a3)] + [fs.circular(h, a3, k) for _, k in solar_scale_items(h)]
        free = fs.free(h, a3)
        check_scheme(sat, SCHEMES[spec.method])  # a stiff tether needs the implicit scheme
        # a start the plan would refuse (a tether beyond its breaking load), refused here
        for s in (*circ, free):
            if resolved_mode(s, "auto") == "given":
                check_given_start(s, model_for_orbit(spec.model, s.orbit))
    except (SatelliteError, ValueError) as exc:
        weak = " (breaking loads divided by the safety factor)" if "breaking load" in str(
            exc) and spec.safety > 1 else ""
        return None, f"{exc}{weak}"
    return circ, free


def judge(spec: DesignSpec, circ_recs: list, free_rec: dict, period: float) -> dict:
    """The row of one design from its records: usable life, settling, trims, verdict."""
    cap = spec.max_lifetime_h * 3600
    status = STATUSES[int(free_rec["status"])]
    end = float(free_rec["end_time"])
    lost = status in ("left-domain", "tether-broke")
    life = math.inf if status == "ok" or end > cap else end
    nominal, trims = outcome_of_record(circ_recs[0]), [outcome_of_record(r) for r in circ_recs[1:]]
    v = verdict(life, nominal, trims, spec.tol, run_s=spec.periods * period, cap_s=cap,
                lost=lost and math.isfinite(life))
    settle = nominal.metrics.settling_time if nominal.metrics else math.nan
    # a run without a finite trim counts as the worst trim there is (π): never NaN in F
    pitches = [abs(o.metrics.steady_state_pitch)
               if o.counts and o.metrics and math.isfinite(o.metrics.steady_state_pitch)
               else math.pi for o in (nominal, *trims)]
    shown_life = min(life, cap)
    margin = shown_life - (settle if math.isfinite(settle) else spec.periods * period)
    # a tether that breaks in the operating airs (the circular runs) fails the design; in
    # the free run, as the air thickens on the way down, it ends the usable life (lost)
    broke = any(int(r["status"]) == STATUSES.index("tether-broke") for r in circ_recs)
    row = {"verdict": v, "reason": "tether tension within the safety factor of its strength"
           if broke else "", "life_h": shown_life / 3600, "life_capped": math.isinf(life),
           "free_end": "capped" if math.isinf(life) else status,
           "settling_h": settle / 3600, "margin_h": margin / 3600,
           "theta_ss_rad": circ_recs[0]["steady_state_pitch"],
           "worst_theta_ss_rad": max(pitches),
           "trail_m": math.hypot(circ_recs[0]["trail_delta_x"], circ_recs[0]["trail_delta_y"])}
    for case, r in zip(SOLAR_CASES, circ_recs[1:]):
        row[f"theta_ss_{case}_rad"] = r["steady_state_pitch"]
    return row


def objectives(spec: DesignSpec, row: dict) -> tuple:
    """(F, G) of a row: F = (−margin [h], worst |θ_ss| [rad]); G <= 0 where feasible."""
    if row["verdict"] == REFUSED:
        return [PENALTY, PENALTY], [PENALTY, PENALTY, 1.0]
    f = [-row["margin_h"], row["worst_theta_ss_rad"]]
    g = [-row["margin_h"], row["worst_theta_ss_rad"] - spec.tol,
         0.0 if row["verdict"] == FEASIBLE and not row["reason"] else 1.0]
    return f, g


def evaluate(spec: DesignSpec, xs: list, *, workers=None, progress=False, pool=None) -> list:
    """Rows of designs ``xs`` (search vectors): two plans of many, every design's runs.

    A design that cannot run is a row with verdict ``refused`` and the reason; the others'
    rows come from :func:`judge`.  Rows carry the design's values under their names.
    """
    from tethersim.experiments.sweep.runner import run_plan
    built = [build_runs(spec, x) for x in xs]
    ok = [i for i, (c, _) in enumerate(built) if c is not None]
    circ_plan, free_plan = spec.plans()
    circ = [s for i in ok for s in built[i][0]]
    free = [built[i][1] for i in ok]
    per = 1 + len(SOLAR_CASES)
    recs_c = run_plan(circ_plan, circ, workers=workers, pool=pool, progress=progress,
                      desc="design: circular runs") if circ else []
    recs_f = run_plan(free_plan, free, workers=workers, pool=pool, progress=progress,
                      desc="design: free runs") if free else []
    rows = []
    for i, x in enumerate(xs):
        row = dict(spec.values(x))
        if built[i][0] is None:
            row.update(verdict=REFUSED, reason=built[i][1])
        else:
            j = ok.index(i)
            row.update(judge(spec, recs_c[j * per:(j + 1) * per], recs_f[j],
                             built[i][0][0].period))
        rows.append(row)
    return rows
