"""The satellite record: every Table 4.1 quantity in SI, validated on creation.

Units at the edge (N/mm^2, km, degrees) are converted by tethersim.model.presets;
inside, a :class:`Satellite` holds SI only.  E1, E2 are tether moduli times the
thesis's 1 mm^2 cross-section, i.e. forces in N (thesis p. 3-1).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, fields, replace

from tethersim.model import atmosphere, inertia, options
from tethersim.model.constants import CD_DEFAULT, MU_EARTH, OMEGA_EARTH, R_EARTH

# fields that must be > 0 and >= 0 (units in UNITS)
_POSITIVE = ("m1", "m2", "m3", "A1", "A2", "A3", "a", "b", "l10", "l20")
_NON_NEGATIVE = ("E1", "E2", "c1", "c2", "CD", "Fb1", "Fb2")
MAX_NAME = 100  # characters of a name: a label in summaries, plot titles and files
COM_RTOL = 1e-6  # relative tolerance of the COM-on-the-boom condition m1 b = m2 a
DENSITY_MODES = ("uniform", "per-body")
# density_mode chosen by the orbit when none is given (docs/air.md)
DENSITY_BY_ORBIT = {"circular": "uniform", "free": "per-body"}
# out-of-plane initial state of the 3-D models (docs/roll.md): name -> unit
INITIAL_3D = {"delta_z": "m", "phi": "rad", "psi": "rad", "delta_z_dot": "m/s",
              "phi_dot": "rad/s", "psi_dot": "rad/s"}
# largest |roll| of the 3-D models' domain [deg]: the roll-pitch-yaw angles are singular at
# 90 deg; why 80 (the kinematic matrix's conditioning): tethersim.engine.domain
ROLL_LIMIT_DEG = 80.0
_OPTIONAL = ("Fb1", "Fb2", "allow_implausible", "orbit", "j2", "eccentricity",
             "reentry_altitude", "atmosphere", "epoch", "f107", "f107a", "ap", "density_scale",
             "inertia", "I1", "I2", "beads", "mt1", "mt2", "dt1", "dt2", "CDt", "s1", "s2")
UNITS = {"m1": "kg", "m2": "kg", "m3": "kg", "A1": "m^2", "A2": "m^2", "A3": "m^2",
         "a": "m", "b": "m", "l10": "m", "l20": "m", "E1": "N", "E2": "N",
         "c1": "N s/m", "c2": "N s/m", "CD": "1", "altitude": "m", "Fb1": "N", "Fb2": "N"}


class SatelliteError(ValueError):
    """A satellite definition that cannot be simulated; the message names the field."""


@dataclass(frozen=True)
class Satellite:
    """A tethered-balloon gravity-gradient satellite (SI units throughout).

    Validated on creation: one-line :class:`SatelliteError` naming the field and
    its allowed range (plausible ranges: ``tethersim.model.params.PARAMETERS``,
    docs/limits.md).  ``replace(**changes)`` returns a validated copy.

    Attributes
    ----------
    name : str
        Display name.
    m1, m2, m3 : float
        Tip-mass, bus, balloon masses [kg].
    A1, A2, A3 : float
        Their frontal areas [m²].
    a, b : float
        COM to bus and COM to tip-mass distances [m] (m1 b = m2 a).
    l10, l20 : float
        Rest lengths of tether 1 (tip-mass) and tether 2 (bus) [m].
    E1, E2 : float
        Tether moduli times the 1 mm² cross-section [N] (N/mm² at the edge).
    c1, c2 : float
        Tether damping coefficients [N s/m].
    altitude : float
        Circular orbit altitude [m] (km at the edge).
    initial : tuple
        (δx, δy, θ, δẋ, δẏ, θ̇) at t = 0 in m, m, rad, m/s, m/s, rad/s.
    CD : float
        Drag coefficient of every body.
    Fb1, Fb2 : float
        Tether breaking loads [N] (0, the default: never breaks).  A run ends
        ``tether-broke`` when a tether's spring tension E (λ − l0) / l0 reaches it,
        at the located time (engine/events.py; docs/tethers.md).
    density_mode : str
        "uniform" (thesis: ρ at the orbit altitude for every body) or
        "per-body" (each body at its own altitude).  Given as None (the default),
        it follows the orbit: "uniform" on a circular orbit, "per-body" on a free
        one (whose air must thicken as it sinks); ``density_auto`` records that.
    density_auto : bool
        True when ``density_mode`` was not given but chosen by the orbit (it
        follows the orbit again in ``replace``); not an argument.
    initial_3d : dict
        The out-of-plane start of the 3-D models, {name: value} with names in
        ``INITIAL_3D`` (δz [m], roll φ [rad], |φ| <= ``ROLL_LIMIT_DEG``, yaw ψ [rad]
        and their rates); missing names are zero, and the planar models ignore it.
    orbit, j2, eccentricity, reentry_altitude, atmosphere, epoch, f107, f107a, ap, density_scale
        Orbit and air options (tethersim.model.options): circular or free orbit, J2,
        eccentricity (altitude at perigee), re-entry altitude [m], air model,
        epoch, solar and geomagnetic indices, density scale.
    inertia : str
        End-body moments of the 3-D models (tethersim.model.inertia): ``"boxes"``
        (thesis Eq 4.4, I = m · 2A / 12 about every axis) or ``"points"`` (zero).
    I1, I2 : tuple or None
        (roll, pitch, yaw) principal moments [kg m²] of the tip-mass and the bus,
        overriding ``inertia`` for that body; each >= 0 and <= the sum of the
        other two.  The planar models ignore ``inertia``, ``I1``, ``I2``.
    """

    name: str
    m1: float
    m2: float
    m3: float
    A1: float
    A2: float
    A3: float
    a: float
    b: float
    l10: float
    l20: float
    E1: float
    E2: float
    c1: float
    c2: float
    altitude: float
    initial: tuple = (0.0, 0.0, math.pi / 6, 0.0, 0.0, 0.0)
    CD: float = CD_DEFAULT
    Fb1: float = 0.0  # N, breaking load of tether 1 (0: never breaks; docs/tethers.md)
    Fb2: float = 0.0  # N
    density_mode: str | None = None  # None: follows the orbit (DENSITY_BY_ORBIT)
    source: str = field(default="", compare=False)
    allow_implausible: bool = False  # run outside tethersim.model.plausibility's ranges knowingly
    initial_3d: dict = field(default_factory=dict, hash=False)
    # orbit and air options (tethersim.model.options; edge units in tethersim.model.params)
    orbit: str = "circular"
    j2: bool = False
    eccentricity: float = 0.0
    reentry_altitude: float = 120e3  # m
    atmosphere: str = "vallado"
    epoch: str = options.DEFAULT_EPOCH
    f107: float | None = None  # sfu
    f107a: float | None = None  # sfu
    ap: float | None = None
    density_scale: float = 1.0
    # end-body inertias of the 3-D models (tethersim.model.inertia), kg m^2
    inertia: str = "boxes"
    I1: tuple | None = None
    I2: tuple | None = None
    # tethers with mass (docs/beads.md): beads per line (None: the massless springs of the
    # chosen model; 0-64: a chain, tethersim.model.beads), line masses [kg], diameters [m]
    # and the lines' drag coefficient (0: no line drag)
    beads: int | None = None
    mt1: float = 0.0
    mt2: float = 0.0
    dt1: float = 0.0
    dt2: float = 0.0
    CDt: float = 0.0
    # where each tether holds the boom [m], from the COM toward the tip-mass (None: the
    # thesis's boom ends, tether 1 at the tip-mass b, tether 2 at the bus −a); any point
    # from −a to b, the COM (0) included; runs as a bead chain (docs/beads.md)
    s1: float | None = None
    s2: float | None = None
    density_auto: bool = field(default=False, init=False, compare=False, repr=False)

    def __post_init__(self):
        n = self.name
        if not (isinstance(n, str) and n.strip() and n.isprintable() and len(n) <= MAX_NAME):
            raise SatelliteError(f"{self._where()}name = {n!r:.60}: must be printable text, "
                                 f"1 to {MAX_NAME} characters, no line breaks or control "
                                 f"characters")
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name in _POSITIVE + _NON_NEGATIVE + ("altitude",):
                try:
                    v = float(v)
                except (TypeError, ValueError):
                    raise SatelliteError(f"{self._where()}{f.name} = {v!r}: must be a number "
                                         f"({UNITS[f.name]})") from None
                object.__setattr__(self, f.name, v)
                if not math.isfinite(v):
                    raise SatelliteError(f"{self._where()}{f.name} = {v}: must be a finite number")
        for k in _POSITIVE:
            if not getattr(self, k) > 0:
                raise SatelliteError(f"{self._where()}{k} = {getattr(self, k)} {UNITS[k]}: "
                                     f"must be > 0")
        for k in _NON_NEGATIVE:
            if not getattr(self, k) >= 0:
                raise SatelliteError(f"{self._where()}{k} = {getattr(self, k)} {UNITS[k]}: "
                                     f"must be >= 0")
        if not (atmosphere.H_MIN <= self.altitude <= atmosphere.H_MAX):
            raise SatelliteError(f"{self._where()}altitude = {self.altitude / 1e3:g} km: "
                                 f"allowed range 0-1000 km (Vallado's exponential atmosphere)")
        lhs, rhs = self.m1 * self.b, self.m2 * self.a
        if abs(lhs - rhs) > COM_RTOL * max(lhs, rhs):
            raise SatelliteError(
                f"{self._where()}COM off the boom: m1*b = {lhs:g} kg m but m2*a = {rhs:g} kg m; "
                f"the thesis puts the COM on the boom (p. 3-1), so m1*b must equal m2*a "
                f"(relative difference <= {COM_RTOL:g}); e.g. a = {lhs / self.m2:.6g} m")
        for k in ("s1", "s2"):
            v = getattr(self, k)
            if v is None:
                continue
            try:
                v = float(v)
            except (TypeError, ValueError):
                v = math.nan
            if not -self.a <= v <= self.b:
                raise SatelliteError(f"{self._where()}{k} = {getattr(self, k)!r} m: allowed "
                                     f"{-self.a:g} to {self.b:g} m (a point on the boom, from "
                                     f"the bus end -a through the COM 0 to the tip-mass end b)")
            # the line's own boom end is the thesis's: None, one satellite whichever way given
            object.__setattr__(self, k, None if v == (self.b if k == "s1" else -self.a) else v)
        try:
            init = tuple(float(x) for x in self.initial)
        except (TypeError, ValueError):
            init = ()
        if len(init) != 6 or not all(math.isfinite(x) for x in init):
            raise SatelliteError(f"{self._where()}initial = {self.initial!r}: must be 6 finite "
                                 f"numbers (δx, δy, θ, δẋ, δẏ, θ̇)")
        if not -math.pi <= init[2] <= math.pi:
            raise SatelliteError(f"{self._where()}theta0 = {math.degrees(init[2]):g} deg: "
                                 f"allowed range -180 to 180 deg")
        object.__setattr__(self, "initial", init)
        object.__setattr__(self, "initial_3d", self._checked_initial_3d())
        auto = self.density_mode is None
        object.__setattr__(self, "density_auto", auto)
        if auto:
            # the thesis's uniform air on its held circular orbit; a free orbit's air
            # follows each body's altitude (a uniform 200-km density would not re-enter)
            object.__setattr__(self, "density_mode", DENSITY_BY_ORBIT.get(self.orbit, "uniform"))
        if self.density_mode not in DENSITY_MODES:
            raise SatelliteError(f"{self._where()}density = {self.density_mode!r}: "
                                 f"allowed values {DENSITY_MODES}")
        if self.density_mode == "per-body":
            reach = options.body_reach(self)
            h_min, h_max = options.air_range(self)
            lo, hi = h_min + reach, h_max - reach
            if not lo <= self.altitude <= hi:
                why = " (the free orbit's default)" if auto else ""
                raise SatelliteError(
                    f"{self._where()}altitude = {self.altitude / 1e3:g} km with density = "
                    f"'per-body'{why}: allowed range {lo / 1e3:.3f}-{hi / 1e3:.3f} km, so that "
                    f"every body (within {reach:.4g} m of the COM) stays inside "
                    f"{h_min / 1e3:g}-{h_max / 1e3:g} km ({self.atmosphere})")
        options.check(self)
        inertia.check(self)
        if not isinstance(self.allow_implausible, bool):
            raise SatelliteError(f"{self._where()}allow_implausible = {self.allow_implausible!r}: "
                                 f"must be true or false")
        from . import plausibility  # imports params, which imports this module
        plausibility.check(self, self._where())

    def _checked_initial_3d(self) -> dict:
        given = self.initial_3d if self.initial_3d is not None else {}
        if not isinstance(given, dict):
            raise SatelliteError(f"{self._where()}initial_3d = {given!r}: must be a dict "
                                 f"{{name: value}} with names in {', '.join(INITIAL_3D)}")
        out = {}
        for k, v in given.items():
            if k not in INITIAL_3D:
                raise SatelliteError(f"{self._where()}initial_3d[{k!r}]: unknown; allowed "
                                     f"{', '.join(INITIAL_3D)}")
            try:
                v = float(v)
            except (TypeError, ValueError):
                v = math.nan
            if not math.isfinite(v):
                raise SatelliteError(f"{self._where()}initial_3d[{k!r}] = {given[k]!r}: must "
                                     f"be a finite number ({INITIAL_3D[k]})")
            if k == "phi" and not abs(v) <= math.radians(ROLL_LIMIT_DEG):
                raise SatelliteError(f"{self._where()}phi0 = {math.degrees(v):g} deg: allowed "
                                     f"range -{ROLL_LIMIT_DEG:g} to {ROLL_LIMIT_DEG:g} deg (the "
                                     f"3-D models' domain: the roll-pitch-yaw angles are "
                                     f"singular at |phi| = 90 deg, docs/limits.md)")
            if k == "psi" and not -math.pi <= v <= math.pi:
                raise SatelliteError(f"{self._where()}psi0 = {math.degrees(v):g} deg: allowed "
                                     f"range -180 to 180 deg")
            out[k] = v
        return out

    def _where(self) -> str:
        return f"{self.source}: " if self.source else ""

    # --- derived quantities --------------------------------------------------
    @property
    def r0(self) -> float:
        """Orbit radius of the COM [m]."""
        return R_EARTH + self.altitude

    @property
    def omega(self) -> float:
        """Orbital rate sqrt(μ/r0³) [rad/s] (Eq 3.14)."""
        return math.sqrt(MU_EARTH / self.r0**3)

    @property
    def period(self) -> float:
        """Orbital period [s]."""
        return 2 * math.pi / self.omega

    @property
    def rho(self) -> float:
        """Air density of the uniform density mode [kg/m^3] (tethersim.model.options)."""
        return options.uniform_density(self)

    @property
    def absent_lines(self) -> tuple:
        """(tether 1, tether 2) absent: E = c = 0 and no mass, one line flown alone."""
        return (self.E1 == self.c1 == self.mt1 == 0.0, self.E2 == self.c2 == self.mt2 == 0.0)

    @property
    def pitch_inertia(self) -> float:
        """m1 b² + m2 a² [kg m²]: the point-mass moment about the COM (Eq 3.30)."""
        return self.m1 * self.b**2 + self.m2 * self.a**2

    @property
    def implausible(self) -> tuple:
        """Plausibility violations allowed by ``allow_implausible`` (empty if none).

        A tether too stiff for the explicit schemes is not one (the implicit scheme
        integrates it); a run with an explicit scheme lists it too
        (plausibility.allowed_problems)."""
        from . import plausibility
        return tuple(plausibility.problems(self))

    def replace(self, **changes) -> Satellite:
        """A copy with fields changed (validated again)."""
        if self.source and "source" not in changes and not self.source.endswith("(modified)"):
            changes["source"] = f"{self.source} (modified)"
        if self.density_auto and "density_mode" not in changes:
            changes["density_mode"] = None  # still follows the (maybe changed) orbit
        return replace(self, **changes)

    def to_dict(self) -> dict:
        d = asdict(self)
        d.pop("source")
        d.pop("density_auto")
        if self.density_auto:  # chosen by the orbit: absent, so it follows it when read back
            d.pop("density_mode")
        for f in fields(self):  # options at their defaults are absent: store JSON unchanged
            if f.name in _OPTIONAL and d[f.name] == f.default:
                d.pop(f.name)
        return d


def parameters(sat: Satellite) -> dict:
    """The thesis symbols as SI floats (contract of tethersim.parameters)."""
    rho = sat.rho
    values = {
        "m1": sat.m1, "m2": sat.m2, "m3": sat.m3, "A1": sat.A1, "A2": sat.A2, "A3": sat.A3,
        "a": sat.a, "b": sat.b, "l10": sat.l10, "l20": sat.l20, "E1": sat.E1, "E2": sat.E2,
        "c1": sat.c1, "c2": sat.c2, "CD": sat.CD, "r0": sat.r0, "mu": MU_EARTH,
        "omega": sat.omega, "omega_earth": OMEGA_EARTH, "rho": rho,
        "rho1": rho, "rho2": rho, "rho3": rho,
    }
    return values

