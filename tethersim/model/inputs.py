"""A satellite as the inputs of one model: its parameter vector and initial state.

Each generated model names its own parameter vector (``Model.parameters``) and
state (``Model.state``); this module fills them from a :class:`Satellite` by
name, so a model with another layout (3-D, free orbit) needs no code here
beyond the values it adds:

* ``I1_roll``, ``I1_pitch``, ``I1_yaw``, ``I2_*`` [kg m²]: principal moments of the
  tip-mass (1) and bus (2), tethersim.model.inertia: thesis Eq 4.4 boxes
  (I = m · 2A / 12 about every axis), zero with ``inertia = "points"``, or the
  satellite's ``I1``, ``I2`` overrides;
* ``J2`` (0 unless the satellite asks for it) and ``R_E`` [m];
* the out-of-plane initial state (δz, roll φ, yaw ψ and rates), zero unless set;
* for a free orbit, the perigee at t = 0: r = r_p = R_E + altitude, ν = 0, ṙ = 0
  and ν̇ the perigee rate of eccentricity e, ν̇² = μ (1 + e) / r_p³ (vis-viva: the
  apogee is then r_p (1 + e)/(1 − e)); with J2, times (1 + 3/2 J2 (R_E/r_p)²), the
  factor that keeps an equatorial orbit circular at e = 0.
"""
from __future__ import annotations

import math

import numpy as np

from tethersim.model.air.vector import air_vector as _air_vector
from tethersim.model.bead_layout import attachments_refused, moved_attachments
from tethersim.model.constants import J2_EARTH, MU_EARTH, R_EARTH
from tethersim.model.inertia import body_inertias
from tethersim.model.options import air_model
from tethersim.model.registry import bead_split, get_model
from tethersim.model.satellite import Satellite, parameters


def box_inertias(sat: Satellite) -> dict:
    """Principal moments [kg m²] of the tip-mass and bus (tethersim.model.inertia).

    Thesis Eq 4.4 boxes by default; zero with ``inertia = "points"``; a body's
    ``I1`` / ``I2`` override wins.  Keys ``I1_roll`` ... ``I2_yaw``.
    """
    return body_inertias(sat)


def model_values(sat: Satellite) -> dict:
    """Every named input any model reads, SI."""
    values = parameters(sat)
    values.update(box_inertias(sat))
    values["J2"] = J2_EARTH if getattr(sat, "j2", False) else 0.0
    values["R_E"] = R_EARTH
    return values


def parameter_vector(sat: Satellite, model: str) -> np.ndarray:
    """The parameter vector of ``model`` for ``sat`` (the model's PARAMETERS order; a bead
    chain's then has its kernels' scratch, tethersim.model.bead_layout.parameter_vector)."""
    if (chain := bead_split(model)) is not None:
        from tethersim.model import bead_layout
        base = parameter_vector(sat.replace(s1=None, s2=None), chain[0])
        return bead_layout.parameter_vector(base, sat.mt1, sat.mt2, sat.dt1, sat.dt2, sat.CDt,
                                            n=chain[1], s1=sat.s1, s2=sat.s2)
    if moved_attachments(sat):
        raise ValueError(attachments_refused(sat, model))
    values = model_values(sat)
    return np.array([values[n] for n in get_model(model).parameters], dtype=np.float64)


def air_vector(sat: Satellite, duration_s: float) -> np.ndarray:
    """The air vector of a run of ``sat`` lasting ``duration_s`` seconds (model/air/vector.py).

    Uniform density (the thesis: ρ in the parameter vector), or each body's own
    density from Vallado's table or NRLMSISE-00, times ``density_scale``.
    """
    return _air_vector(air_model(sat), sat.density_mode == "per-body", sat.density_scale,
                       duration_s)


def initial_model_state(sat: Satellite, model: str) -> np.ndarray:
    """The model's own initial state (its STATE order) for ``sat``; a bead chain's: its
    beads on the straight lines from the boom ends to the balloon (bead_layout.straight_chain)."""
    if (chain := bead_split(model)) is not None:
        from tethersim.model import bead_layout
        return bead_layout.straight_chain(initial_model_state(sat, chain[0]), chain[1],
                                          parameter_vector(sat, model))
    dx, dy, th, dxd, dyd, thd = sat.initial
    extra = {"delta_z": 0.0, "phi": 0.0, "psi": 0.0, "delta_z_dot": 0.0, "phi_dot": 0.0,
             "psi_dot": 0.0}
    extra.update(getattr(sat, "initial_3d", {}) or {})
    values = {"delta_x": dx, "delta_y": dy, "theta": th, "delta_x_dot": dxd,
              "delta_y_dot": dyd, "theta_dot": thd, **extra}
    m = get_model(model)
    if m.orbit == "free":
        r = sat.r0
        j2 = J2_EARTH if getattr(sat, "j2", False) else 0.0
        e = getattr(sat, "eccentricity", 0.0)
        values.update(r=r, nu=0.0, r_dot=0.0,
                      nu_dot=math.sqrt(MU_EARTH * (1 + e) / r**3
                                       * (1 + 1.5 * j2 * (R_EARTH / r) ** 2)))
    return np.array([values[n] for n in m.state], dtype=np.float64)
