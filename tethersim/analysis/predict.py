"""Stability classes predicted from the equilibrium and its linear modes, with no integration.

The simulated class of a run (tethersim.analysis.classify, docs/metrics.md) is predicted from
the equilibrium on the θ ≈ 0 branch and the eigenvalues of the generated Jacobian
there (tethersim.analysis.equilibrium).  The lead overlays these maps on simulated sweeps
(tethersim.experiments.sweep); tethersim.analysis.classify.agreement scores a prediction
against a sweep.

**Which equilibrium.** The balloon modes (≈ 0.08 rad/s) are about 20 times faster
than the pitch libration (≈ 0.004 rad/s), so for the pitch the balloon sits at its
own equilibrium for the current θ.  Call g(θ) [rad/s²] the pitch acceleration θ̈ with
the balloon at rest at that equilibrium and every rate zero: the quasi-static pitch
torque per unit inertia.  Starting from θ = 0, the boom turns in the direction of
g(0).  It stops at the first zero of g where g changes sign against the motion, a
statically stable equilibrium.  This is "the equilibrium on the θ ≈ 0 branch".  As E1
or E2 move away from the torque balance (docs/torque-balance.md), this branch goes
continuously from θ = 0 to ±π/2 (a boom trailing the wake, the thesis's Fig 5.5).
The branch is found by walking θ in steps of ``WALK_STEP`` from 0.  The step where g
changes sign is then refined: ``WALK_SUBSTEPS`` sub-steps, Brent's method on g, and
tethersim.analysis.equilibrium.find_equilibrium for the full 3-state root and the eigenvalues.
A plain root find from θ = 0 is not used.  Near the band it often lands on the
unstable θ = ±π/2 roots (SatI with E1 × 1.2 or × 0.25, for instance).  Continuation
over a sweep grid cannot follow the branch either: one grid step of 2–12 % in a
modulus moves θ_eq by up to ~1 rad.

**Classes predicted** (codes of tethersim.analysis.classify, tested in this order, like the
simulated classifier):

  5 failed       nothing predicted: no balloon equilibrium on the walk (e.g.
                 E1 = E2 = 0, where nothing holds the balloon against drag)
  4 tumbling     no pitch equilibrium (g keeps one sign over a whole turn, so the
                 boom is driven round), or the branch equilibrium is linearly
                 unstable (max Re λ > ``MARGINAL_RATE``).  Such a libration grows
                 with no rest state in its well.  This module predicts "tumbling"
                 for it, although the run may end as "offset" or "upside_down"
                 instead.
  3 upside_down  |θ_eq| > 3π/4 (the definition of tethersim.analysis.metrics)
  4 tumbling     (``swing=True``, the default) the first swing from θ0 at rest
                 reaches ±π.  The swing is conservative: kinetic energy ∫ g dθ
                 from θ0, pitch damping left out.  For SatI this is how E1 × 0.9
                 and E2 × 1.1 tumble on their way to θ_eq ≈ −1.5 and −1.1 rad
                 (simulated: tumbling).  Not a linear result; ``swing=False``
                 leaves it out.
  2 offset       |θ_eq| > tol = 0.05 rad (thesis p. 5-18)
  1 unsettled    the predicted settling time from θ0 = sat.initial[2] exceeds the
                 limit, min(3 days, (1 − SS_FRACTION) × run length).  Why not the
                 whole run length: tethersim.analysis.metrics counts a run as settled only if
                 its whole last fifth stays in the band.  A marginal equilibrium
                 (max Re λ within ±MARGINAL_RATE) never settles.
  0 stable       otherwise
  6 undecided    a run shorter than metrics.min_run_orbits (no simulated class either)

The predicted settling time is Equilibrium.predicted_settling_time (ln(A/tol) over the
slowest decay rate, amplitude A = |θ0 − θ_eq|).  It ignores the first nonlinear swings
(within ~10 % of the simulated time for SatI; tests/analysis/test_equilibrium.py).

**Checked against simulation.** SatI's 41 × 41 grid (E1 0–0.02, E2 0–0.06 N/mm²) was
run as 50-orbit DOP853 runs (simulate defaults) and classified.  Of 1680 points, 90.4 %
get the same class (76.0 % with swing=False) and 100 % the same stable / not-stable
verdict.  The five stable points match.  Of the 1271 points that are offset both ways,
1257 have θ_eq within 0.05 rad of the run's steady pitch (median 8e-5 rad).  The other
14 end in the mirror well, π − θ_eq: their first swing crosses the π/2 barrier.  The
misses:

- 160 runs predicted offset (θ_eq ≈ π/2, quasi-static swing turning at ≈ 2.62 rad)
  tumble.  Their trails are long (δx ≈ 56–1100 m) against the initial δx0 = 29 m.  The
  balloon's start-up transient feeds the swing, and the quasi-static picture leaves that
  out.
- 2 runs predicted tumbling end upside down.

**Limits.** The prediction is linear about the branch equilibrium, plus the one energy
test above.  It does not follow a swing that crosses into another well without reaching
±π (the class is still that of the θ ≈ 0 branch), nor energy that the balloon's own
motion feeds in or takes out (see above).

Two roots closer than WALK_STEP / WALK_SUBSTEPS (0.3°) merge; a stable–unstable pair inside
one 5° step, with no sign change, is stepped over.  Densities are at the orbit altitude.

Units: SI inside; map coordinates in the edge units of tethersim.model.params.
"""
from __future__ import annotations

