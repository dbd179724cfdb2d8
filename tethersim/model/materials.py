"""Tether materials: what a real line's axial stiffness, strength and damping are.

The thesis's tethers are a modulus times 1 mm² (E·1 mm², thesis p. 3-1): 0.004
and 0.0427 N for SatI, a modulus of 4-43 kPa, a million times softer than any
fibre a tether is made of.  This table holds typical room-temperature fibre
values from the manufacturers' data sheets (docs/tethers.md cites each), and
:func:`tether_parameters` turns a material and a diameter into the model's
per-tether numbers (SI): EA [N] (the field ``E1``/``E2``), a damping ``c`` [N s/m]
from the material's loss factor, the breaking load [N] and the mass per metre.

A braided line is weaker and softer than its fibre (braid angle, fill factor):
``knockdown`` (0.5-0.8 is common, docs/tethers.md) scales both E and the
strength.  The strength is the low end of each data sheet's range.
"""
from __future__ import annotations

import math
from collections import namedtuple

# name -> Material(tensile modulus E [Pa], tensile strength [Pa], density [kg/m^3], source)
Material = namedtuple("Material", "E strength density source")
GPA = 1e9
MATERIALS = {
    "kevlar49": Material(112 * GPA, 3.0 * GPA, 1440.0, "DuPont Kevlar technical guide"),
    "dyneema-sk75": Material(115 * GPA, 3.0 * GPA, 970.0,
                             "DSM Dyneema SK75 data sheet (E 100-130 GPa: the middle)"),
    "vectran-ht": Material(75 * GPA, 3.2 * GPA, 1410.0, "Kuraray Vectran HT data sheet"),
    "zylon-as": Material(180 * GPA, 5.8 * GPA, 1540.0, "Toyobo Zylon (PBO) technical information"),
    "zylon-hm": Material(270 * GPA, 5.8 * GPA, 1560.0, "Toyobo Zylon (PBO) technical information"),
}
# material damping of such lines: loss factor of order 0.01-0.05 (Cosmo & Lorenzini,
# Tethers in Space Handbook, 3rd ed., 1997); the low end, as the data sheets give none
LOSS_FACTOR = 0.01
# the largest failure strain (strength / E) of the table's fibres: no real line stretches
# further before it breaks (engine/start.py refuses a start of a stiff line beyond it)
MAX_FAILURE_STRAIN = max(m.strength / m.E for m in MATERIALS.values())
# EA [N] from which a tether is a real line, not a rubber band: 100 N is a modulus of
# 100 MPa on the thesis's 1 mm^2, ten times the stiffest rubber and 1/750 of the softest
# fibre of the table (a 0.1 mm Dyneema line has EA ~ 900 N; the thesis's tethers
# 0.004-0.06 N).  Such a line barely stretches, so a run starts at its equilibrium by
# default (tethersim.engine.start) and a start that strains it past MAX_FAILURE_STRAIN
# is refused.
REAL_TETHER_EA = 100.0
KNOCKDOWN_RANGE = (0.1, 1.0)
DIAMETER_RANGE = (1e-5, 0.1)  # m: a 10 µm filament to a 10 cm rope


def real_tethers(sat) -> tuple:
    """The tethers (1, 2) of ``sat`` whose EA is at least :data:`REAL_TETHER_EA`."""
    return tuple(j for j, ea in ((1, sat.E1), (2, sat.E2)) if ea >= REAL_TETHER_EA)


def material(name: str) -> Material:
    """The material called ``name`` (MATERIALS); one-line error naming the choices."""
    key = str(name).strip().lower()
    if key not in MATERIALS:
        raise ValueError(f"tether material {name!r}: allowed {', '.join(MATERIALS)}")
    return MATERIALS[key]


