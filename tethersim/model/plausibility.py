"""Physical plausibility of a satellite: the ranges where the model means something.

A :class:`~tethersim.model.satellite.Satellite` that passes its hard checks (positive
masses, an altitude inside the atmosphere table, ...) can still be absurd: an
orbit below the re-entry altitude, a balloon starting a million kilometres from
6 m tethers, a tether so stiff that its oscillation is faster than the
integrator can follow.  Such runs used to end "ok" with meaningless numbers.

The per-quantity ranges live in one table, :data:`tethersim.model.params.PARAMETERS`;
the rules that need several quantities at once are here.  :func:`problems`
lists every violation as a one-line message naming the field, the plausible
range and why; :func:`check` refuses the first one unless the satellite was
made with ``allow_implausible=True`` (preset ``[model] allow_implausible =
true``, CLI ``--allow-implausible``), in which case the run's summary lists them.
"""
from __future__ import annotations

import math

# Generous factors, documented in docs and messages: the thesis presets sit far inside.
REACH_FACTOR = 10.0  # balloon start <= this x the longest tether-plus-boom reach
BOOM_FACTOR = 10.0  # l10 + l20 >= (a + b) / this: tethers spanning the boom
T_TETHER_MIN = 0.1  # s, shortest tether oscillation period the explicit schemes resolve
# (DOP853 is capped at 1e6 steps per orbit, ~5 ms at 200 km: 20 steps per 0.1 s period)
# s, shortest damper time m3_eff / c: an overdamped decay need not be resolved, only
# integrated stably, which DOP853 does while step x c / m3_eff < ~5: 1 ms at ~5 ms steps,
# with a tenfold margin
T_DAMPER_MIN = 0.01
# starting rates: |theta_dot|, |phi_dot|, |psi_dot| <= RATE_FACTOR x the orbit rate: 100 turns
# per orbit is the Nyquist rate of the 200-per-orbit metrics grid (faster, the samples alias
# the rotation: a yaw rate of 1000 rad/s gave a summary of an aliased yaw), and ~58x the
# fastest librating pitch rate sqrt(3) x orbit rate (the separatrix of theta'' = -3 n^2 sin
# theta cos theta).  The balloon's starting speed (delta_x_dot, ...) <= that rate times the
# farthest plausible start (REACH_FACTOR x reach): ~20 m/s for the presets.
RATE_FACTOR = 100.0
# the balloon's ballistic coefficient A3/m3 <= this [m^2/kg]: the thinnest balloon films
# (with seams) weigh ~10 g/m^2, so even a single sheet facing the flow has A/m <= 100 m^2/kg
# (an inflated sphere, 4x its frontal area of film, <= 25); the presets' balloons have 12
MAX_AREA_PER_MASS = 100.0
HINT = "--allow-implausible (preset: [model] allow_implausible = true) runs it anyway"


def _unit(p) -> str:
    return "" if p.unit == "1" else f" {p.unit}"  # no unit after a pure number (CD)


def _range_text(p) -> str:
    if p.zero_ok and p.low > 0:
        return f"0 or {p.low:g}..{p.high:g}{_unit(p)}"
    return f"{p.low:g}..{p.high:g}{_unit(p)}"


def _table_problems(sat) -> list:
    from .params import PARAMETERS  # params imports satellite: import at call time

    out = []
    for name, p in PARAMETERS.items():
        if getattr(sat, name) is None:  # an unset index (MSIS reads the table)
            continue
        v = getattr(sat, name) / p.factor
        if (p.zero_ok and v == 0) or p.low <= v <= p.high:
            continue
        out.append(f"{name} = {v:g}{_unit(p)}: plausible range {_range_text(p)} "
                   f"({p.meaning}: {p.why})")
    return out


def _balloon_mass(sat) -> float:
    """Reduced mass of the balloon against the boom [kg]: what a tether spring moves."""
    boom = sat.m1 + sat.m2
    return sat.m3 * boom / (sat.m3 + boom)


def _cross_problems(sat) -> list:
    out = []
    dx, dy, dz = sat.initial[0], sat.initial[1], sat.initial_3d.get("delta_z", 0.0)
    reach = max(sat.l10 + sat.b, sat.l20 + sat.a)
    r, limit = math.hypot(dx, dy, dz), REACH_FACTOR * reach
    if r > limit:
        names, values = ("delta_x, delta_y", f"{dx:g}, {dy:g}") if dz == 0 else (
            "delta_x, delta_y, delta_z", f"{dx:g}, {dy:g}, {dz:g}")
        out.append(f"{names} = ({values}) m: the balloon starts {r:.4g} m from "
                   f"the COM; plausible range <= {limit:.4g} m ({REACH_FACTOR:g} x max(l10 + b, "
                   f"l20 + a): far beyond any trail the tethers hold)")
    out += _rate_problems(sat, limit)
    if sat.A3 / sat.m3 > MAX_AREA_PER_MASS:
        out.append(f"A3 / m3 = {sat.A3 / sat.m3:.4g} m^2/kg: plausible range <= "
                   f"{MAX_AREA_PER_MASS:g} m^2/kg (the balloon's area per mass: the thinnest "
                   f"balloon films weigh ~10 g/m^2)")
    span = (sat.a + sat.b) / BOOM_FACTOR
    if sat.l10 + sat.l20 < span:
        out.append(f"l10 + l20 = {sat.l10 + sat.l20:g} m: plausible range >= {span:.4g} m "
                   f"((a + b) / {BOOM_FACTOR:g}: shorter tethers would always be stretched "
                   f"over {BOOM_FACTOR:g}x across the boom)")
    return out


