"""The result record of a simulation: arrays, counters, status and the model it ran.

A plain record, as scipy's ``OdeResult``: what the run *means* (metrics, class,
trail, force peaks) is :func:`tethersim.analysis.outcome.outcome`; files are
written by :mod:`tethersim.output.tables`.  The physics evaluated along the run
(generalized forces, tether tensions, energy budget, inertial positions) is here
because it only re-evaluates the model's kernels.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from tethersim.engine.dynamics import held_circle, held_circle_orbit
from tethersim.engine.evaluate import (
    chain_power_series,
    family_forces_series,
    jacobi_series,
    tether_margin_series,
)
from tethersim.model.constants import R_EARTH
from tethersim.model.inputs import air_vector, parameter_vector
from tethersim.model.registry import Model, bead_index, get_model
from tethersim.model.satellite import Satellite

ORBIT_COLUMNS = ("X", "Y", "VX", "VY")
ORBIT_UNITS = ("m", "m", "m/s", "m/s")
CONVERGED_THETA = 1e-3  # rad: 1/50 of the thesis's ±0.05 rad stability band
CONVERGED_POSITION = 1e-2  # m
# the convergence bound of a coordinate, by its unit: every generalized coordinate of
# every model is an angle or a length (registry state_units)
CONVERGED_TOLERANCE = {"rad": CONVERGED_THETA, "m": CONVERGED_POSITION}
#: every status a run can end with (simulate); a stored status code is its index here
# appended, never reordered: a sweep store codes a status by its index here
STATUSES = ("ok", "diverged", "failed", "re-entered", "left-domain", "interrupted",
            "tether-broke")
DISSIPATIVE = ("drag1", "drag2", "drag3", "damper1", "damper2")
# how labels name the error-controlled schemes (simulate's method -> words)
ADAPTIVE_SCHEMES = {"adaptive": "DOP853 adaptive", "implicit": "Radau IIA implicit"}


def errors_converged(errors: dict | None, units: dict) -> bool | None:
    """Whether each estimated final error is within its unit's bound.

    Parameters
    ----------
    errors : dict or None
        {coordinate name: estimated final error} in SI (``SimResult.errors``).
    units : dict
        {coordinate name: SI unit} (``SimResult.units``).

    Returns
    -------
    bool or None
        None when there is no estimate.  Bounds: :data:`CONVERGED_TOLERANCE`.
    """
    if errors is None:
        return None
    return all(e <= CONVERGED_TOLERANCE[units[k]] for k, e in errors.items())


def dominant_error(errors: dict, units: dict) -> tuple:
    """(name, error, unit) of the coordinate whose error is largest against its bound."""
    name = max(errors, key=lambda k: errors[k] / CONVERGED_TOLERANCE[units[k]])
    return name, errors[name], units[name]


def error_phrase(errors: dict, units: dict) -> str:
    """"estimated final error largest in phi: 3e-07 rad" (largest against its bound)."""
    name, err, unit = dominant_error(errors, units)
    return f"estimated final error largest in {name}: {err:.2g} {unit}"


@dataclass(frozen=True)
class SimResult:
    """Time series (SI) and bookkeeping of one run.

    Attributes
    ----------
    satellite : Satellite
        What was simulated.
    model : str
        Model name (``tethersim.MODELS``); its state layout is
        ``tethersim.model.registry.get_model(model).state``.
    method : str
        ``"rk4"`` or ``"adaptive"``.
    t : numpy.ndarray
        Sample times [s].
    states : numpy.ndarray
        (n, model state): the model's state (its STATE order), all that is
        integrated; a circular-orbit model's COM orbit is :attr:`orbit`.
    step : float or None
        RK4 step [s].
    rtol, atol : float or None
        Tolerances of the adaptive run.
    locate_switches : bool
        Whether taut/slack switches were located.
    nfev, n_accepted, n_rejected, n_switches : int
        Right-hand-side evaluations, accepted and rejected steps, switches located.
    status : str
        One of :data:`STATUSES`: ``"ok"``, ``"diverged"``, ``"failed"``,
        ``"re-entered"``, ``"left-domain"``, ``"interrupted"`` or ``"tether-broke"``
        (a tether's tension reached its breaking load ``Satellite.Fb1``/``Fb2``).
    message : str
        What happened, for a status other than ok.
    error_estimate : tuple or None
        Estimated error of the final state in every generalized coordinate, in
        the layout's order (planar: δx [m], δy [m], θ [rad]; 3-D: δx, δy, δz,
        φ, θ, ψ; a free orbit adds r [m], ν [rad]; ``errors`` names them): step
        halving for RK4, a tighter-tolerance rerun for the adaptive method;
        None if not checked (``estimate_error()``).
    wall_time : float
        Seconds the integration took.
    periods : float or None
        Length of the run asked for, in orbits.
    reentry_time : float or None
        When the boom's COM fell below the re-entry altitude [s] (status
        ``"re-entered"``; located in the loop, as ``event_time``), else None.
    event : str or None
        The stopping limit that ended the run (a terminal event name of
        tethersim.engine.events.EVENTS: "re-entry", "roll", "balloon reach",
        "tether 1 stretch", "tether 2 stretch"), else None.  The last sample is
        the state just past it.
    event_time : float or None
        When it was reached [s], located to the switch location's accuracy
        (the last sample's time).
    fine_t, fine_states : numpy.ndarray or None
        The same run on the metrics grid (at least 200 samples per orbit) when
        the output grid asked for is coarser; the output is every k-th of them.
        Metrics (:func:`tethersim.outcome`) use these, so they do not depend on
        the output sampling.  None when the output grid is the metrics grid.
    start : str
        ``"given"``: the run started from ``satellite.initial`` as set;
        ``"equilibrium"``: from the satellite's equilibrium (simulate's
        ``start``), which ``satellite.initial`` then holds.

    The series of any state by name: ``res.series("theta")``; shortcuts ``x``,
    ``y``, ``theta``, ``xdot``, ``ydot``, ``thetadot`` (δx, δy, θ and rates).
    """

    satellite: Satellite
    model: str
    method: str
    t: np.ndarray
    states: np.ndarray  # (n, 10)
    step: float | None = None  # s, RK4 step
    rtol: float | None = None
    atol: float | None = None
    locate_switches: bool = False
    nfev: int = 0
    n_accepted: int = 0
    n_rejected: int = 0
    n_switches: int = 0
    status: str = "ok"
    message: str = ""
    error_estimate: tuple | None = None
    wall_time: float = field(default=0.0, compare=False)
    periods: float | None = None  # length of the run asked for, in orbits (for reruns)
    reentry_time: float | None = None  # s, when the COM fell below the re-entry altitude
    event: str | None = None  # the stopping limit that ended the run (engine/events.py)
    event_time: float | None = None  # s, located in the loop
    # the integrator's dense output on the metrics grid when the output grid is coarser
    fine_t: np.ndarray | None = field(default=None, repr=False)
    fine_states: np.ndarray | None = field(default=None, repr=False)
    # "given" (Satellite.initial as set) or "equilibrium" (engine/start.py): where it started
    start: str = "given"

    # --- arrays --------------------------------------------------------------
    @property
    def layout(self) -> Model:
        """The model's registry entry (state names and units, parameters, kind)."""
        return get_model(self.model)

    def series(self, name: str) -> np.ndarray:
        """Samples of the state called ``name`` (a name in ``layout.state``)."""
        try:
            return self.states[:, self.layout.state.index(name)]
        except ValueError:
            raise KeyError(f"{name!r}: model {self.model} has states "
                           f"{', '.join(self.layout.state)}") from None

    x = property(lambda self: self.series("delta_x"))
    y = property(lambda self: self.series("delta_y"))
    theta = property(lambda self: self.series("theta"))
    xdot = property(lambda self: self.series("delta_x_dot"))
    ydot = property(lambda self: self.series("delta_y_dot"))
    thetadot = property(lambda self: self.series("theta_dot"))

    @property
    def model_states(self) -> np.ndarray:
        """(n, model state): the model's states, :attr:`states` (nothing is appended)."""
        return self.states

    @property
    def orbit(self) -> np.ndarray:
        """(n, 4): the reference point's (boom COM's) inertial X, Y [m] and VX, VY [m/s].

        A circular-orbit model holds it on the circle r0 (cos ωt, sin ωt), computed
        in closed form from the parameter vector's r0 and ω (the two-body Eq 3.9 from
        Table 4.3's start; dynamics.held_circle_orbit), never integrated; a free-orbit
        model integrates r and ν, and R = r (−sin ν, cos ν) (docs/orbit.md), so
        Ṙ = ṙ (−sin ν, cos ν) − r ν̇ (cos ν, sin ν).
        """
        m = self.layout
        if held_circle(m.index):
            p = self.parameters
            return held_circle_orbit(p[m.parameters.index("r0")],
                                     p[m.parameters.index("omega")], self.t)
        r, nu, rd, nud = (self.series(n) for n in ("r", "nu", "r_dot", "nu_dot"))
        s, c = np.sin(nu), np.cos(nu)
        return np.column_stack([-r * s, r * c, -rd * s - r * nud * c, rd * c - r * nud * s])

    @property
    def altitude(self) -> np.ndarray:
        """Altitude of the reference point (the boom's COM) above R_E [m], per sample."""
        if held_circle(self.layout.index):
            r0 = self.parameters[self.layout.parameters.index("r0")]
            return np.full(self.t.shape, r0 - R_EARTH)
        return self.series("r") - R_EARTH

    @property
    def faithful(self) -> bool:
        """True for the thesis's scheme: fixed-step RK4, switches not located."""
        return self.method == "rk4" and not self.locate_switches

    @property
    def units(self) -> dict:
        """{coordinate name: SI unit} of the model's generalized coordinates."""
        m = self.layout
        return dict(zip(m.state[:m.n_coordinates], m.state_units[:m.n_coordinates]))

    @property
    def errors(self) -> dict | None:
        """{coordinate name: estimated final error} in SI (None if not checked)."""
        if self.error_estimate is None:
            return None
        return dict(zip(self.layout.state, self.error_estimate))

    @property
    def converged(self) -> bool | None:
        """Whether every coordinate's estimated final error is within its bound.

        The bound is CONVERGED_TOLERANCE by the coordinate's unit: 1e-3 rad for
        an angle (θ, φ, ψ, ν), 1 cm for a length (δx, δy, δz, r).
        """
        return errors_converged(self.errors, self.units)

    @property
    def label(self) -> str:
        if self.method == "rk4":
            kind = f"RK4, fixed step {self.step:.4g} s"
            kind += " (faithful to the thesis)" if self.faithful else ", switches located"
        else:
            kind = f"{ADAPTIVE_SCHEMES[self.method]}, rtol {self.rtol:g}"
        if self.converged is None:
            conv = "convergence not checked"
        else:
            # what was checked is the final state (estimate_error), not every sample
            conv = "final state converged" if self.converged else "final state NOT converged"
            conv += f" ({error_phrase(self.errors, self.units)})"
        return f"{self.satellite.name}, model {self.model}: {kind}; {conv}"

    def estimate_error(self) -> SimResult:
        """Rerun finer and return this result with ``error_estimate`` set.

        Returns
        -------
        SimResult
            A copy with error_estimate (and so ``converged``) from a rerun at
            half the step (RK4) or at rtol/100 (adaptive), exactly what
            ``simulate(..., check=True)`` returns; this result itself when the
            run did not finish with status "ok".
        """
        from tethersim.engine.simulate import estimate_error
        return estimate_error(self)

    @property
    def per_body(self) -> bool:
        """True when each body sees the air density at its own position."""
        return self.satellite.density_mode == "per-body"

    @cached_property
    def air(self) -> np.ndarray:
        """The air vector the run used (tethersim.model.air.vector)."""
        duration = self.periods * self.satellite.period if self.periods else float(self.t[-1])
        return air_vector(self.satellite, duration)

    @property
    def parameters(self) -> np.ndarray:
        """The parameter vector the run used (the model's PARAMETERS order)."""
        return parameter_vector(self.satellite, self.model)

    # --- derived quantities ----------------------------------------------------
    @cached_property
    def forces(self) -> np.ndarray:
        """Generalized force of each family on each coordinate (n, families, coordinates).

        SI: N on lengths, N m on angles; families in ``layout.families``.
        """
        return family_forces_series(self.layout.index, self.air, self.t, self.states,
                                    self.parameters)

    def tether_margins(self) -> np.ndarray:
        """λ_j − l_j0 [m] of tethers 1 and 2 (n, 2): taut when positive (the model's kernel)."""
        return tether_margin_series(self.layout.index, self.states, self.parameters)

    def tether_tensions(self) -> np.ndarray:
        """Spring tension of tethers 1 and 2 (n, 2) [N], zero while slack (Eqs 3.35-3.36)."""
        s = self.satellite
        g = self.tether_margins()
        return np.column_stack([s.E1 * np.maximum(g[:, 0] / s.l10, 0),
                                s.E2 * np.maximum(g[:, 1] / s.l20, 0)])

    def inertial_positions(self) -> dict:
        """Inertial (GCE-plane) positions [m] of "tip-mass", "bus", "balloon": (n, 2) each.

        Local axes in inertial coordinates follow Eq 3.34 with φ the propagated
        COM's polar angle: local y = (cos φ, sin φ) (radial), local x =
        (sin φ, −cos φ); a body at local offset (x, y − r0) from the COM sits at
        R_COM + x x̂ + (y − r0) ŷ.
        """
        s = self.satellite
        X, Y = self.orbit[:, 0], self.orbit[:, 1]
        phi = np.arctan2(Y, X)
        xhat = np.column_stack([np.sin(phi), -np.cos(phi)])
        yhat = np.column_stack([np.cos(phi), np.sin(phi)])
        com = np.column_stack([X, Y])
        th = self.theta
        offsets = {"tip-mass": (s.b * np.sin(th), s.b * np.cos(th)),
                   "bus": (-s.a * np.sin(th), -s.a * np.cos(th)),
                   "balloon": (self.x, self.y)}
        return {k: com + ox[:, None] * xhat + oy[:, None] * yhat
                for k, (ox, oy) in offsets.items()}

    def bodies(self):
        """Inertial positions, velocities, attitude and spin of the bodies along the run.

        The map of :func:`tethersim.bodies` at every sample (the COM on its
        circle of radius r0 at polar angle ωt for a circular-orbit model).

        Returns
        -------
        tethersim.engine.bodies.Bodies
            Arrays with a leading sample axis, SI, inertial frame.
        """
        from tethersim.engine.bodies import bodies_from_states

        return bodies_from_states(self.satellite, self.model, self.t, self.model_states)

    def energy_budget(self) -> dict:
        """Jacobi integral h(t) [J], dissipated work W(t) [J] and residual h − h0 − W.

        dh/dt equals the power of drag and dampers (Σ Q_k q̇_k), so the
        residual measures integration error (and that of Simpson's rule on the
        samples: sample the run finely, well below the tether period, ~70 s).
        A bead chain's power adds its segments' dampers and drag
        (tethersim.model.beads.chain_power).
        """
        m = self.layout
        h = jacobi_series(m.index, self.states, self.parameters)
        if bead_index(m.index):
            power = chain_power_series(m.index, self.air, self.t, self.states, self.parameters)
        else:
            Q = self.forces
            idx = [m.families.index(f) for f in DISSIPATIVE]
            rates = self.states[:, m.n_coordinates:m.n_state]
            power = np.einsum("ifk,ik->i", Q[:, idx, :], rates)
        from scipy.integrate import cumulative_simpson  # lazy: 0.4 s of import time

        work = cumulative_simpson(power, x=self.t, initial=0.0)
        return {"jacobi": h, "power": power, "work": work, "residual": h - h[0] - work}
