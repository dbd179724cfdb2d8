"""Satellite parameters a user can set or sweep, in the units of the edge.

Inside, a Satellite is SI; on the command line and in sweep files the values
are in the preset files' units (thesis units): E1, E2 in N/mm^2 (x 1 mm^2,
thesis p. 3-1), altitude in km, everything else SI.  ``EDGE_UNITS`` names them
once; ``to_si``/``from_si`` convert; ``parse_grid`` reads a grid spec such as
``0:0.02:41`` (start:stop:count, both ends included) or ``0.001,0.002,0.004``.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from tethersim.model.presets import INITIAL_3D_KEYS, N_PER_MM2_TO_N
from tethersim.model.satellite import Satellite, SatelliteError

# The one table of settable quantities: name -> Param(file key, unit at the edge, SI
# value per edge unit, meaning, plausible range in edge units, why).  The range is
# where the model's assumptions hold (point masses, a 1 mm^2 tether of modulus E,
# free-molecular drag, Vallado's atmosphere); tethersim.model.plausibility checks it, and
# ``allow_implausible`` lets a user knowingly go outside.  Generous on purpose: the
# thesis presets sit well inside every range.
Param = namedtuple("Param", "key unit factor meaning low high zero_ok why")
_MASS = "a point mass from 1 g to 100 t"
_AREA = "a frontal area from 1 mm^2 to a 100 m x 100 m sail"
_LEN = "a length from 1 mm to 10 km"
PARAMETERS = {
    "m1": Param("satellite.m1", "kg", 1.0, "tip-mass mass", 1e-3, 1e5, False, _MASS),
    "m2": Param("satellite.m2", "kg", 1.0, "bus mass", 1e-3, 1e5, False, _MASS),
    "m3": Param("satellite.m3", "kg", 1.0, "balloon mass", 1e-3, 1e5, False, _MASS),
    "A1": Param("satellite.A1", "m^2", 1.0, "tip-mass frontal area", 1e-6, 1e4, False, _AREA),
    "A2": Param("satellite.A2", "m^2", 1.0, "bus frontal area", 1e-6, 1e4, False, _AREA),
    "A3": Param("satellite.A3", "m^2", 1.0, "balloon frontal area", 1e-6, 1e4, False, _AREA),
    "a": Param("satellite.a", "m", 1.0, "COM to bus", 1e-3, 1e4, False, _LEN),
    "b": Param("satellite.b", "m", 1.0, "COM to tip-mass", 1e-3, 1e4, False, _LEN),
    "l10": Param("tethers.l10", "m", 1.0, "taut length of tether 1", 1e-3, 1e4, False, _LEN),
    "l20": Param("tethers.l20", "m", 1.0, "taut length of tether 2", 1e-3, 1e4, False, _LEN),
    "E1": Param("tethers.E1_N_per_mm2", "N/mm^2", N_PER_MM2_TO_N, "tether 1 modulus x 1 mm^2",
                0.0, 1e6, True, "0 (no tether) up to 5x steel's 2e5 N/mm^2"),
    "E2": Param("tethers.E2_N_per_mm2", "N/mm^2", N_PER_MM2_TO_N, "tether 2 modulus x 1 mm^2",
                0.0, 1e6, True, "0 (no tether) up to 5x steel's 2e5 N/mm^2"),
    "c1": Param("tethers.c1", "N s/m", 1.0, "tether 1 damping", 0.0, 1e4, True,
                "0 (undamped) up to a damper that stops a 1 t mass in 0.1 s"),
    "c2": Param("tethers.c2", "N s/m", 1.0, "tether 2 damping", 0.0, 1e4, True,
                "0 (undamped) up to a damper that stops a 1 t mass in 0.1 s"),
    "Fb1": Param("tethers.Fb1", "N", 1.0, "tether 1 breaking load (0: never breaks)", 1e-3, 1e7,
                 True, "0 (unbreakable, the thesis) or a thread's 1 mN to a 10 MN cable"),
    "Fb2": Param("tethers.Fb2", "N", 1.0, "tether 2 breaking load (0: never breaks)", 1e-3, 1e7,
                 True, "0 (unbreakable, the thesis) or a thread's 1 mN to a 10 MN cable"),
    # tethers with mass (docs/beads.md): used by a run with beads (--beads N)
    "mt1": Param("tethers.mt1", "kg", 1.0, "tether 1 mass (bead chains)", 1e-6, 1e4, True,
                 "0 (massless, the thesis) or a thread's 1 mg to a 10 t cable"),
    "mt2": Param("tethers.mt2", "kg", 1.0, "tether 2 mass (bead chains)", 1e-6, 1e4, True,
                 "0 (massless, the thesis) or a thread's 1 mg to a 10 t cable"),
    "dt1": Param("tethers.dt1", "m", 1.0, "tether 1 diameter (line drag)", 1e-5, 0.1, True,
                 "0 or a 10 um filament to a 10 cm rope"),
    "dt2": Param("tethers.dt2", "m", 1.0, "tether 2 diameter (line drag)", 1e-5, 0.1, True,
                 "0 or a 10 um filament to a 10 cm rope"),
    "CDt": Param("tethers.CDt", "1", 1.0, "drag coefficient of the lines (bead chains)", 0.5,
                 4.0, True, "0 (no line drag) or a cylinder's free-molecular range"),
    # attachment points on the boom (docs/beads.md): from the COM toward the tip-mass, in
    # -a..b (the satellite checks that range; the table's is the lengths' own)
    "s1": Param("tethers.s1", "m", 1.0, "tether 1 attachment on the boom (bead chains)", -1e4,
                1e4, True, "a point from the bus end -a to the tip-mass end b"),
    "s2": Param("tethers.s2", "m", 1.0, "tether 2 attachment on the boom (bead chains)", -1e4,
                1e4, True, "a point from the bus end -a to the tip-mass end b"),
    "CD": Param("environment.CD", "1", 1.0, "drag coefficient of every body", 0.5, 4.0, True,
                "0 (no drag) or the free-molecular range of real shapes"),
    "altitude": Param("orbit.altitude_km", "km", 1e3, "circular orbit altitude", 120.0, 1000.0,
                      False, "below 120 km the orbit re-enters within hours; above 1000 km "
                             "is outside Vallado's atmosphere table"),
    # orbit and air options (tethersim.model.options holds the hard rules)
    "eccentricity": Param("orbit.eccentricity", "1", 1.0, "initial free-orbit eccentricity "
                          "(altitude at perigee)", 0.0, 0.0999, True, "near-circular orbits"),
    "reentry_altitude": Param("orbit.reentry_altitude_km", "km", 1e3, "re-entry altitude (run "
                              "ends)", 80.0, 1000.0, False, "MSIS's lower edge to the table's top"),
    "density_scale": Param("atmosphere.density_scale", "1", 1.0, "factor on the air density",
                           0.01, 100.0, False, "solar-cycle and storm densities"),
    "f107": Param("atmosphere.f107", "sfu", 1.0, "F10.7 of the previous day (MSIS)", 60.0, 400.0,
                  False, "observed solar radio flux"),
    "f107a": Param("atmosphere.f107a", "sfu", 1.0, "81-day mean F10.7 (MSIS)", 60.0, 400.0,
                   False, "observed solar radio flux"),
    "ap": Param("atmosphere.ap", "1", 1.0, "daily Ap (MSIS)", 0.0, 400.0, True,
                "quiet to a severe storm"),
}
# options that are not numbers: name -> (file key, allowed values or kind, meaning); --set
# takes them as text (orbit=free, j2=true, atmosphere=nrlmsise00, epoch=2017-06-23T00:00:00,
# inertia=points, I1=1,2,3 or I1=none: three moments roll,pitch,yaw, or back to `inertia`)
Option = namedtuple("Option", "key allowed meaning")
_MOMENTS = "roll,pitch,yaw in kg m^2 (three numbers), or none"
OPTIONS = {
    "orbit": Option("orbit.orbit", ("circular", "free"), "orbit mode"),
    "j2": Option("orbit.j2", ("true", "false"), "Earth's J2 in the free orbit"),
    "atmosphere": Option("atmosphere.atmosphere", ("vallado", "nrlmsise00"), "air model"),
    "epoch": Option("atmosphere.epoch", "ISO UTC date-time", "instant of t = 0 (MSIS)"),
    "density": Option("environment.density", ("uniform", "per-body"),
                      "one density, or each body's own altitude (default: by orbit)"),
    "inertia": Option("satellite.inertia", ("boxes", "points"),
                      "end-body moments of the 3-D models: Eq 4.4 boxes or point masses"),
    "I1": Option("satellite.I1", _MOMENTS, "tip-mass principal moments (3-D models)"),
    "I2": Option("satellite.I2", _MOMENTS, "bus principal moments (3-D models)"),
}
_OPTION_FIELDS = {"density": "density_mode"}  # option name -> Satellite field, where they differ
# name -> (unit at the edge, SI value per edge unit): the table's conversion columns
EDGE_UNITS = {n: (p.unit, p.factor) for n, p in PARAMETERS.items()}
NAMES = tuple(EDGE_UNITS)
# the out-of-plane start of the 3-D models (Satellite.initial_3d), settable like a
# parameter (--set phi0_deg=5) but not listed in NAMES (not a sweep axis of the CLI)
INITIAL_EDGE_UNITS = {k: (unit, si) for k, (unit, _, si) in INITIAL_3D_KEYS.items()}
_ALL_UNITS = {**EDGE_UNITS, **INITIAL_EDGE_UNITS}
MAX_GRID = 1_000_000
SHOWN_DIGITS = 12  # significant digits of a printed value (edge_text): no float noise


def check_name(name: str) -> str:
    if name in OPTIONS:
        o = OPTIONS[name]
        allowed = ", ".join(o.allowed) if isinstance(o.allowed, tuple) else o.allowed
        raise ValueError(f"{name!r} is an option, not a number: --set {name}=VALUE ({allowed})")
    if name not in _ALL_UNITS:
        raise ValueError(f"unknown parameter {name!r}; allowed: {', '.join(_ALL_UNITS)}; "
                         f"options: {', '.join(OPTIONS)}")
    return name


def option_value(name: str, text: str):
    """The value of option ``name`` (OPTIONS) from its text; one-line error if not allowed."""
    o = OPTIONS[name]
    value = text.strip()
    if o.allowed is _MOMENTS:
        return _moments(name, text)
    if isinstance(o.allowed, tuple):
        if value.lower() not in o.allowed:
            raise ValueError(f"--set {name}={_shown(text)}: allowed values "
                             f"{', '.join(o.allowed)}")
        value = value.lower()
    return value == "true" if name == "j2" else value


def _moments(name: str, text: str):
    """'1,2,3' -> (1.0, 2.0, 3.0); 'none' -> None (the satellite's ``inertia`` again)."""
    if text.strip().lower() == "none":
        return None
    parts = text.split(",")
    what = f"--set {name}={_shown(text)}"
    if len(parts) != 3:
        raise ValueError(f"{what}: expected {_MOMENTS}, e.g. {name}=10,12,3")
    return tuple(_float(part.strip(), what) for part in parts)


def unit(name: str) -> str:
    return _ALL_UNITS[check_name(name)][0]


def to_si(name: str, value: float) -> float:
    return float(value) * _ALL_UNITS[check_name(name)][1]


def from_si(name: str, value: float) -> float:
    return float(value) / _ALL_UNITS[check_name(name)][1]


def edge_value(sat: Satellite, name: str) -> float:
    """The satellite's value of ``name`` in edge units (NaN for an unset index)."""
    if check_name(name) in INITIAL_3D_KEYS:
        return from_si(name, sat.initial_3d.get(INITIAL_3D_KEYS[name][1], 0.0))
    v = getattr(sat, name)
    return math.nan if v is None else from_si(name, v)


def edge_text(sat: Satellite, name: str) -> str:
    """The satellite's value of ``name`` in edge units as short text (``nan`` if unset).

    The shortest text of at most :data:`SHOWN_DIGITS` significant digits that converts
    back to the same SI value, so it fed back through ``--set NAME=TEXT`` gives the same
    satellite; a value that has no such text (a product of ``--scale``: 0.0423 x 100 is
    4.2299999999999995) is rounded to that many digits, within 5e-13 relative.
    """
    v = edge_value(sat, name)
    if not math.isfinite(v):
        return repr(v)
    si = (sat.initial_3d.get(INITIAL_3D_KEYS[name][1], 0.0) if name in INITIAL_3D_KEYS
          else getattr(sat, name))
    for digits in range(1, SHOWN_DIGITS):
        if to_si(name, float(f"{v:.{digits}g}")) == si:
            break
    # through float and 15 digits: 10, not the 1e+01 of .1g; a short value prints as is
    return f"{float(f'{v:.{digits}g}'):.15g}"


def with_values(sat: Satellite, values: dict) -> Satellite:
    """A copy of ``sat`` with {name: value in edge units} set (validated)."""
    fields = {check_name(k): to_si(k, v) for k, v in values.items()
              if k not in INITIAL_3D_KEYS}
    start = {INITIAL_3D_KEYS[k][1]: to_si(k, v) for k, v in values.items()
             if k in INITIAL_3D_KEYS}
    if start:
        fields["initial_3d"] = {**sat.initial_3d, **start}
    return sat.replace(**fields)


def _shown(text: str) -> str:
    """The user's text as typed, or escaped (repr) if it holds a line break or control
    character: an error message stays one line whatever was typed."""
    return text if text.isprintable() else repr(text)


def _float(text: str, what: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise ValueError(f"{what}: {text!r} is not a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{what}: {text!r} must be finite")
    return v


def parse_grid(name: str, spec: str) -> np.ndarray:
    """Grid values (edge units) from 'start:stop:count' or a comma list.

    Raises ValueError naming the option, the spec and what a good value is.
    """
    try:
        return _parse_grid(name, spec)
    except ValueError as exc:
        p = PARAMETERS.get(name)
        if p is None or ("not a number" not in str(exc) and "must be finite" not in str(exc)):
            raise
        raise ValueError(f"{exc} (expected {name} values in {p.unit}, plausible range "
                         f"{p.low:g}..{p.high:g})") from None


def _parse_grid(name: str, spec: str) -> np.ndarray:
    what = f"--{name} {_shown(spec)}"
    if ":" in spec:
        parts = spec.split(":")
        if len(parts) != 3:
            raise ValueError(f"{what}: expected start:stop:count, e.g. 0:0.02:41")
        start, stop = _float(parts[0], what), _float(parts[1], what)
        try:
            n = int(parts[2])
        except ValueError:
            raise ValueError(f"{what}: count {parts[2]!r} must be an integer >= 1") from None
        if not 1 <= n <= MAX_GRID:
            raise ValueError(f"{what}: count {n} must be in 1..{MAX_GRID}")
        if n == 1 and start != stop:
            raise ValueError(f"{what}: a single point needs start == stop")
        values = np.linspace(start, stop, n)
    else:
        values = np.array([_float(s, what) for s in spec.split(",") if s.strip()])
        if values.size == 0:
            raise ValueError(f"{what}: no values")
    if np.unique(values).size != values.size:
        raise ValueError(f"{what}: values repeat")
    return values


def parse_assignment(text: str, option: str = "--set") -> tuple:
    """'E1=0.006' -> ('E1', 0.006) (edge units); ``option`` names the flag in errors."""
    if "=" not in text:
        raise ValueError(f"{option} {text!r}: expected NAME=VALUE, e.g. E1=0.006")
    name, value = text.split("=", 1)
    name = check_name(name.strip())
    try:
        return name, _float(value.strip(), f"{option} {_shown(text)}")
    except ValueError as exc:  # say what a good value looks like
        raise ValueError(f"{exc} (expected {_expected(name, option)})") from None


def _expected(name: str, option: str) -> str:
    """What a good ``option NAME=VALUE`` value is: a factor, or the name's unit and range
    (the plausible range of :data:`PARAMETERS`; the 3-D start has none, any finite value)."""
    if option == "--scale":
        return "a factor"
    if name in PARAMETERS:
        p = PARAMETERS[name]
        return f"{name} in {p.unit}, plausible range {p.low:g}..{p.high:g}"
    return f"{name} in {_ALL_UNITS[name][0]}, a finite number"


def apply_overrides(sat: Satellite, sets=(), scales=()) -> Satellite:
    """Apply '--set NAME=VALUE' (edge units) then '--scale NAME=FACTOR' to a satellite.

    Options (:data:`OPTIONS`: orbit, j2, atmosphere, epoch) are set as text first.
    """
    chosen = {}
    numbers = []
    for s in sets:
        name = s.split("=", 1)[0].strip()
        if "=" in s and name in OPTIONS:
            chosen[_OPTION_FIELDS.get(name, name)] = option_value(name, s.split("=", 1)[1])
        else:
            numbers.append(s)
    if chosen:
        try:
            sat = sat.replace(**chosen)
        except SatelliteError as exc:
            raise SatelliteError(f"after --set: {exc}") from None
    values = dict(parse_assignment(s) for s in numbers)
    for s in scales:
        name, factor = parse_assignment(s, "--scale")
        base = values.get(name, edge_value(sat, name))
        if math.isnan(base):  # an index left to the space-weather table: nothing to scale
            raise ValueError(f"--scale {name}: {name} is unset (read from the space-weather "
                             f"table): set it first, e.g. --set {name}=150 --scale {s}")
        values[name] = base * factor
    if not values:
        return sat
    try:
        return with_values(sat, values)
    except SatelliteError as exc:
        raise SatelliteError(f"after --set/--scale: {exc}") from None
