"""Preset and user satellite files (TOML), with strict validation.

File layout (units in the key name where they are not SI)::

    name = "SatI"
    [satellite]    m1 m2 m3 [kg]  A1 A2 A3 [m^2]  a b [m]; optional, for the 3-D models:
                   inertia = "boxes" | "points" (thesis Eq 4.4 boxes, or point masses),
                   I1 = [roll, pitch, yaw], I2 = [...] [kg m^2] (tip-mass, bus overrides)
    [tethers]      l10 l20 [m]  E1_N_per_mm2 E2_N_per_mm2 [N/mm^2]  c1 c2 [N s/m]
                   (optional: Fb1 Fb2 [N], breaking loads)
    [orbit]        altitude_km [km]; optional: orbit = "circular" | "free", j2 = true | false,
                   eccentricity [-] (altitude_km is then the perigee), reentry_altitude_km [km]
    [initial]      delta_x delta_y [m]  theta0_deg [deg]  delta_x_dot delta_y_dot [m/s]
                   theta_dot [rad/s]; optional, for the 3-D models: delta_z [m]
                   phi0_deg psi0_deg [deg] (roll, yaw)  delta_z_dot [m/s]
                   phi_dot psi_dot [rad/s]
    [environment]  (optional) CD [-], density = "uniform" | "per-body" (default: uniform on a
                   circular orbit, per-body on a free one)
    [model]        (optional) allow_implausible = true: run outside the plausible
                   ranges (tethersim.plausibility) knowingly; the summary says so
    [atmosphere]   (optional) atmosphere = "vallado" | "nrlmsise00", epoch = ISO UTC,
                   f107, f107a [sfu], ap, density_scale [-] (tethersim.model.options)

Moduli are given, as in the thesis, in N/mm^2 for a 1 mm^2 cross-section,
so the value in N/mm^2 equals the tether force scale in N (thesis p. 3-1).
"""
from __future__ import annotations

import math
import re
import tomllib
from importlib import resources
from pathlib import Path

from tethersim.model.constants import CD_DEFAULT, TETHER_AREA
from tethersim.model.satellite import Satellite, SatelliteError

SCHEMA = {
    "satellite": {"m1": "kg", "m2": "kg", "m3": "kg", "A1": "m^2", "A2": "m^2", "A3": "m^2",
                  "a": "m", "b": "m"},
    "tethers": {"l10": "m", "l20": "m", "E1_N_per_mm2": "N/mm^2", "E2_N_per_mm2": "N/mm^2",
                "c1": "N s/m", "c2": "N s/m"},
    "orbit": {"altitude_km": "km"},
    "initial": {"delta_x": "m", "delta_y": "m", "theta0_deg": "deg", "delta_x_dot": "m/s",
                "delta_y_dot": "m/s", "theta_dot": "rad/s"},
}
OPTIONAL = {"environment": {"CD": "1", "density": "uniform | per-body"},
            "model": {"allow_implausible": "true | false"},
            "atmosphere": {"atmosphere": "vallado | nrlmsise00", "epoch": "ISO UTC",
                           "f107": "sfu", "f107a": "sfu", "ap": "1", "density_scale": "1"}}
# optional keys of [initial]: the out-of-plane start of the 3-D models
# (file key -> (unit, Satellite.initial_3d name, SI per file unit))
INITIAL_3D_KEYS = {"delta_z": ("m", "delta_z", 1.0), "phi0_deg": ("deg", "phi", math.pi / 180),
                   "psi0_deg": ("deg", "psi", math.pi / 180),
                   "delta_z_dot": ("m/s", "delta_z_dot", 1.0),
                   "phi_dot": ("rad/s", "phi_dot", 1.0), "psi_dot": ("rad/s", "psi_dot", 1.0)}
# optional keys of required tables
OPTIONAL_KEYS = {"orbit": {"orbit": "circular | free", "j2": "true | false",
                           "eccentricity": "1", "reentry_altitude_km": "km"},
                 "satellite": {"inertia": "boxes | points", "I1": "kg m^2", "I2": "kg m^2"},
                 "tethers": {"Fb1": "N", "Fb2": "N"}}
_TEXT = {"density": str, "orbit": str, "atmosphere": str, "epoch": str, "j2": bool,
         "allow_implausible": bool, "inertia": str}