import math

import numpy as np
import xarray as xr
from scipy.optimize import brentq
from tqdm.auto import tqdm

from tethersim.analysis.classify import (
    FAILED,
    OFFSET,
    SETTLING_REQUIREMENT,
    STABLE,
    TUMBLING,
    UNDECIDED,
    UNSETTLED,
    UPSIDE_DOWN,
    flag_attrs,
)
from tethersim.analysis.equilibrium import find_equilibrium
from tethersim.analysis.metrics import SETTLING_TOL, SS_FRACTION, long_enough, min_run_orbits
from tethersim.analysis.torque_balance import PitchTorque
from tethersim.model import params
from tethersim.model.registry import DEFAULT_MODEL, THESIS_VARIANTS, model_index
from tethersim.model.satellite import Satellite, SatelliteError

WALK_STEP = math.radians(5.0)  # rad, step of the walk along θ from 0
WALK_SUBSTEPS = 16  # sub-steps of the step where g changes sign
MARGINAL_RATE = 1e-10  # 1/s: |max Re λ| below this is marginal (an e-fold in ~300 years)
UPSIDE_DOWN_PITCH = 3 * math.pi / 4  # rad, as tethersim.analysis.metrics


def _branch(torque: PitchTorque):
    """The stable zero of g reached by walking θ from 0 along g(0) (module docstring).

    Returns (kind, θ [rad], (δx, δy) there [m], (δx, δy) at θ = 0 [m] or None) with
    kind "root"; "none" if g keeps its sign over a whole turn; "fail" where the
    balloon has no equilibrium (θ then says where).
    """
    g0 = torque(0.0)
    if math.isnan(g0):
        return "fail", 0.0, None, None
    trail0 = (float(torque.trail[0]), float(torque.trail[1]))
    s = 1.0 if g0 >= 0.0 else -1.0
    lo, trail_lo = 0.0, torque.trail.copy()
    for k in range(1, round(2 * math.pi / WALK_STEP) + 1):
        hi = s * k * WALK_STEP
        ghi = torque(hi)
        if math.isnan(ghi):
            return "fail", hi, None, trail0
        if s * ghi <= 0.0:
            break
        lo, trail_lo = hi, torque.trail.copy()
    else:
        return "none", None, None, trail0
    # the first sign change inside the step [lo, hi]
    torque.trail[:] = trail_lo
    for j in range(1, WALK_SUBSTEPS + 1):
        t = lo + (hi - lo) * j / WALK_SUBSTEPS
        gt = torque(t)
        if math.isnan(gt):
            return "fail", t, None, trail0
        if s * gt <= 0.0:
            hi, ghi = t, gt
            break
        lo, trail_lo = t, torque.trail.copy()
    torque.trail[:] = trail_lo
    try:
        theta = hi if ghi == 0.0 else brentq(torque, min(lo, hi), max(lo, hi), xtol=1e-14,
                                             rtol=4 * np.finfo(float).eps)
    except ValueError:  # g turned NaN, or changed branch, inside the bracket
        return "fail", hi, None, trail0
    at = torque.balloon(theta)
    return ("root" if at is not None else "fail"), theta, at, trail0


