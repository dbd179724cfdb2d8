"""The result record of a simulation, its derived quantities and exports."""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from generated.layout import FAMILIES, STATE, STATE_UNITS

from . import metrics as _metrics
from .dynamics import CFG_MODEL, CFG_PER_BODY
from .evaluate import family_forces_series, jacobi_series
from .models import model_index
from .satellite import Satellite, parameter_vector

ORBIT_COLUMNS = ("X", "Y", "VX", "VY")
ORBIT_UNITS = ("m", "m", "m/s", "m/s")
CONVERGED_THETA = 1e-3  # rad: 1/50 of the thesis's ±0.05 rad stability band
CONVERGED_POSITION = 1e-2  # m
DISSIPATIVE = ("drag1", "drag2", "drag3", "damper1", "damper2")


@dataclass(frozen=True)
class SimResult:
    """Time series (SI) and bookkeeping of one run.

    t [s]; x, y [m] balloon offsets δx, δy; theta [rad]; xdot, ydot [m/s];
    thetadot [rad/s]; orbit (n, 4): COM inertial X, Y [m], VX, VY [m/s].
    method: "rk4" or "adaptive"; faithful: fixed-step RK4 without switch
    location, as in the thesis; error_estimate: estimated error of the final
    state in (δx [m], δy [m], θ [rad]) — step halving for RK4, a tighter-
    tolerance rerun for the adaptive method — or None if not checked.
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

    # --- arrays --------------------------------------------------------------
    x = property(lambda self: self.states[:, 0])
    y = property(lambda self: self.states[:, 1])
    theta = property(lambda self: self.states[:, 2])
    xdot = property(lambda self: self.states[:, 3])
    ydot = property(lambda self: self.states[:, 4])
    thetadot = property(lambda self: self.states[:, 5])
    orbit = property(lambda self: self.states[:, 6:10])

    @property
    def faithful(self) -> bool:
        """True for the thesis's scheme: fixed-step RK4, switches not located."""
        return self.method == "rk4" and not self.locate_switches

    @property
    def converged(self) -> bool | None:
        """Whether the estimated final error is within CONVERGED_THETA and CONVERGED_POSITION."""
        if self.error_estimate is None:
            return None
        ex, ey, eth = self.error_estimate
        return bool(eth <= CONVERGED_THETA and ex <= CONVERGED_POSITION and ey <= CONVERGED_POSITION)

    @property
    def label(self) -> str:
        if self.method == "rk4":
            kind = f"RK4, fixed step {self.step:.4g} s"
            kind += " (faithful to the thesis)" if self.faithful else ", switches located"
        else:
            kind = f"DOP853 adaptive, rtol {self.rtol:g}"
        if self.converged is None:
            conv = "convergence not checked"
        else:
            conv = "converged" if self.converged else "NOT converged"
            conv += f" (estimated final error in θ {self.error_estimate[2]:.2g} rad)"
        return f"{self.satellite.name}, model {self.model}: {kind}; {conv}"

    @property
    def cfg(self) -> np.ndarray:
        cfg = np.zeros(2, dtype=np.int64)
        cfg[CFG_MODEL] = model_index(self.model)
        cfg[CFG_PER_BODY] = 1 if self.satellite.density_mode == "per-body" else 0
        return cfg

    # --- derived quantities ----------------------------------------------------
    @cached_property
    def metrics(self) -> _metrics.PitchMetrics:
        return _metrics.pitch_metrics(self.t, self.theta)

    @cached_property
    def forces(self) -> np.ndarray:
        """Generalized force of each family (n, 7, 3): N, N, N m (families in FAMILIES)."""
        return family_forces_series(self.cfg, self.states, parameter_vector(self.satellite))

    def tether_tensions(self) -> np.ndarray:
        """Spring tension of tethers 1 and 2 (n, 2) [N], zero while slack (Eqs 3.35-3.36)."""
        s = self.satellite
        th, dx, dy = self.theta, self.x, self.y
        lam1 = np.hypot(s.b * np.sin(th) - dx, s.b * np.cos(th) - dy)
        lam2 = np.hypot(-s.a * np.sin(th) - dx, -s.a * np.cos(th) - dy)
        return np.column_stack([s.E1 * np.maximum(lam1 / s.l10 - 1, 0),
                                s.E2 * np.maximum(lam2 / s.l20 - 1, 0)])

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

    def energy_budget(self) -> dict:
        """Jacobi integral h(t) [J], dissipated work W(t) [J] and residual h − h0 − W.

        dh/dt equals the power of drag and dampers (Σ Q_k q̇_k), so the
        residual measures integration error (and that of Simpson's rule on the
        samples: sample the run finely, well below the tether period, ~70 s).
        """
        h = jacobi_series(self.cfg, self.states, parameter_vector(self.satellite))
        Q = self.forces
        idx = [FAMILIES.index(f) for f in DISSIPATIVE]
        power = np.einsum("ifk,ik->i", Q[:, idx, :], self.states[:, 3:6])
        from scipy.integrate import cumulative_simpson  # lazy: 0.4 s of import time

        work = cumulative_simpson(power, x=self.t, initial=0.0)
        return {"jacobi": h, "power": power, "work": work, "residual": h - h[0] - work}

    def summary(self) -> dict:
        m = self.metrics
        period = self.satellite.period
        tension = self.tether_tensions().max(axis=0)
        peak = np.abs(self.forces).max(axis=0)  # (family, coordinate)
        biggest = peak.argmax(axis=0)
        return {
            "label": self.label,
            "mean pitch [rad]": m.mean_pitch,
            "steady-state pitch [rad]": m.steady_state_pitch,
            "settling time [orbits]": m.settling_time / period,
            "settling time [h]": m.settling_time / 3600,
            "largest tension tether 1 [N]": float(tension[0]),
            "largest tension tether 2 [N]": float(tension[1]),
            "largest force on dx [N]": float(peak[biggest[0], 0]),
            "largest force on dx: family": FAMILIES[biggest[0]],
            "largest force on dy [N]": float(peak[biggest[1], 1]),
            "largest force on dy: family": FAMILIES[biggest[1]],
            "largest torque on theta [N m]": float(peak[biggest[2], 2]),
            "largest torque on theta: family": FAMILIES[biggest[2]],
            "tumbled": m.tumbled,
            "upside down": m.upside_down,
            "final delta_x [m]": float(self.x[-1]),
            "final delta_y [m]": float(self.y[-1]),
            "status": self.status,
            **self._implausible_summary(),
        }

    def _implausible_summary(self) -> dict:
        """The plausibility violations the run was allowed (``allow_implausible``), if any."""
        found = self.satellite.implausible if self.satellite.allow_implausible else ()
        return {"implausible inputs (allowed)": "; ".join(found)} if found else {}

    # --- exports ---------------------------------------------------------------
    def to_xarray(self):
        import xarray as xr

        data = {n: ("t", self.states[:, i], {"units": u})
                for i, (n, u) in enumerate(zip(STATE + ORBIT_COLUMNS, STATE_UNITS + ORBIT_UNITS))}
        attrs = {"satellite": self.satellite.name, "model": self.model, "method": self.method,
                 "label": self.label, "status": self.status,
                 **{k.split(" (")[0].replace(" ", "_"): v
                    for k, v in self._implausible_summary().items()},
                 "conventions": "docs/conventions.md: local frame rotating with omega z, "
                                "COM moves along -x, theta from +y towards +x"}
        for k, v in self.satellite.to_dict().items():
            if isinstance(v, (int, float, str)):
                attrs[f"sat_{k}"] = v
        return xr.Dataset(data, coords={"t": ("t", self.t, {"units": "s"})}, attrs=attrs)

    def to_netcdf(self, path) -> Path:
        path = Path(path)
        self.to_xarray().to_netcdf(path, engine="scipy")
        return path

    def to_csv(self, path) -> Path:
        path = Path(path)
        cols = ("t",) + STATE + ORBIT_COLUMNS
        units = ("s",) + STATE_UNITS + ORBIT_UNITS
        header = ",".join(f"{c} [{u}]" for c, u in zip(cols, units))
        np.savetxt(path, np.column_stack([self.t, self.states]), delimiter=",",
                   header=header, comments="", fmt="%.17g")
        return path


