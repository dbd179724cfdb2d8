"""40-digit reference evaluation of any DerivedModel (for the contract tests).

Evaluates the symbolic M, f, families, tether lengths, Jacobi integral and body
positions of derive.model.derive with mpmath (sympy.lambdify, modules="mpmath";
the exact-gravity functions H, G rewritten as powers), applies the tether gates
(taut when λ_j > l_j0, Eqs 3.35-3.36) and solves M q̈ = Σ Q − f by LU at 40
digits, with the rule of the generated kernels for a boom without axial
inertia (I1_yaw + I2_yaw = 0: ψ̈ = 0, the other rows alone; docs/three-d.md).
Nothing here is shared with the printer (derive/emit.py and the solves), so
it is an independent check of the generated kernels, the same for every model.
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp

from .model import DerivedModel, derive

DIGITS = 40


@functools.cache
def derived(name: str) -> DerivedModel:
    """The DerivedModel of the registered model ``name`` (derived once per process)."""
    from .models import BY_NAME
    return derive(BY_NAME[name])


def _mp(values):
    """mpf of each value: float64 inputs exactly, mpf inputs unchanged."""
    return [v if isinstance(v, mpmath.mpf) else mpmath.mpf(float(v)) for v in values]


class Reference:
    """mpmath evaluation of one model at float64 (or mpf) inputs.

    Parameters
    ----------
    model : DerivedModel
        The symbolic model.
    """

    def __init__(self, model: DerivedModel):
        co = model.coordinates
        args = (*co.state_symbols, *(p.symbol for p in co.parameters))
        wl = (*args, *co.tether_lengths)

        def lam(exprs, with_lengths=False):
            exprs = [sp.sympify(e).rewrite(sp.Pow) for e in exprs]
            return sp.lambdify(wl if with_lengths else args, exprs, modules="mpmath")

        self.model, self.n = model, co.n_q
        self.tethers = tuple(f.tether for f in model.families)
        self.lengths = lam([model.length_defs[x] for x in co.tether_lengths])
        self.families = [lam(f.Q, True) for f in model.families]
        self.f = lam(model.f)
        self.M = lam([model.mass_matrix[k, m] for k in range(self.n) for m in range(self.n)])
        self.energy = lam([model.energy])
        self.energy_terms = lam(sp.Add.make_args(sp.expand(model.energy)))
        pots = [sum(f.potential for f in model.families if f.tether == j + 1 and f.potential is not None)
                for j in range(2)]
        self.spring_energy = lam(pots, True)
        self.positions = lam([c for r in model.positions for c in r])
        names = [p.name for p in co.parameters]
        self.i_rest = (names.index("l10"), names.index("l20"))
        self.i_axial = tuple(names.index(n) for n in ("I1_yaw", "I2_yaw") if n in names)
        self.psi = co.state_names.index("psi") if "psi" in co.state_names else None

    def tether_lengths(self, y, p):
        """(λ1, λ2) [m] as mpf."""
        with mpmath.workdps(DIGITS):
            return tuple(self.lengths(*_mp((*y, *p))))

    def taut(self, y, p):
        """Whether each tether is taut, λ_j > l_j0 (Eqs 3.35-3.36)."""
        lam = self.tether_lengths(y, p)
        return tuple(bool(lam[j] > mpmath.mpf(float(p[self.i_rest[j]]))) for j in range(2))

    def forces(self, y, p):
        """families[f][k]: the gated generalized forces as mpf."""
        taut = self.taut(y, p)
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            lam = self.lengths(*vals)
            return [[mpmath.mpf(v) for v in fn(*vals, *lam)]
                    if tether is None or taut[tether - 1] else [mpmath.mpf(0)] * self.n
                    for fn, tether in zip(self.families, self.tethers)]

    def qdd(self, y, p):
        """q̈ (mpf) from M q̈ = Σ Q − f."""
        fam = self.forces(y, p)
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            f, Mf = self.f(*vals), self.M(*vals)
            rhs = [sum(fm[k] for fm in fam) - f[k] for k in range(self.n)]
            point_masses = self.i_axial and sum(float(p[i]) for i in self.i_axial) == 0.0
            rows = [k for k in range(self.n) if not (point_masses and k == self.psi)]
            A = mpmath.matrix([[Mf[k * self.n + m] for m in rows] for k in rows])
            x = mpmath.lu_solve(A, mpmath.matrix([rhs[k] for k in rows]))
            acc = [mpmath.mpf(0)] * self.n
            for i, k in enumerate(rows):
                acc[k] = x[i]
        return acc

    def rhs(self, y, p):
        """dy/dt (mpf)."""
        return _mp(y[self.n:]) + self.qdd(y, p)

    def jacobi(self, y, p):
        """Jacobi integral (free orbit: T + V) plus taut-tether spring energy [J] (mpf)."""
        taut = self.taut(y, p)
        with mpmath.workdps(DIGITS):
            vals = _mp((*y, *p))
            lam = self.lengths(*vals)
            springs = self.spring_energy(*vals, *lam)
            return self.energy(*vals)[0] + sum(springs[j] for j in range(2) if taut[j])

    def jacobi_scale(self, y, p):
        """Σ |terms| of the Jacobi integral's expanded form [J]: the size its rounding scales with."""
        with mpmath.workdps(DIGITS):
            return sum(abs(v) for v in self.energy_terms(*_mp((*y, *p))))

    def body_radii(self, y, p):
        """(|R_1|, |R_2|, |R_3|) [m] from the positions of Eqs 3.10-3.12 (mpf)."""
        with mpmath.workdps(DIGITS):
            c = self.positions(*_mp((*y, *p)))
            d = len(c) // 3
            return tuple(mpmath.sqrt(sum(v**2 for v in c[i * d:(i + 1) * d])) for i in range(3))
