"""What a Monte Carlo draws: the uncertain inputs, their bands, and one random stream each.

Every input is uniform over a band (docs/montecarlo.md says why each band): a
*scale* multiplies the design's value, a *logscale* multiplies it by a factor uniform
in its logarithm, an *offset* adds to it, and the epoch is uniform in time over a span
of the bundled space-weather history.  Each input maps a number u in (0, 1) to its
value (the band's inverse CDF), so the same map serves the random samples and the
Sobol' design (whose points are u's).

Random streams: input ``name`` draws its u's from
``numpy.random.default_rng(SeedSequence(seed, spawn_key=(crc32(name),)))``: a stream of
its own, keyed by its name, not by its place in the table, so changing one input's band,
or adding an input, leaves every other input's draws as they were; sample i takes the
i-th number of each stream, so a larger n keeps the first samples.
"""
from __future__ import annotations

import functools
import math
import zlib
from dataclasses import dataclass

import numpy as np

KINDS = ("scale", "logscale", "offset", "epoch")
# initial-state inputs: name -> index in Satellite.initial, SI per edge unit
_INITIAL = {"theta0": (2, math.pi / 180), "theta_dot0": (5, math.pi / 180),
            "delta_x_dot0": (3, 1.0)}


@dataclass(frozen=True)
class Input:
    """One uncertain input: a uniform band in edge units.

    Attributes
    ----------
    name : str
        The satellite field (``CD``, ``A3``, ``E1``...), an initial-state name of
        ``_INITIAL`` or ``epoch``.
    kind : str
        One of :data:`KINDS`.
    low, high : float or str
        The band: factors (scale, logscale), an offset in ``unit`` (offset), or ISO UTC
        days (epoch: from the start of ``low`` to the end of ``high``).
    unit : str
        The offset's edge unit ("1" for a factor).
    meaning : str
        What it stands for (tables and docs).
    """

    name: str
    kind: str
    low: float | str
    high: float | str
    unit: str
    meaning: str

    def check(self) -> None:
        """Refuse a band that cannot be drawn (one line naming the input)."""
        if self.kind == "epoch":
            lo, hi = epoch_seconds(self.low), epoch_seconds(self.high) + 86400
            if not lo < hi:
                raise ValueError(f"range of epoch = {self.low}:{self.high}: the first day must "
                                 f"not be after the last")
            return
        lo, hi = self.low, self.high
        if not (isinstance(lo, (int, float)) and isinstance(hi, (int, float))
                and math.isfinite(lo) and math.isfinite(hi) and lo <= hi):
            raise ValueError(f"range of {self.name} = {lo}:{hi}: need finite numbers LOW <= HIGH")
        if self.kind in ("scale", "logscale") and not lo > 0:
            raise ValueError(f"range of {self.name} = {lo}:{hi}: a factor band must be > 0")

    def value(self, u: np.ndarray, nominal: float = 0.0) -> np.ndarray:
        """The input's values [SI; epoch: seconds since 1970] at unit numbers ``u``."""
        u = np.asarray(u, dtype=float)
        if self.kind == "epoch":
            # uniform over the time of the span's usable days, laid end to end
            days = usable_days(str(self.low), str(self.high))
            t = np.minimum(np.floor(u * days.size * 86400.0), days.size * 86400.0 - 1)
            return days[(t // 86400).astype(np.int64)] + t % 86400  # whole seconds
        if self.kind == "logscale":
            return nominal * np.exp(math.log(self.low) + u * math.log(self.high / self.low))
        if self.kind == "scale":
            return nominal * (self.low + u * (self.high - self.low))
        si = _INITIAL[self.name][1]
        return nominal + si * (self.low + u * (self.high - self.low))


def epoch_seconds(day: str) -> float:
    """Seconds since 1970 of the start of UTC day ``day`` (ISO)."""
    try:
        return float(np.datetime64(str(day), "D").astype("datetime64[s]").astype(np.int64))
    except ValueError:
        raise ValueError(f"epoch day {day!r}: must be an ISO date, e.g. 1996-05-01") from None


@functools.lru_cache(maxsize=8)
def usable_days(first: str, last: str) -> np.ndarray:
    """Start [s since 1970] of every day from ``first`` to ``last`` (ISO, both included)
    whose table indices NRLMSISE-00 accepts as an epoch (tethersim.model.air.model's
    F10.7 60-400 sfu, Ap 0-400): a few days of a radio burst (F10.7 > 400) or a reading
    below 60 sfu are left out (9 of the 14 500 days from 1986-09-01 to 2026-06-30)."""
    from tethersim.model.air.indices import bundled_table, indices_for_day
    from tethersim.model.air.model import AP_RANGE, F107_RANGE
    t = bundled_table()
    days = np.arange(np.datetime64(first, "D"), np.datetime64(last, "D") + 1)
    k = np.searchsorted(t["days"], days)

    def out(v, lo, hi):
        return (v < lo) | (v > hi)
    # candidates: a value out of range on the day or the day before (f107 is the previous
    # day's flux); each is then checked as an epoch reads it
    f = t["f107_obs"]
    suspect = (out(f[k], *F107_RANGE) | out(f[k - 1], *F107_RANGE)
               | out(t["f107a_obs"][k], *F107_RANGE) | out(t["ap"][k], *AP_RANGE))
    keep = np.ones(days.size, bool)
    for j in np.nonzero(suspect)[0]:
        d = indices_for_day(days[j])
        keep[j] = not (out(d.f107, *F107_RANGE) or out(d.f107a, *F107_RANGE)
                       or out(d.ap, *AP_RANGE))
    return days[keep].astype("datetime64[s]").astype(np.int64).astype(float)


def iso(seconds: float) -> str:
    """ISO UTC time of ``seconds`` since 1970."""
    return str(np.datetime64(int(seconds), "s"))


def observed_days() -> tuple:
    """(first, last) ISO day of the bundled table's *observed* rows (not its forecast)."""
    from tethersim.model.air.indices import bundled_table, table_span
    t = bundled_table()
    return str(table_span()[0]), str(t["days"][~t["forecast"]][-1])


# Solar cycle 22 began at the minimum of September 1986: from there the span holds
# cycles 22-24 whole and 25 up to the table's last observed day (docs/montecarlo.md)
EPOCH_FIRST = "1986-09-01"


def default_inputs(last_epoch_day: str) -> tuple:
    """The default bands (docs/montecarlo.md gives the reason for each)."""
    return (
        Input("epoch", "epoch", EPOCH_FIRST, last_epoch_day, "day",
              "start instant: the daily F10.7, F10.7a and Ap of every day of the run"),
        Input("CD", "scale", 0.85, 1.15, "1", "drag coefficient (free-molecular accommodation)"),
        Input("A3", "scale", 0.8, 1.0, "1", "balloon frontal area (inflation: 80-100 %)"),
        Input("E1", "scale", 0.8, 1.2, "1", "tether 1 modulus (material, temperature)"),
        Input("E2", "scale", 0.8, 1.2, "1", "tether 2 modulus (material, temperature)"),
        Input("c1", "logscale", 0.5, 2.0, "1", "tether 1 damping (least known: x/2 to x2)"),
        Input("c2", "logscale", 0.5, 2.0, "1", "tether 2 damping (least known: x/2 to x2)"),
        Input("theta0", "offset", -15.0, 15.0, "deg", "initial pitch after deployment"),
        Input("theta_dot0", "offset", -0.05, 0.05, "deg/s",
              "initial pitch rate (about +-0.75 x the orbit rate at 200 km)"),
        Input("delta_x_dot0", "offset", -0.05, 0.05, "m/s",
              "residual balloon separation speed along the trail"),
    )


def with_ranges(inputs: tuple, ranges) -> tuple:
    """``inputs`` with the bands of ``ranges`` ({name: (low, high)}) replaced, checked."""
    from dataclasses import replace
    names = [i.name for i in inputs]
    ranges = dict(ranges)
    bad = [k for k in ranges if k not in names]
    if bad:
        raise ValueError(f"range of {bad[0]}: unknown input; inputs are {', '.join(names)}")
    out = tuple(replace(i, low=ranges[i.name][0], high=ranges[i.name][1])
                if i.name in ranges else i for i in inputs)
    for i in out:
        i.check()
    return out


def stream(seed: int, name: str) -> np.random.Generator:
    """The random stream of input ``name`` under ``seed`` (its own, keyed by its name)."""
    return np.random.default_rng(np.random.SeedSequence(int(seed),
                                                        spawn_key=(zlib.crc32(name.encode()),)))


def unit_draws(inputs: tuple, n: int, seed: int) -> np.ndarray:
    """(n, d) unit numbers of the random samples: column j from input j's own stream."""
    return np.column_stack([stream(seed, i.name).random(n) for i in inputs]) if n else \
        np.empty((0, len(inputs)))


def sample_satellites(base, inputs: tuple, u: np.ndarray, model: str = "derived") -> list:
    """[(values, circular satellite, free satellite)] at each row of unit numbers ``u``.

    ``values`` maps each input's name to its value in SI (the epoch as an ISO UTC
    instant).  Both satellites breathe NRLMSISE-00 air from the sample's epoch with the
    table's daily indices (f107, f107a, ap left None): the circular one the uniform
    density (the 24-local-time mean at the orbit altitude on the epoch's day: the
    thesis's held orbit), the free one each body's own density along the run.

    Each satellite's ``initial`` is the sample's start (the plans run it as given).  The
    thesis's tethers start at the design's ``initial`` plus the drawn offsets, as the
    thesis did.  Real lines (engine/start.py: their auto start is the equilibrium) start
    at the sample's own equilibrium in ``model``, deployed by the same offsets as a whole
    formation: boom and balloon turned together by the θ0 offset (the lines keep their
    length), turning at the θ̇0 offset, the balloon moving away from the COM at the
    δẋ0 offset; an equilibrium the thesis's damper turned over is refused in one line.
    """
    out = []
    for row in np.atleast_2d(u):
        vals, changes, init = {}, {}, list(base.initial)
        for i, x in zip(inputs, row):
            if i.kind == "epoch":
                vals["epoch"] = iso(i.value(x))
            elif i.name in _INITIAL:
                k = _INITIAL[i.name][0]
                init[k] = float(i.value(x, base.initial[k]))
                vals[i.name] = init[k]
            else:
                changes[i.name] = vals[i.name] = float(i.value(x, getattr(base, i.name)))
        circ = base.replace(initial=tuple(init), atmosphere="nrlmsise00",
                            epoch=vals.get("epoch", base.epoch), f107=None, f107a=None, ap=None,
                            orbit="circular", density_mode="uniform", **changes)
        circ = _deployed(circ, model, np.subtract(init, base.initial))
        for name, (k, _) in _INITIAL.items():  # the start as run (real lines: deployed)
            if name in vals:
                vals[name] = circ.initial[k]
        free = circ.replace(orbit="free", density_mode="per-body")
        out.append((vals, circ, free))
    return out


def _deployed(sat, model: str, offset):
    """``sat`` itself for the thesis's tethers (its ``initial`` holds the offsets); on real
    lines its equilibrium in ``model`` deployed by ``offset`` (θ0, θ̇0, δẋ0 at indices 2,
    5, 3) as a whole formation (:func:`sample_satellites`)."""
    from tethersim.engine.start import resolved_mode, start_satellite
    if resolved_mode(sat, "auto") != "equilibrium":
        return sat
    eq = start_satellite(sat, model)[0]  # refuses a start the thesis's damper turned over
    dx, dy, theta = eq.initial[:3]
    turn, rate, away = offset[2], offset[5], offset[3]
    # θ turns the tip-mass from +y towards +x: a turn by φ maps (x, y) to
    # (x cos φ + y sin φ, −x sin φ + y cos φ), and turning at rate ω moves (x, y) at
    # ω (y, −x)
    x = dx * math.cos(turn) + dy * math.sin(turn)
    y = -dx * math.sin(turn) + dy * math.cos(turn)
    r = math.hypot(x, y)
    return eq.replace(initial=(x, y, theta + turn, rate * y + away * x / r,
                               -rate * x + away * y / r, rate))