def _swing(torque: PitchTorque, theta0: float, trail0):
    """Far turning point [rad] of the first swing from θ0 at rest, or NaN.

    Conservative and quasi-static: the kinetic energy per unit inertia is
    K(θ) = ∫_{θ0}^{θ} g dφ (trapezoids of WALK_STEP), and the swing runs in the
    direction of g(θ0) until K falls to 0.  Returns ±π if it reaches ±π first
    (the boom goes over the top: "tumbled" in tethersim.analysis.metrics).  The pitch damping
    is light (damping ratio ~0.004 for the presets) and is left out.
    """
    torque.trail[:] = trail0
    g_prev = torque(theta0)
    if math.isnan(g_prev):
        return math.nan
    if g_prev == 0.0:
        return theta0
    s = 1.0 if g_prev > 0.0 else -1.0
    th, K = theta0, 0.0
    while True:
        nxt = th + s * WALK_STEP
        if abs(nxt) >= math.pi:
            nxt = s * math.pi
        g = torque(nxt)
        if math.isnan(g):
            return math.nan
        dK = 0.5 * (g_prev + g) * (nxt - th)
        if K + dK <= 0.0:
            # K is quadratic in θ on the step: K + g_prev u + (g − g_prev) u²/(2h) = 0
            h = nxt - th
            qa, qb, qc = 0.5 * (g - g_prev) / h, g_prev, K
            if qa == 0.0:
                u = -qc / qb
            else:
                disc = max(qb * qb - 4 * qa * qc, 0.0)
                roots = [(-qb + r) / (2 * qa) for r in (math.sqrt(disc), -math.sqrt(disc))]
                u = min((r for r in roots if r * s > 0), key=abs, default=h)
            return th + u
        K += dK
        if abs(nxt) >= math.pi:
            return nxt
        th, g_prev = nxt, g


def _settling_limit(sat: Satellite, periods: float) -> float:
    """min(3 days, (1 − SS_FRACTION) × run length) [s] (module docstring)."""
    return min(SETTLING_REQUIREMENT, (1.0 - SS_FRACTION) * periods * sat.period)


def _predict(sat: Satellite, model: str, periods: float, trail=None, swing: bool = True):
    """(code, info, balloon trail at θ = 0 or None) of one satellite (a run too short
    for a class, metrics.long_enough, has no predicted class either: undecided)."""
    code, info, trail0 = _predict_class(sat, model, periods, trail, swing)
    if code != FAILED and not long_enough(periods):
        info["reason"] = f"too short to decide (>= {min_run_orbits():.4g} orbits); " \
                         f"longer: {info['reason']}"
        return UNDECIDED, info, trail0
    return code, info, trail0


