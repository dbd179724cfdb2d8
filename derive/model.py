"""One derivation pipeline for every model: definition → Lagrange → derived record.

A model is one :class:`ModelDefinition`: its generalized coordinates (a
:class:`Coordinates` record: geometry, orbit kind, kinematics, state and
parameter symbols, and the Lagrange step of those coordinates), its gravity
law, truncation, force families and options.  :func:`derive` turns every
definition, whatever its geometry or orbit, into one :class:`DerivedModel`:
plain sympy expressions in the state symbols, which the one printer
(derive/emit.py) writes as a numba module.

What differs between coordinates is physics, not pipeline, and lives beside
the coordinates: the planar circular Lagrange equations are truncated in 1/r0
(derive/pipeline.py), the 3-D ones are formed from T and V directly
(derive/three_d/pipeline3d.py), the free-orbit ones carry r and ν
(derive/orbit.py, derive/three_d/free3d.py).
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy as sp


@dataclass(frozen=True)
class Coordinates:
    """The generalized coordinates of one geometry on one orbit kind.

    Attributes
    ----------
    geometry : str
        ``planar`` (δx, δy, θ) or ``3d`` (δx, δy, δz, φ, θ, ψ).
    orbit : str
        ``circular`` (r0, ω prescribed, Eq 3.14) or ``free`` (r, ν are coordinates).
    state_names, state_units, state_symbols : tuple
        The state y: coordinates, then their rates.
    acceleration_symbols, q_symbols : tuple
        q̈ and the summed generalized forces Q, one per coordinate.
    parameters : tuple of Parameter
        The parameter vector p.
    tether_lengths : tuple of sympy.Symbol
        λ1, λ2 (Eqs 3.41-3.42).
    kinematics : callable
        ``kinematics()`` → bodies, frames and tether vectors.
    substitution : callable
        ``substitution()`` → {q̈, q̇, q (functions of t): plain symbols}.
    equations : callable
        ``equations(defn, kin)`` → :class:`Equations` (the Lagrange step).
    expand_tethers : bool
        Expand the tether families' generalized forces (free orbit: their
        r·(...) terms cancel symbolically, so exact zeros stay zeros).
    """

    geometry: str
    orbit: str
    state_names: tuple
    state_units: tuple
    state_symbols: tuple
    acceleration_symbols: tuple
    q_symbols: tuple
    parameters: tuple
    tether_lengths: tuple
    kinematics: Callable
    substitution: Callable
    equations: Callable
    expand_tethers: bool = False

    @property
    def n_q(self) -> int:
        return len(self.acceleration_symbols)

    def to_state(self, expr):
        """Replace q(t), q̇(t), q̈(t) by the plain state symbols."""
        return sp.sympify(expr).xreplace(self.substitution())


@dataclass(frozen=True)
class Equations:
    """What a Lagrange step returns: M q̈ + f = Σ Q and the Jacobi integral.

    ``lhs``, ``lhs_untruncated``: the Lagrange left-hand sides where the step
    forms them (None: :func:`derive` assembles M q̈ + f).
    """

    mass_matrix: sp.Matrix
    f: tuple
    energy: sp.Expr
    lhs: tuple | None = None
    lhs_untruncated: tuple | None = None


@dataclass(frozen=True)
class ModelDefinition:
    """What distinguishes one model from another.

    Attributes
    ----------
    name, description : str
        Model name used by the runtime (``derived``, ``3d-free`` ...) and one
        line for the generated header.
    coordinates : Coordinates
        Geometry, orbit kind, kinematics and the Lagrange step.
    potential : callable
        The gravity law, in the form the coordinates' Lagrange step takes
        (1/|r_i| for the planar circular models, |r_i|^(2n) for the 3-D ones,
        (1/|r_i|, 1/|r_i|³) for the planar free orbit).
    truncation : int or None
        Highest order kept (1/r0 power, or degree in the offsets on a free orbit).
    families : callable
        kinematics → tuple of ForceFamily, in the generated FAMILIES order.
    lhs_override : tuple or None
        Lagrange left-hand sides to use instead of the derived ones (only the
        printed model, to simulate exactly what the thesis printed).
    circular : str
        Free-orbit models: the model this one reduces to on a circular orbit.
    """

    name: str
    description: str
    coordinates: Coordinates
    potential: Callable
    truncation: int | None
    families: Callable
    lhs_override: tuple | None = None
    circular: str = ""

    @property
    def geometry(self) -> str:
        return self.coordinates.geometry

    @property
    def orbit(self) -> str:
        return self.coordinates.orbit


@dataclass(frozen=True)
class DerivedModel:
    """M q̈ + f(q, q̇) = Σ Q_family of one model, in its state symbols.

    Attributes
    ----------
    definition : ModelDefinition
    lhs, lhs_untruncated : tuple
        M q̈ + f, the Lagrange left-hand sides (after and before truncation).
    mass_matrix : sympy.Matrix
    f : tuple
        The non-acceleration terms (Coriolis, centrifugal, gravity) [N, N m].
    families : tuple of ForceFamily
        Generalized forces, λ1, λ2 as symbols.
    energy : sympy.Expr
        The Jacobi integral h = Σ q̇ ∂L/∂q̇ − L without state-free constants (on
        a free orbit T + V) [J].
    qdd : tuple or None
        q̈ in closed form in the state and Q symbols where M is diagonal.
    length_defs : dict
        λ1, λ2 → tether lengths in the state symbols (Eqs 3.41-3.42).
    positions, tether_vectors : tuple of tuple
        Components in the local frame of each body's position from Earth's
        centre (Eqs 3.10-3.12) and of each tether vector.
    """

    definition: ModelDefinition
    lhs: tuple
    lhs_untruncated: tuple
    mass_matrix: sp.Matrix
    f: tuple
    families: tuple
    energy: sp.Expr
    qdd: tuple | None
    length_defs: dict
    positions: tuple
    tether_vectors: tuple

    @property
    def name(self) -> str:
        return self.definition.name

    @property
    def coordinates(self) -> Coordinates:
        return self.definition.coordinates

    @property
    def jacobi(self):
        """The Jacobi integral (alias of ``energy``)."""
        return self.energy


def derive(defn: ModelDefinition) -> DerivedModel:
    """Run the pipeline for one model definition.

    Parameters
    ----------
    defn : ModelDefinition

    Returns
    -------
    DerivedModel
    """
    co = defn.coordinates
    kin = co.kinematics()
    eq = co.equations(defn, kin)
    M, f = eq.mass_matrix, eq.f
    acc = co.acceleration_symbols
    lhs = eq.lhs if eq.lhs is not None else tuple(
        sum(M[k, m] * acc[m] for m in range(co.n_q)) + f[k] for k in range(co.n_q))
    families = tuple(replace(fam, Q=tuple(_tidy(co, co.to_state(q), fam.tether) for q in fam.Q),
                             potential=None if fam.potential is None else co.to_state(fam.potential))
                     for fam in defn.families(kin))
    qdd = None
    if M.is_diagonal():  # the planar circular models: q̈ in closed form
        qdd = M.LUsolve(sp.Matrix(co.q_symbols) - sp.Matrix(f))
        qdd = tuple(sp.expand(sp.simplify(e)) for e in qdd)
    sub = co.substitution()
    axes = (kin.L.x, kin.L.y) if co.geometry == "planar" else (kin.L.x, kin.L.y, kin.L.z)

    def comps(vec):
        return tuple(sp.sympify(vec.dot(axis)).subs(sub) for axis in axes)

    length_defs = {lam: co.to_state(kin.tether_length_defs[lam]) for lam in co.tether_lengths}
    _check_symbols(defn, lhs + f + (qdd or ()) + tuple(q for fam in families for q in fam.Q)
                   + (eq.energy,))
    return DerivedModel(defn, lhs, eq.lhs_untruncated or lhs, M, f, families, eq.energy, qdd,
                        length_defs, tuple(comps(r) for r in kin.positions),
                        tuple(comps(v) for v in kin.tether_vectors))


def _tidy(co: Coordinates, q, tether):
    """Expand a tether family's generalized force (free orbit); leave drag (with its √) as derived."""
    return sp.expand(q) if co.expand_tethers and tether is not None else q


def _check_symbols(defn: ModelDefinition, exprs) -> None:
    """Fail at generation time if an expression uses a symbol with no slot."""
    co = defn.coordinates
    allowed = (set(co.state_symbols) | set(co.acceleration_symbols) | set(co.q_symbols)
               | {p.symbol for p in co.parameters} | set(co.tether_lengths))
    for e in exprs:
        extra = sp.sympify(e).free_symbols - allowed
        if extra:
            raise ValueError(f"model {defn.name!r}: symbols without a slot: {sorted(map(str, extra))}")