_ARRAYS = ("I1", "I2")  # [roll, pitch, yaw]: checked by the Satellite (tethersim.model.inertia)
PRESET_NAMES = {"sati": "satI.toml", "satii": "satII.toml", "dumbsat": "dumbsat.toml"}
N_PER_MM2_TO_N = 1e6 * TETHER_AREA  # (N/mm^2 -> N/m^2) x 1 mm^2 = 1


def _number(where, key, value, unit):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SatelliteError(f"{where}: {key} = {value!r}: must be a number in {unit}")
    if not math.isfinite(value):
        raise SatelliteError(f"{where}: {key} = {value}: must be a finite number in {unit}")
    return float(value)


def from_dict(doc: dict, where: str = "<dict>", allow_implausible: bool = False) -> Satellite:
    """Build a Satellite from a parsed preset document (thesis units at the edge).

    allow_implausible: accept values outside the plausible ranges (also set by the
    document's ``[model] allow_implausible = true``).
    """
    allowed_top = {"name"} | set(SCHEMA) | set(OPTIONAL)
    for key in doc:
        if key not in allowed_top:
            raise SatelliteError(f"{where}: unknown key {key!r}; allowed: {sorted(allowed_top)}")
    if not isinstance(doc.get("name"), str):
        raise SatelliteError(f"{where}: missing key 'name' (a string)")
    vals = {}
    for table, keys in list(SCHEMA.items()) + list(OPTIONAL.items()):
        sub = doc.get(table)
        if sub is None:
            if table in OPTIONAL:
                continue
            raise SatelliteError(f"{where}: missing table [{table}] with keys {sorted(keys)}")
        if not isinstance(sub, dict):
            raise SatelliteError(f"{where}: {table} must be a table [{table}]")
        extra = INITIAL_3D_KEYS if table == "initial" else OPTIONAL_KEYS.get(table, {})
        for key in sub:
            if key not in keys and key not in extra:
                raise SatelliteError(f"{where}: unknown key {table}.{key!r}; allowed: "
                                     f"{sorted(keys) + sorted(extra)}")
        initial_3d = {} if table != "initial" else {
            name: _number(where, f"initial.{key}", sub[key], unit) * si
            for key, (unit, name, si) in extra.items() if key in sub}
        if table == "initial":
            vals["initial_3d"] = initial_3d
        optional = {} if table == "initial" else extra  # [initial]'s 3-D keys are read above
        for key, unit in {**keys, **optional}.items():
            if key not in sub:
                if table in OPTIONAL or key in extra:
                    continue
                raise SatelliteError(f"{where}: missing key {table}.{key} ({unit})")
            if key in _ARRAYS:
                vals[key] = sub[key]
            elif key in _TEXT:
                if not isinstance(sub[key], _TEXT[key]):
                    kind = "true or false" if _TEXT[key] is bool else f"a string ({unit})"
                    raise SatelliteError(f"{where}: {table}.{key} = {sub[key]!r}: must be {kind}")
                vals[key] = sub[key]
            else:
                vals[key] = _number(where, f"{table}.{key}", sub[key], unit)
    initial = (vals["delta_x"], vals["delta_y"], math.radians(vals["theta0_deg"]),
               vals["delta_x_dot"], vals["delta_y_dot"], vals["theta_dot"])
    try:
        return Satellite(
            name=doc["name"], m1=vals["m1"], m2=vals["m2"], m3=vals["m3"], A1=vals["A1"],
            A2=vals["A2"], A3=vals["A3"], a=vals["a"], b=vals["b"], l10=vals["l10"],
            l20=vals["l20"], E1=vals["E1_N_per_mm2"] * N_PER_MM2_TO_N,
            E2=vals["E2_N_per_mm2"] * N_PER_MM2_TO_N, c1=vals["c1"], c2=vals["c2"],
            altitude=vals["altitude_km"] * 1e3, initial=initial,
            CD=vals.get("CD", CD_DEFAULT), density_mode=vals.get("density"),
            source=where, allow_implausible=allow_implausible or vals.get("allow_implausible", False),
            initial_3d=vals["initial_3d"], **_options(vals))
    except SatelliteError as exc:
        # name the file's key, not the internal SI field
        msg = str(exc)
        for internal, key in (("E1 =", "tethers.E1_N_per_mm2 ="), ("E2 =", "tethers.E2_N_per_mm2 ="),
                              ("theta0 =", "initial.theta0_deg ="), ("altitude =", "orbit.altitude_km ="),
                              ("phi0 =", "initial.phi0_deg ="), ("psi0 =", "initial.psi0_deg =")):
            msg = msg.replace(internal, key)
        # E in N equals the file's N/mm^2 value (1 mm^2 cross-section): name the file's unit
        msg = re.sub(r"(E[12]_N_per_mm2 = \S+) N:", r"\1 N/mm^2:", msg)
        msg = _file_key(msg, where)
        raise SatelliteError(msg) from None


