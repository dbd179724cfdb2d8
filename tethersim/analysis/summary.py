"""The summary of one run that ``tethersim run`` prints and writes (summary.json)."""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from tethersim.analysis.classify import UNDECIDED
from tethersim.analysis.metrics import min_run_orbits, steady_state_mean, wrap
from tethersim.analysis.outcome import Outcome, finite_prefix, outcome
from tethersim.analysis.tethers import loads_summary
from tethersim.engine.result import SimResult


def run_summary(res: SimResult, out: Outcome | None = None) -> dict:
    """Label, pitch metrics, largest tensions and forces (with their family), status.

    Parameters
    ----------
    res : SimResult
        The run.
    out : Outcome, optional
        Its outcome, if already computed.

    Returns
    -------
    dict
        Keys carry their units (``"settling time [h]"``); NaN means "never".

    Examples
    --------
    >>> import tethersim as ts
    >>> s = ts.run_summary(ts.simulate(ts.load_preset("satI"), periods=1, progress=False))
    >>> s["status"], s["largest torque on theta: family"] in ts.FAMILIES
    ('ok', True)
    """
    out = outcome(res, forces=False) if out is None else out
    m = out.metrics
    period = res.satellite.period
    n = max(1, finite_prefix(res))  # a diverged run: up to its last finite sample
    tension = res.tether_tensions()[:n].max(axis=0)
    lay = res.layout
    ix, iy, ith = (lay.state.index(s) for s in ("delta_x", "delta_y", "theta"))
    nan = float("nan")
    return {
        "label": res.label,
        "class": out.class_name,
        **({"run at least [orbits] to decide the class": min_run_orbits()}
           if out.stability_class == UNDECIDED else {}),
        "mean pitch [rad]": m.mean_pitch if m else nan,
        "steady-state pitch [rad]": m.steady_state_pitch if m else nan,
        "settling time [orbits]": m.settling_time / period if m else nan,
        "settling time [h]": m.settling_time / 3600 if m else nan,
        "largest tension tether 1 [N]": float(tension[0]),
        "largest tension tether 2 [N]": float(tension[1]),
        # peak, snap, safety factor and slack on the metrics grid (analysis/tethers.py)
        **loads_summary(res),
        **_largest_forces(res, n, (ix, iy, ith)),
        "tumbled": bool(m.tumbled) if m else None,
        "upside down": bool(m.upside_down) if m else None,
        "final delta_x [m]": float(res.x[n - 1]),
        "final delta_y [m]": float(res.y[n - 1]),
        "status": res.status,
        # where it started: the satellite's initial state, or its equilibrium (engine/start.py)
        "start": res.start,
        # the stopping limit that ended the run, and its located time (engine/events.py)
        **({"event": res.event, "event time [s]": res.event_time} if res.event else {}),
        **out_of_plane_summary(res),
        **orbit_summary(res, out),
        **implausible_summary(res.satellite, res.method),
    }


def out_of_plane_summary(res: SimResult) -> dict:
    """Roll φ, yaw ψ and the balloon's sideways δz of a 3-D run (empty for a planar model).

    Parameters
    ----------
    res : SimResult
        The run; its metrics grid (``fine_t``) when it has one, up to the last
        finite sample (a diverged run).

    Returns
    -------
    dict
        Largest |φ|, |ψ| [rad] and |δz| [m]; steady-state roll and yaw [rad]
        (mean over the steady-state window, as the steady-state pitch,
        docs/metrics.md); final roll, yaw [rad] and δz [m].
    """
    if res.layout.geometry != "3d":
        return {}
    if res.fine_t is not None:  # the metrics grid, as the pitch metrics (outcome.py)
        res = replace(res, t=res.fine_t, states=res.fine_states, fine_t=None, fine_states=None)
    n = max(1, finite_prefix(res))
    t = res.t[:n]
    phi, psi, dz = (res.series(k)[:n] for k in ("phi", "psi", "delta_z"))
    return {
        "largest |roll phi| [rad]": float(np.max(np.abs(phi))),
        "largest |yaw psi| [rad]": float(np.max(np.abs(psi))),
        "steady-state roll [rad]": float(wrap(steady_state_mean(t, phi))),
        "steady-state yaw [rad]": float(wrap(steady_state_mean(t, psi))),
        "final roll phi [rad]": float(phi[-1]),
        "final yaw psi [rad]": float(psi[-1]),
        "largest |delta_z| [m]": float(np.max(np.abs(dz))),
        "final delta_z [m]": float(dz[-1]),
    }


def orbit_summary(res: SimResult, out: Outcome) -> dict:
    """Orbit mode, the density the run used, drag make-up or re-entry time."""
    from tethersim.model.options import density_text

    sat = res.satellite
    d = {"orbit": f"{sat.orbit} (model {res.model})", "air density": density_text(sat)}
    if res.layout.orbit == "circular":
        d["drag make-up to hold the circular orbit [m/s/day]"] = out.drag_makeup
    else:
        rt = out.reentry_time
        d["re-entry time [h]"] = rt / 3600 if rt is not None else float("nan")
        d["final altitude [km]"] = float(res.altitude[-1] / 1e3)
        # which limit ended the run, and when: re-entry, the model's domain, or its length
        d["run ended at [h]"] = float(res.t[-1] / 3600)
        d["run ended by"] = (f"its length, {res.t[-1] / res.satellite.period:.4g} orbits, "
                             f"without re-entry" if res.status == "ok"
                             else res.message or res.status)
    return d


def implausible_summary(sat, method: str) -> dict:
    """The plausibility violations a run with ``method`` was allowed, if any."""
    from tethersim.model.plausibility import allowed_problems
    found = allowed_problems(sat, method)
    return {"implausible inputs (allowed)": "; ".join(found)} if found else {}


def _largest_forces(res, n: int, cols) -> dict:
    """The largest force family on δx, δy and θ; none for a bead chain (its forces are
    not split into the generated families: tethersim.model.beads)."""
    lay = res.layout
    if not lay.families:
        return {}
    peak = np.abs(res.forces[:n]).max(axis=0)[:, list(cols)]  # (family, δx δy θ)
    biggest = peak.argmax(axis=0)
    out = {}
    for k, (what, unit, name) in enumerate((("force", "N", "dx"), ("force", "N", "dy"),
                                            ("torque", "N m", "theta"))):
        out[f"largest {what} on {name} [{unit}]"] = float(peak[biggest[k], k])
        out[f"largest {what} on {name}: family"] = lay.families[biggest[k]]
    return out
