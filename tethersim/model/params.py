"""Satellite parameters a user can set or sweep, in the units of the edge.

Inside, a Satellite is SI; on the command line and in sweep files the values
are in the preset files' units (thesis units): E1, E2 in N/mm^2 (x 1 mm^2,
thesis p. 3-1), altitude in km, everything else SI.  ``EDGE_UNITS`` names them
once; ``to_si``/``from_si`` convert; ``parse_grid`` reads a grid spec such as
``0:0.02:41`` (start:stop:count, both ends included) or ``0.001,0.002,0.004``.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.model.presets import INITIAL_3D_KEYS, N_PER_MM2_TO_N
from tethersim.model.satellite import Satellite, SatelliteError

# name -> (unit at the edge, SI value per edge unit)
EDGE_UNITS = {
    "m1": ("kg", 1.0), "m2": ("kg", 1.0), "m3": ("kg", 1.0),
    "A1": ("m^2", 1.0), "A2": ("m^2", 1.0), "A3": ("m^2", 1.0),
    "a": ("m", 1.0), "b": ("m", 1.0), "l10": ("m", 1.0), "l20": ("m", 1.0),
    "E1": ("N/mm^2", N_PER_MM2_TO_N), "E2": ("N/mm^2", N_PER_MM2_TO_N),
    "c1": ("N s/m", 1.0), "c2": ("N s/m", 1.0), "CD": ("1", 1.0),
    "altitude": ("km", 1e3),
}
NAMES = tuple(EDGE_UNITS)
# the out-of-plane start of the 3-D models (Satellite.initial_3d), settable like a
# parameter (--set phi0_deg=5) but not listed in NAMES (not a sweep axis of the CLI)
INITIAL_EDGE_UNITS = {k: (unit, si) for k, (unit, _, si) in INITIAL_3D_KEYS.items()}
_ALL_UNITS = {**EDGE_UNITS, **INITIAL_EDGE_UNITS}
MAX_GRID = 1_000_000


def check_name(name: str) -> str:
    if name not in _ALL_UNITS:
        raise ValueError(f"unknown parameter {name!r}; allowed: {', '.join(_ALL_UNITS)}")
    return name


def unit(name: str) -> str:
    return _ALL_UNITS[check_name(name)][0]


def to_si(name: str, value: float) -> float:
    return float(value) * _ALL_UNITS[check_name(name)][1]


def from_si(name: str, value: float) -> float:
    return float(value) / _ALL_UNITS[check_name(name)][1]


def edge_value(sat: Satellite, name: str) -> float:
    """The satellite's value of ``name`` in edge units."""
    if check_name(name) in INITIAL_3D_KEYS:
        return from_si(name, sat.initial_3d.get(INITIAL_3D_KEYS[name][1], 0.0))
    return from_si(name, getattr(sat, name))


def with_values(sat: Satellite, values: dict) -> Satellite:
    """A copy of ``sat`` with {name: value in edge units} set (validated)."""
    fields = {check_name(k): to_si(k, v) for k, v in values.items()
              if k not in INITIAL_3D_KEYS}
    start = {INITIAL_3D_KEYS[k][1]: to_si(k, v) for k, v in values.items()
             if k in INITIAL_3D_KEYS}
    if start:
        fields["initial_3d"] = {**sat.initial_3d, **start}
    return sat.replace(**fields)


def _float(text: str, what: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise ValueError(f"{what}: {text!r} is not a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{what}: {text!r} must be finite")
    return v


def parse_grid(name: str, spec: str) -> np.ndarray:
    """Grid values (edge units) from 'start:stop:count' or a comma list."""
    what = f"--{name} {spec}"
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
    return name, _float(value.strip(), f"{option} {text}")


def apply_overrides(sat: Satellite, sets=(), scales=()) -> Satellite:
    """Apply '--set NAME=VALUE' (edge units) then '--scale NAME=FACTOR' to a satellite."""
    values = dict(parse_assignment(s) for s in sets)
    for s in scales:
        name, factor = parse_assignment(s, "--scale")
        values[name] = values.get(name, edge_value(sat, name)) * factor
    if not values:
        return sat
    try:
        return with_values(sat, values)
    except SatelliteError as exc:
        raise SatelliteError(f"after --set/--scale: {exc}") from None