def _predict_class(sat: Satellite, model: str, periods: float, trail=None, swing: bool = True):
    info = {"theta_eq": math.nan, "delta_x": math.nan, "delta_y": math.nan,
            "max_real_eigenvalue": math.nan, "predicted_settling_time": math.nan,
            "settling_limit": _settling_limit(sat, periods), "taut": (False, False),
            "theta_turn": math.nan, "equilibrium": None, "reason": ""}
    torque = PitchTorque(sat, model, trail)
    kind, theta, at, trail0 = _branch(torque)
    if kind == "fail":
        info["reason"] = (f"no balloon equilibrium at theta = {theta:.4g} rad: nothing holds "
                          f"the balloon against drag (no prediction)")
        return FAILED, info, trail0
    if kind == "none":
        info["reason"] = "no pitch equilibrium: the quasi-static pitch torque keeps one sign"
        info["predicted_settling_time"] = math.inf
        return TUMBLING, info, trail0
    try:
        eq = find_equilibrium(sat, model, guess=(at[0], at[1], theta))
    except RuntimeError as exc:
        info["reason"] = f"equilibrium not refined: {exc}"
        return FAILED, info, trail0
    max_re = float(np.max(eq.eigenvalues.real))
    settle = (math.inf if max_re > -MARGINAL_RATE
              else float(eq.predicted_settling_time(sat.initial[2] - eq.theta)))
    info.update(theta_eq=eq.theta, delta_x=eq.delta_x, delta_y=eq.delta_y,
                max_real_eigenvalue=max_re, predicted_settling_time=settle, taut=eq.taut,
                equilibrium=eq)
    if max_re > MARGINAL_RATE:
        info["reason"] = "the branch equilibrium is linearly unstable (max Re λ > 0)"
        return TUMBLING, info, trail0
    if abs(eq.theta) > UPSIDE_DOWN_PITCH:
        info["reason"] = "|theta_eq| > 3 pi/4"
        return UPSIDE_DOWN, info, trail0
    if swing:
        info["theta_turn"] = turn = _swing(torque, sat.initial[2], trail0)
        if abs(turn) >= math.pi:
            info["reason"] = "the first swing from theta0 reaches +-pi (quasi-static energy)"
            return TUMBLING, info, trail0
    if abs(eq.theta) > SETTLING_TOL:
        info["reason"] = f"|theta_eq| > {SETTLING_TOL} rad"
        return OFFSET, info, trail0
    if settle > info["settling_limit"]:
        info["reason"] = "predicted settling time beyond min(3 days, settling window of the run)"
        return UNSETTLED, info, trail0
    info["reason"] = "settles within the limit"
    return STABLE, info, trail0


def predicted_class(sat: Satellite, model: str = DEFAULT_MODEL, periods: float = 50.0,
                    swing: bool = True):
    """Stability class predicted from the θ ≈ 0 branch equilibrium (module docstring).

    Parameters: sat (SI), model (tethersim.MODELS), periods: run length in orbits
    (the settling limit is min(3 days, (1 − SS_FRACTION) × periods × period)),
    swing: also predict "tumbling" when the first swing from θ0 reaches ±π.

    Returns (code, info): code from tethersim.analysis.classify.CLASSES; info has theta_eq
    [rad], delta_x, delta_y [m], max_real_eigenvalue [1/s], predicted_settling_time
    [s] (inf if it never settles, NaN if not computed), settling_limit [s],
    theta_turn [rad] (far turning point of the first swing from θ0, ±π if it goes
    over the top, NaN if not computed), taut (tether 1, tether 2), equilibrium
    (tethersim.analysis.equilibrium.Equilibrium or None) and reason (text).
    """
    if not (isinstance(periods, (int, float)) and math.isfinite(periods) and periods > 0):
        raise ValueError(f"periods = {periods!r}: must be a finite number > 0")
    code, info, _ = _predict(sat, model, float(periods), swing=bool(swing))
    return code, info