def stiffness_problems(sat) -> list:
    """Tethers and dampers faster than the explicit schemes resolve, one line each.

    Not a property of the satellite: a real fibre tether (docs/tethers.md) oscillates
    axially in a fraction of a second, which the implicit scheme (``method="implicit"``)
    integrates and RK4 and DOP853 cannot; simulate() refuses such a satellite for the
    explicit schemes unless it allows implausible input (engine/simulate.py).

    Parameters
    ----------
    sat : tethersim.model.satellite.Satellite
        A satellite that passed its hard checks.

    Returns
    -------
    list of str
        Messages naming the field, the largest value the explicit schemes resolve and
        the tether's period or damper time; empty if none.
    """
    out = []
    from .params import PARAMETERS
    per_edge = PARAMETERS["E1"].factor  # N per N/mm^2 (1: the 1 mm^2 cross-section)
    m = _balloon_mass(sat)
    stiff = stiff_tethers(sat)
    for E, c, l0, i in ((sat.E1, sat.c1, sat.l10, 1), (sat.E2, sat.c2, sat.l20, 2)):
        e_max = _stiff_modulus(sat, l0)
        if i in stiff:
            period = 2 * math.pi * math.sqrt(m * l0 / E)
            out.append(f"E{i} = {E / per_edge:g} N/mm^2: tether {i} would oscillate with period "
                       f"{period:.3g} s, under the {T_TETHER_MIN:g} s the explicit schemes "
                       f"resolve (E{i} <= {e_max / per_edge:.4g} N/mm^2 for m3 and l{i}0)")
        c_max = m / T_DAMPER_MIN
        if c > c_max:
            out.append(f"c{i} = {c:g} N s/m: damper time m3/c{i} = {m / c:.3g} s, under the "
                       f"{T_DAMPER_MIN:g} s the explicit schemes resolve (c{i} <= {c_max:.4g} "
                       f"N s/m for m3)")
    return out


def _stiff_modulus(sat, l0: float) -> float:
    """The modulus x 1 mm^2 [N] above which a tether of rest length l0 is stiff: spring
    k = E / l0 (E a force), axial period 2 pi sqrt(m l0 / E) under T_TETHER_MIN."""
    return _balloon_mass(sat) * l0 * (2 * math.pi / T_TETHER_MIN) ** 2


def stiff_tethers(sat) -> tuple:
    """The tethers (1, 2) whose axial period is under ``T_TETHER_MIN``: real lines.

    What the explicit schemes cannot resolve (:func:`stiffness_problems`): a
    fibre line (docs/tethers.md) oscillates axially in a fraction of a second,
    the thesis's tethers in about a minute.
    """
    return tuple(i for E, l0, i in ((sat.E1, sat.l10, 1), (sat.E2, sat.l20, 2))
                 if E > _stiff_modulus(sat, l0))


def _rate_problems(sat, reach_limit: float) -> list:
    """Starting rates beyond RATE_FACTOR x the orbit rate, and starting balloon speeds
    beyond that rate times the farthest plausible start ``reach_limit`` [m]."""
    w_max = RATE_FACTOR * sat.omega
    v_max = w_max * reach_limit
    rates = {"theta_dot": sat.initial[5], "phi_dot": sat.initial_3d.get("phi_dot", 0.0),
             "psi_dot": sat.initial_3d.get("psi_dot", 0.0)}
    out = [f"{k} = {v:g} rad/s: plausible range |{k}| <= {w_max:.4g} rad/s ({RATE_FACTOR:g} x "
           f"the orbit rate: faster turns alias on the 200-per-orbit output)"
           for k, v in rates.items() if abs(v) > w_max]
    speeds = (sat.initial[3], sat.initial[4], sat.initial_3d.get("delta_z_dot", 0.0))
    v = math.hypot(*speeds)
    if v > v_max:
        out.append(f"delta_x_dot, delta_y_dot, delta_z_dot = ({', '.join(f'{x:g}' for x in speeds)})"
                   f" m/s: the balloon starts at {v:.4g} m/s; plausible range <= {v_max:.4g} m/s "
                   f"({RATE_FACTOR:g} x the orbit rate x the farthest plausible start)")
    return out


def problems(sat, method: str = "implicit") -> list:
    """Every plausibility violation of ``sat``, one line each.

    Parameters
    ----------
    sat : tethersim.model.satellite.Satellite
        A satellite that passed its hard checks.
    method : str, optional
        The scheme of a run: an explicit one (``"adaptive"``, ``"rk4"``) adds
        :func:`stiffness_problems` (what it cannot resolve); the default, the implicit
        scheme, resolves every tether, so a real fibre line is plausible.

    Returns
    -------
    list of str
        Messages naming the field (SI field names, edge units: E in N/mm^2,
        altitude in km), the plausible range and why; empty if plausible.
    """
    return (_table_problems(sat) + _cross_problems(sat)
            + (stiffness_problems(sat) if method != "implicit" else []))


def allowed_problems(sat, method: str) -> list:
    """The violations a run of ``sat`` with ``method`` was allowed (``allow_implausible``),
    for its summary and files; empty when it does not allow any."""
    return problems(sat, method) if getattr(sat, "allow_implausible", False) else []


def check(sat, where: str = "") -> None:
    """Refuse an implausible satellite unless it allows it.

    Parameters
    ----------
    sat : tethersim.model.satellite.Satellite
        The satellite being created.
    where : str
        Prefix naming the source (a preset path), e.g. ``"satI.toml: "``.

    Raises
    ------
    tethersim.model.satellite.SatelliteError
        Naming the first violation, its range and ``allow_implausible``.
    """
    if getattr(sat, "allow_implausible", False):
        return
    # stiff tethers are refused by the scheme that cannot integrate them (simulate), not here
    found = problems(sat)
    if found:
        from .satellite import SatelliteError
        raise SatelliteError(f"{where}{found[0]}; {HINT}")