def tether_parameters(name: str, diameter: float, l0: float, mass: float,
                      knockdown: float = 1.0, loss_factor: float = LOSS_FACTOR) -> dict:
    """The model's numbers for one tether of material ``name`` and ``diameter``.

    Parameters
    ----------
    name : str
        A key of :data:`MATERIALS`.
    diameter : float
        Line diameter [m] (a solid round section, area π d²/4).
    l0 : float
        Rest length [m].
    mass : float
        The mass the tether's spring moves [kg] (the balloon against the boom: its
        reduced mass), for the damping.
    knockdown : float, optional
        Braid knock-down on E and strength (1: the fibre's values).
    loss_factor : float, optional
        Material loss factor η; the damping c = η √(k m) with k = EA / l0 dissipates
        per cycle of the tether's axial oscillation what η does (hysteretic damping
        at the axial frequency √(k/m)).

    Returns
    -------
    dict
        ``EA`` [N] (the model's E1/E2 field), ``c`` [N s/m], ``breaking_load`` [N],
        ``mass_per_length`` [kg/m] and ``axial_period`` [s] (2π √(m l0 / EA)).

    Examples
    --------
    >>> import tethersim as ts
    >>> t = ts.tether_parameters("kevlar49", diameter=1e-3, l0=6.0, mass=1.0)
    >>> round(t["EA"]), round(t["breaking_load"])
    (87965, 2356)
    >>> sat = ts.load_preset("satI").replace(E1=t["EA"], c1=t["c"], allow_implausible=True)
    """
    mat = material(name)
    for what, v, (lo, hi) in (("diameter", diameter, DIAMETER_RANGE),
                              ("knockdown", knockdown, KNOCKDOWN_RANGE)):
        if not (isinstance(v, (int, float)) and lo <= v <= hi):
            raise ValueError(f"tether {what} = {v!r}: allowed range {lo:g}..{hi:g}"
                             f"{' m' if what == 'diameter' else ''}")
    for what, v in (("l0", l0), ("mass", mass)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ValueError(f"tether {what} = {v!r}: must be a finite number > 0")
    if not (isinstance(loss_factor, (int, float)) and 0 <= loss_factor <= 1):
        raise ValueError(f"loss_factor = {loss_factor!r}: allowed range 0..1")
    area = math.pi * diameter ** 2 / 4
    ea = knockdown * mat.E * area
    k = ea / l0
    return {"EA": ea, "c": loss_factor * math.sqrt(k * mass),
            "breaking_load": knockdown * mat.strength * area,
            "mass_per_length": mat.density * area,
            "axial_period": 2 * math.pi * math.sqrt(mass / k)}


def with_tethers(sat, name: str, diameter: float, tethers=(1, 2), knockdown: float = 1.0,
                 loss_factor: float = LOSS_FACTOR):
    """``sat`` with tethers made of a real line: E_j, c_j and Fb_j of each tether j.

    The rest lengths stay the satellite's (set them first); the damping is taken at the
    axial frequency of the balloon's reduced mass against the boom on each line.

    Parameters
    ----------
    sat : tethersim.Satellite
        The satellite.
    name : str
        A key of :data:`MATERIALS`.
    diameter : float
        Line diameter [m].
    tethers : tuple of int, optional
        Which tethers (1, 2 or both).
    knockdown, loss_factor : float, optional
        As :func:`tether_parameters`.

    Returns
    -------
    tethersim.Satellite
        A copy with ``E1``/``E2`` = EA [N], ``c1``/``c2`` and ``Fb1``/``Fb2`` set.

    Examples
    --------
    >>> import tethersim as ts
    >>> sat = ts.with_tethers(ts.load_preset("satI"), "kevlar49", 1e-3)
    >>> round(sat.E1), round(sat.Fb2)
    (87965, 2356)
    """
    if not tethers or any(j not in (1, 2) for j in tethers):
        raise ValueError(f"tethers = {tethers!r}: allowed 1, 2 or both")
    boom = sat.m1 + sat.m2
    mass = sat.m3 * boom / (sat.m3 + boom)  # the balloon against the boom
    changes = {}
    for j in sorted(set(tethers)):
        t = tether_parameters(name, diameter, sat.l10 if j == 1 else sat.l20, mass,
                              knockdown, loss_factor)
        changes.update({f"E{j}": t["EA"], f"c{j}": t["c"], f"Fb{j}": t["breaking_load"]})
    return sat.replace(**changes)