def predicted_map(sat: Satellite, name_x: str, values_x, name_y: str, values_y,
                  model: str = DEFAULT_MODEL, periods: float = 50.0, swing: bool = True,
                  progress: bool | None = None) -> xr.Dataset:
    """Predicted classes on a grid of two parameters (edge units, tethersim.model.params).

    values_x, values_y: grid values in edge units (E1, E2 in N/mm², altitude in km,
    else SI).  Every point is ``params.with_values(sat, {name_x: x, name_y: y})``
    and must be a valid satellite (raises SatelliteError naming the point).
    The points are visited row by row, in a serpentine order.  The balloon trail at
    θ = 0 of each point seeds the next one's Newton solve.  The θ ≈ 0 branch itself
    is followed along θ at every point (module docstring), one thread: a 41 × 41 grid
    takes seconds.
    model, periods, swing: as predicted_class.
    progress: None shows a bar (tqdm) only if the map takes more than a second; True
    always; False never.

    Returns an xarray Dataset on dims (name_y, name_x) with coordinates in edge
    units and the variables predicted_class (int8, CF flags of tethersim.analysis.classify),
    theta_eq [rad], max_real_eigenvalue [1/s], predicted_settling_time [s] and
    theta_turn [rad].
    """
    params.check_name(name_x)
    params.check_name(name_y)
    if name_x == name_y:
        raise ValueError(f"the two axes must differ, both are {name_x!r}")
    if not (isinstance(periods, (int, float)) and math.isfinite(periods) and periods > 0):
        raise ValueError(f"periods = {periods!r}: must be a finite number > 0")
    model_index(model, THESIS_VARIANTS, "the stability prediction")
    xs = np.asarray(values_x, dtype=float).ravel()
    ys = np.asarray(values_y, dtype=float).ravel()
    for name, v in ((name_x, xs), (name_y, ys)):
        if v.size == 0 or not np.all(np.isfinite(v)):
            raise ValueError(f"axis {name}: needs one or more finite values")
    shape = (ys.size, xs.size)
    code = np.full(shape, FAILED, dtype=np.int8)
    out = {k: np.full(shape, np.nan) for k in
           ("theta_eq", "max_real_eigenvalue", "predicted_settling_time", "theta_turn")}
    trail = None
    with tqdm(total=code.size, desc=f"predicted {sat.name}", unit="point", leave=False,
              delay=0.0 if progress else 1.0, disable=(progress is False)) as bar:
        for i, yv in enumerate(ys):
            cols = range(xs.size) if i % 2 == 0 else range(xs.size - 1, -1, -1)
            for j in cols:
                try:
                    s = params.with_values(sat, {name_x: xs[j], name_y: yv})
                except SatelliteError as exc:
                    raise SatelliteError(
                        f"grid point {name_x} = {xs[j]:g} {params.unit(name_x)}, {name_y} = "
                        f"{yv:g} {params.unit(name_y)} is not a valid satellite: {exc}") from None
                c, info, t0 = _predict(s, model, float(periods), trail, bool(swing))
                if t0 is not None:
                    trail = t0
                code[i, j] = c
                for k, arr in out.items():
                    arr[i, j] = info[k]
                bar.update()

    def coord(name, v):
        return (name, v, {"units": params.unit(name), "long_name": f"{name} (edge units)"})

    cls_attrs = flag_attrs()
    cls_attrs["long_name"] = "predicted stability class (tethersim.analysis.predict)"
    data = {
        "predicted_class": ((name_y, name_x), code, cls_attrs),
        "theta_eq": ((name_y, name_x), out["theta_eq"],
                     {"units": "rad", "long_name": "pitch at the theta ~ 0 branch equilibrium"}),
        "max_real_eigenvalue": ((name_y, name_x), out["max_real_eigenvalue"],
                                {"units": "1/s", "long_name": "largest real part of the "
                                 "Jacobian's eigenvalues there"}),
        "predicted_settling_time": ((name_y, name_x), out["predicted_settling_time"],
                                    {"units": "s", "long_name": "linear settling time from "
                                     f"theta0 to +-{SETTLING_TOL} rad (inf: never)"}),
        "theta_turn": ((name_y, name_x), out["theta_turn"],
                       {"units": "rad", "long_name": "far turning point of the first swing "
                        "from theta0 (+-pi: over the top)"}),
    }
    attrs = {"title": f"tethersim predicted classes of {sat.name} over {name_x} x {name_y}",
             "model": model, "periods": float(periods), "swing": int(bool(swing)),
             "settling_limit_s": _settling_limit(sat, float(periods)),
             "method": "theta ~ 0 branch equilibrium and its linear modes (tethersim.analysis.predict)",
             "conventions": "docs/conventions.md; classes: docs/metrics.md"}
    return xr.Dataset(data, coords={name_x: coord(name_x, xs), name_y: coord(name_y, ys)},
                      attrs=attrs)


__all__ = ["predicted_class", "predicted_map"]
