"""Short coupled runs for ``tethersim deorbit``: trail angle, tether loads, host rates.

At a few start altitudes the design runs its held circular orbit for a few orbits in the
model's uniform air at that altitude (the coupled attitude model, real lines with
``--tethers``), and each run gives

* the balloon's trail angle from the local vertical, atan2(δx, |δy|), mean over the last
  half (90 deg: level behind; 0: straight below or above), beside the closed form
  asin(min(ε, 1)) at the run's own mean distance (tethersim.analysis.deorbit);
* each tether's peak tension (tethersim.analysis.tethers);
* the host's attitude-rate envelope: max |θ̇| over the run and over its last fifth.

:func:`towed_line` is the configuration the closed form is the limit of: one line much
longer than the boom, collinear with it, nearly inextensible (docs/deorbit.md);
tests/experiments/test_deorbit_runs.py checks the closed form against its runs.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.analysis import deorbit as law
from tethersim.analysis.tethers import tether_loads
from tethersim.engine.simulate import simulate
from tethersim.engine.start import atol_floor
from tethersim.model.options import uniform_density

#: modulus x area [N] of the towed line: its stretch under the tide of a 1-kg balloon on
#: 100 m at 500 km (0.4 mN) is 0.02 %
TOWED_MODULUS = 2.0


def towed_line(sat, length: float, angle: float = 0.0):
    """``sat`` with its balloon on one line ``length`` [m] below the bus, along the boom.

    Tether 2 (bus) gets rest length ``length`` and tether 1 (tip-mass) ``length + a + b``,
    both :data:`TOWED_MODULUS`, so the two lie on one straight line through the boom; the
    start puts that line at ``angle`` [rad] from the local vertical towards the wake,
    the boom along it, at rest.
    """
    if not (math.isfinite(length) and length > 0):
        raise ValueError(f"length = {length!r} m: must be > 0")
    r = sat.a + length
    return sat.replace(l20=length, l10=length + sat.a + sat.b, E1=TOWED_MODULUS,
                       E2=TOWED_MODULUS,
                       initial=(r * math.sin(angle), -r * math.cos(angle), -angle, 0.0, 0.0, 0.0))


def run_at(sat, periods: float, model: str, method: str = "adaptive") -> dict:
    """One coupled run of ``sat``: its trail angle, loads and rates (SI, angles in rad).

    Real lines (tethersim.model.materials.real_tethers) run at atol 1e-10, their force's
    rounding level (engine/start.py), and rtol 1e-8; the thesis's tethers at 1e-12, 1e-10.
    """
    atol = max(1e-12, atol_floor(sat))
    res = simulate(sat, periods, method=method, model=model, progress=False, atol=atol,
                   rtol=1e-8 if atol > 1e-12 else 1e-10)
    n = res.t.size
    half, fifth = n // 2, max(1, n - n // 5)
    dx, dy = res.x[half:], res.y[half:]
    angle = float(np.mean(np.arctan2(dx, np.abs(dy))))
    length = float(np.mean(np.hypot(dx, dy)))
    rho = uniform_density(sat)
    loads = tether_loads(res)
    rate = np.abs(res.thetadot)
    return {"altitude": sat.altitude, "status": res.status, "trail_angle": angle,
            "closed_form_angle": law.trail_angle(sat, rho, length), "trail_length": length,
            "epsilon": law.differential_drag(sat, rho) / (3 * sat.omega ** 2 * sat.m3 * length),
            "peak_tension_1": loads[0].peak, "peak_tension_2": loads[1].peak,
            "max_rate": float(rate.max()), "settled_rate": float(rate[fifth - 1:].max())}


def coupled_runs(sat, altitudes, periods: float = 6.0, model: str = "objective-damper",
                 method: str = "adaptive", bar=None) -> list:
    """:func:`run_at` at each altitude [m] (``bar``: a tqdm bar advanced per run).

    The default model is the Kelvin-Voigt damper: the thesis damper pulls a balloon at
    rest across its line (docs/torque-balance.md), which tilts a hanging balloon by tens of
    degrees on a long line.
    """
    out = []
    for h in np.asarray(altitudes, float):
        out.append(run_at(sat.replace(altitude=float(h)), periods, model, method))
        if bar is not None:
            bar.update()
    return out
