"""40-digit reference evaluation of a DerivedModel3D (for tests and checks).

Evaluates the symbolic M, f, families, tether lengths and Jacobi integral of
derive/three_d/pipeline3d.py with mpmath (sympy.lambdify, modules="mpmath"),
applies the tether gates (taut when λ_j > l_j0, Eqs 3.35-3.36) and solves
M q̈ = Σ Q − f with the same zero-axial-inertia rule as the generated kernels
(ψ̈ = 0 and the (φ, θ) block alone when I1_yaw + I2_yaw = 0).  Nothing here is
shared with the code printer, so it is an independent check of codegen3d.
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp

from ..model import DerivedModel as DerivedModel3D
from ..reference import derived
from .symbols3d import N_Q, PARAMETER_NAMES, PARAMETERS, ROTATION, STATE_SYMBOLS, TETHER_LENGTHS

DIGITS = 40


@functools.cache
def derived_3d(name: str) -> DerivedModel3D:
    """The DerivedModel3D of ``name`` (derived once per process)."""
    return derived(name)


def _mp(values):
    """mpf of each value: float64 inputs exactly, mpf inputs unchanged."""
    return [v if isinstance(v, mpmath.mpf) else mpmath.mpf(float(v)) for v in values]


class Reference3D:
    """mpmath evaluation of one 3-D model at float64 inputs.

    Parameters
    ----------
    model : DerivedModel3D
        The symbolic model.
    """

    def __init__(self, model: DerivedModel3D):
        args = (*STATE_SYMBOLS, *(p.symbol for p in PARAMETERS))
        wl = (*args, *TETHER_LENGTHS)

        def lam(exprs, with_lengths=False):
            exprs = [sp.sympify(e).rewrite(sp.Pow) for e in exprs]
            return sp.lambdify(wl if with_lengths else args, exprs, modules="mpmath")

        self.model = model
        self.tethers = tuple(f.tether for f in model.families)
        self.lengths = lam([model.length_defs[x] for x in TETHER_LENGTHS])
        self.families = [lam(f.Q, True) for f in model.families]
        self.f = lam(model.f)
        self.M = lam([model.mass_matrix[k, m] for k in range(N_Q) for m in range(N_Q)])
        self.jacobi_h = lam([model.jacobi])
        pots = [sum(f.potential for f in model.families if f.tether == j + 1 and f.potential is not None)
                for j in range(2)]
        self.spring_energy = lam(pots, True)
        self.i_rest = (PARAMETER_NAMES.index("l10"), PARAMETER_NAMES.index("l20"))
        self.i_axial = (PARAMETER_NAMES.index("I1_yaw"), PARAMETER_NAMES.index("I2_yaw"))

    def _gates(self, vals, p):
        lam = self.lengths(*vals)
        taut = tuple(bool(lam[j] > mpmath.mpf(float(p[self.i_rest[j]]))) for j in range(2))
        return lam, taut

    def forces(self, y, p):
        """(families[f][k], taut): gated generalized forces as mpf."""
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            lam, taut = self._gates(vals, p)
            out = []
            for fn, tether in zip(self.families, self.tethers):
                on = tether is None or taut[tether - 1]
                out.append([mpmath.mpf(v) for v in fn(*vals, *lam)] if on
                           else [mpmath.mpf(0)] * N_Q)
        return out, taut

    def qdd(self, y, p):
        """q̈ (six mpf) from M q̈ = Σ Q − f."""
        fam, _ = self.forces(y, p)
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            f = self.f(*vals)
            Mf = self.M(*vals)
            rhs = [sum(fm[k] for fm in fam) - f[k] for k in range(N_Q)]
            acc = [rhs[k] / Mf[k * N_Q + k] for k in range(3)]
            axial = sum(float(p[i]) for i in self.i_axial) > 0.0
            rot = ROTATION if axial else ROTATION[:2]
            A = mpmath.matrix([[Mf[k * N_Q + m] for m in rot] for k in rot])
            x = mpmath.lu_solve(A, mpmath.matrix([rhs[k] for k in rot]))
            acc += [x[i] for i in range(len(rot))] + ([] if axial else [mpmath.mpf(0)])
        return acc

    def rhs(self, y, p):
        """dy/dt (twelve mpf)."""
        return _mp(y[N_Q:]) + self.qdd(y, p)

    def jacobi(self, y, p):
        """Jacobi integral plus taut-tether spring energy [J] (mpf)."""
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            lam, taut = self._gates(vals, p)
            h = self.jacobi_h(*vals)[0]
            springs = self.spring_energy(*vals, *lam)
            return h + sum(springs[j] for j in range(2) if taut[j])