def _options(vals: dict) -> dict:
    """The orbit, air and inertia options a document set (SI; absent keys keep the defaults)."""
    out = {k: vals[k] for k in ("orbit", "j2", "eccentricity", "atmosphere", "epoch", "f107",
                                "f107a", "ap", "density_scale") if k in vals}
    if "reentry_altitude_km" in vals:
        out["reentry_altitude"] = vals["reentry_altitude_km"] * 1e3
    out.update({k: vals[k] for k in ("inertia", *_ARRAYS, "Fb1", "Fb2") if k in vals})
    return out


def _file_key(msg: str, where: str) -> str:
    """Name the file's key (satellite.m1, tethers.c1, ...) of the field a message starts with."""
    from ..params import OPTIONS, PARAMETERS  # params imports this package: at call time

    head = f"{where}: "
    if not msg.startswith(head):
        return msg
    rest = msg[len(head):]
    for name, p in list(PARAMETERS.items()) + list(OPTIONS.items()):
        if rest.startswith(f"{name} = "):
            return head + p.key + rest[len(name):]
    return msg


def load(path, allow_implausible: bool = False) -> Satellite:
    """Load a satellite from a TOML file (layout: this module's docstring, the presets).

    Parameters
    ----------
    path : str or Path
        The file; values in preset units (E1, E2 in N/mm², altitude in km, else SI).
    allow_implausible : bool, optional
        Accept values outside the plausible ranges (docs/limits.md); the run's
        summary then lists them.

    Returns
    -------
    Satellite

    Raises
    ------
    SatelliteError
        One line naming the file, the field and the allowed range.

    Examples
    --------
    >>> import tethersim as ts
    >>> from importlib import resources
    >>> path = resources.files("tethersim.model.presets") / "satI.toml"
    >>> ts.load(path).name
    'SatI'
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")  # TOML is UTF-8 whatever the locale
    except OSError as exc:
        raise SatelliteError(f"{path}: cannot read: {exc.strerror}") from None
    except UnicodeDecodeError as exc:  # a binary or Latin-1 file: say which, and where
        raise SatelliteError(f"{path}: not a TOML text file: byte {exc.object[exc.start]:#04x} "
                             f"at offset {exc.start} is not UTF-8 (TOML files are UTF-8 text)"
                             ) from None
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SatelliteError(f"{path}: not valid TOML: {exc}") from None
    return from_dict(doc, str(path), allow_implausible)


def load_preset(name: str, allow_implausible: bool = False) -> Satellite:
    """A shipped preset by name.

    Parameters
    ----------
    name : str
        ``satI``, ``satII`` or ``dumbsat`` (any case).
    allow_implausible : bool, optional
        As for :func:`load`.

    Returns
    -------
    Satellite

    Raises
    ------
    SatelliteError
        An unknown name (the message lists the presets).

    Examples
    --------
    >>> import tethersim as ts
    >>> round(ts.load_preset("satI").altitude / 1e3)
    200
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a preset name (str: satI, satII, dumbsat), got "
                        f"{type(name).__name__}")
    key = name.lower()
    if key not in PRESET_NAMES:
        raise SatelliteError(f"unknown preset {name!r}; available: satI, satII, dumbsat "
                             f"(any case), or a path to a .toml file")
    ref = resources.files("tethersim.model.presets") / PRESET_NAMES[key]
    with resources.as_file(ref) as p:
        return load(p, allow_implausible)


def resolve(name_or_path: str, allow_implausible: bool = False) -> Satellite:
    """Preset name or path to a TOML file."""
    if name_or_path.lower() in PRESET_NAMES:
        return load_preset(name_or_path, allow_implausible)
    if Path(name_or_path).suffix == ".toml" or Path(name_or_path).exists():
        return load(name_or_path, allow_implausible)
    return load_preset(name_or_path, allow_implausible)
