"""Runs of the generated free-orbit kernels with scipy's DOP853 (docs/orbit.md's checks).

What the measured figures of figures_orbit.py and the physics tests of the kernels
(tests/derive/test_orbit_physics.py, tests/derive/test_free3d_kernels.py) share:
SatI's inputs, a state and a parameter vector filled by name, DOP853 at rtol 1e-12,
and the system COM's inertial position, velocity and osculating semi-major axis.
Everything goes by the module's ``STATE`` and ``PARAMETERS`` names, so the planar
free models (10 states) and the 3-D ones (16 states) use the same code.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from tethersim.model.constants import MU_EARTH
from tethersim.model.inputs import model_values
from tethersim.model.presets import load_preset

#: SatI's inputs (tethersim/model/presets/satI.toml, thesis Eq 4.4 boxes, WGS-84 μ and
#: R_E, Vallado Table D-3), with air and J2 off: a check switches on what it tests
SATI = {**model_values(load_preset("satI")), "rho1": 0.0, "rho2": 0.0, "rho3": 0.0, "J2": 0.0}


def params(module, **changes) -> np.ndarray:
    """The module's parameter vector (its ``PARAMETERS`` order) from :data:`SATI` with ``changes``."""
    values = dict(SATI, **changes)
    return np.array([values[n] for n in module.PARAMETERS], dtype=np.float64)


def dumbbell(**changes) -> dict:
    """Tethers cut, air off, balloon riding at the boom COM: a rigid dumbbell (K = 1)."""
    return dict(dict(E1=0.0, E2=0.0, c1=0.0, c2=0.0), **changes)


def state(module, **values) -> np.ndarray:
    """The module's state vector (its ``STATE`` order): ``values`` by name, the rest 0."""
    y = np.zeros(len(module.STATE))
    for name, v in values.items():
        y[module.STATE.index(name)] = v
    return y


def ballistic() -> float:
    """Σ C_D A_i / Σ m_i of SatI [m²/kg], the coefficient of the decay law."""
    s = SATI
    return s["CD"] * (s["A1"] + s["A2"] + s["A3"]) / (s["m1"] + s["m2"] + s["m3"])


def _atol_scale(module) -> np.ndarray:
    # r ~ 1e7 m, ṙ ~ 1 m/s, the other positions ~ 1 and their rates ~ 1e-3 per second
    return np.array([1e7 if n == "r" else 1.0 if n == "r_dot" or not n.endswith("_dot")
                     else 1e-3 for n in module.STATE])


def integrate(module, p, y0, t_end, extra=None, **kw):
    """DOP853 of the generated ``rhs`` at rtol 1e-12 from t = 0 to ``t_end``.

    Parameters
    ----------
    module : module
        A generated free-orbit kernel module (``tethersim.generated.free`` ...).
    p, y0 : numpy.ndarray
        Parameter vector and initial state.
    t_end : float
        End time [s].
    extra : callable, optional
        ``extra(y) -> list``: integrands appended to the state (quadratures, from 0).
    **kw
        Passed to :func:`scipy.integrate.solve_ivp` (``t_eval``, ``events``, ``dense_output``).

    Returns
    -------
    scipy.integrate OdeResult
        The solution; the quadratures are its rows after the state's.
    """
    n = len(module.STATE)
    n_extra = 0 if extra is None else len(extra(y0))

    def f(t, z):
        d = np.empty(n)
        module.rhs(t, z[:n], p, d)
        return d if extra is None else np.concatenate([d, extra(z[:n])])

    z0 = np.concatenate([y0, np.zeros(n_extra)])
    atol = np.concatenate([1e-12 * _atol_scale(module), np.full(n_extra, 1e-6)])
    sol = solve_ivp(f, (0.0, t_end), z0, method="DOP853", rtol=1e-12, atol=atol, **kw)
    if not sol.success:
        raise RuntimeError(f"{module.MODEL}: DOP853 failed: {sol.message}")
    return sol


def inertial_com(module, p, y) -> tuple:
    """(|R|, |V|, radial speed) of the system COM from the state (positions 3.10-3.12).

    The reference point G = r L.y, the tip-mass and bus at G + b ê and G − a ê with the
    boom axis ê = (cos φ sin θ, cos φ cos θ, sin φ) in L (φ = 0 in the plane), the
    balloon at G + δ; velocities in L plus ν̇ ẑ × r (Eq 3.13).
    """
    P = dict(zip(module.PARAMETERS, p))
    s = dict(dict.fromkeys(("delta_z", "phi", "delta_z_dot", "phi_dot"), 0.0),
             **dict(zip(module.STATE, y)))
    cf, sf = math.cos(s["phi"]), math.sin(s["phi"])
    ct, st = math.cos(s["theta"]), math.sin(s["theta"])
    fd, td = s["phi_dot"], s["theta_dot"]
    e = np.array([cf * st, cf * ct, sf])
    e_dot = np.array([-sf * st * fd + cf * ct * td, -sf * ct * fd - cf * st * td, cf * fd])
    g, g_dot = np.array([0.0, s["r"], 0.0]), np.array([0.0, s["r_dot"], 0.0])
    delta = np.array([s["delta_x"], s["delta_y"], s["delta_z"]])
    delta_dot = np.array([s["delta_x_dot"], s["delta_y_dot"], s["delta_z_dot"]])
    pos = np.array([g + P["b"] * e, g - P["a"] * e, g + delta])
    vel = np.array([g_dot + P["b"] * e_dot, g_dot - P["a"] * e_dot, g_dot + delta_dot])
    vel += s["nu_dot"] * np.column_stack([-pos[:, 1], pos[:, 0], np.zeros(3)])
    m = np.array([P["m1"], P["m2"], P["m3"]])
    R, V = m @ pos / m.sum(), m @ vel / m.sum()
    return np.linalg.norm(R), np.linalg.norm(V), R @ V / np.linalg.norm(R)


def semi_major_axis(module, p, y) -> float:
    """Osculating a of the system COM (vis-viva with point-mass μ)."""
    R, V, _ = inertial_com(module, p, y)
    return 1.0 / (2.0 / R - V * V / MU_EARTH)


def work(module, p):
    """``power(y) -> [drag power, damper power]``, Σ_k Q_k q̇_k of those families (Eq 3.31)."""
    fams = module.FAMILIES
    drag = [i for i, f in enumerate(fams) if f.startswith("drag")]
    damp = [i for i, f in enumerate(fams) if f.startswith("damper")]
    nq = len(module.STATE) // 2
    out = np.zeros((len(fams), nq))

    def power(y):
        module.family_forces(y, p, out)
        return [out[drag].sum(axis=0) @ y[nq:], out[damp].sum(axis=0) @ y[nq:]]
    return power


def apsides(module, p, y0, t_end) -> tuple:
    """(solution, perigee times, states at perigee, states at apogee): ṙ's zeros."""
    i = module.STATE.index("r_dot")
    per = lambda t, y: y[i]
    per.direction = 1.0  # ṙ − → +: perigee
    apo = lambda t, y: y[i]
    apo.direction = -1.0
    sol = integrate(module, p, y0, t_end, events=(per, apo), dense_output=True)
    return sol, sol.t_events[0], sol.y_events[0], sol.y_events[1]
