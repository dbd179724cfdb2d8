"""The one registry of models: what `make derive` produced, read from generated/.

Every generated module carries its own layout and description (``STATE``,
``STATE_UNITS``, ``PARAMETERS``, ``PARAMETER_UNITS``, ``FAMILIES``,
``DESCRIPTION``, ``GEOMETRY``, ``ORBIT``); ``tethersim.generated.MODELS`` lists
them in index order.  Nothing else in tethersim lists the models: a model that
`make derive` adds (another state size, another geometry) appears here, in the
CLI's ``--model`` choices and in the engine's compiled loops with no edit.

Geometry and orbit kinds:

* ``planar`` / ``circular``: the thesis's models (derived, printed,
  exact-gravity, objective-damper), the COM held on a circular orbit;
* ``3d`` / ``circular``: roll, pitch, yaw and an out-of-plane balloon (docs/three-d.md);
* ``planar`` / ``free``: the orbit radius r and anomaly ν as coordinates (docs/orbit.md);
* ``3d`` / ``free``: both (docs/three-d.md, docs/orbit.md).

A free model's module names the circular model it reduces to (``CIRCULAR_TWIN``):
:func:`model_for_orbit` maps a circular model to its free twin from that.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from types import ModuleType

import tethersim.generated as generated

DEFAULT_MODEL = "derived"


@dataclass(frozen=True)
class Model:
    """One generated model and its layout.

    Attributes
    ----------
    name : str
        Model name (``--model``).
    index : int
        Position in ``tethersim.generated.MODELS`` (the compiled loops' literal).
    description : str
        What distinguishes it (from derive/).
    geometry : str
        ``"planar"`` or ``"3d"``.
    orbit : str
        ``"circular"`` (COM held on its circle) or ``"free"`` (r, ν coordinates).
    state, state_units : tuple of str
        Names and SI units of the model's state vector.
    parameters, parameter_units : tuple of str
        Names and SI units of its parameter vector.
    families : tuple of str
        Force families of ``family_forces``.
    module : module
        The generated kernels.
    """

    name: str
    index: int
    description: str
    geometry: str
    orbit: str
    state: tuple
    state_units: tuple
    parameters: tuple
    parameter_units: tuple
    families: tuple
    module: ModuleType

    @property
    def n_state(self) -> int:
        """Length of the model's own state vector."""
        return len(self.state)

    @property
    def n_coordinates(self) -> int:
        """Number of generalized coordinates (half the state)."""
        return len(self.state) // 2

    @property
    def thesis_variant(self) -> bool:
        """True for the planar, circular-orbit models of the thesis."""
        return self.geometry == "planar" and self.orbit == "circular"


def _model(index: int, name: str, module: ModuleType) -> Model:
    return Model(name=name, index=index, description=module.DESCRIPTION,
                 geometry=module.GEOMETRY, orbit=module.ORBIT, state=tuple(module.STATE),
                 state_units=tuple(module.STATE_UNITS), parameters=tuple(module.PARAMETERS),
                 parameter_units=tuple(module.PARAMETER_UNITS),
                 families=tuple(module.FAMILIES), module=module)


MODELS = tuple(_model(i, n, m) for i, (n, m) in enumerate(generated.MODELS.items()))
NAMES = tuple(m.name for m in MODELS)
BY_NAME = {m.name: m for m in MODELS}
THESIS_VARIANTS = tuple(m.name for m in MODELS if m.thesis_variant)
# each model's generated module by index: calling its own kernels from Python compiles
# that model only (the generated dispatch.py branches over every model, and compiling a
# call through it compiles all of them)
KERNELS = tuple(m.module for m in MODELS)


#: the base models a bead chain (tethersim/model/beads.py, docs/beads.md) runs over
BEAD_BASES = ("derived", "exact-gravity", "objective-damper")
#: each base's chain: a fixed index after the generated models (the compiled loops'
#: literal and numba's cache key), never an order of registration at run time
BEAD_INDEX = {base: len(MODELS) + i for i, base in enumerate(BEAD_BASES)}
_BEAD_TAG = "+beads"


def bead_model_name(base: str, n: int) -> str:
    """The name of the chain of ``n`` beads a line over ``base`` (e.g. ``derived+beads4``)."""
    if base not in BEAD_BASES:
        raise ValueError(f"model = {base!r} with beads: allowed values {', '.join(BEAD_BASES)}")
    return f"{base}{_BEAD_TAG}{int(n)}"


def bead_split(name: str):
    """(base, N) of a chain model's name, or None for any other name."""
    base, tag, n = str(name).rpartition(_BEAD_TAG)
    if not tag or base not in BEAD_BASES or not n.isdigit():
        return None
    return base, int(n)


def _bead_model(base: str, n: int) -> Model:
    from tethersim.model import bead_kernels, beads  # they import this module: at call time
    m = BY_NAME[base]
    state, units = beads.state_names(base, n)
    return replace(m, name=bead_model_name(base, n), index=BEAD_INDEX[base],
                   description=f"{m.description}; each tether a chain of {n} beads",
                   state=state, state_units=units,
                   parameters=m.parameters + beads.EXTRA_PARAMETERS,
                   parameter_units=m.parameter_units + beads.EXTRA_UNITS,
                   families=(), module=bead_kernels.engine_kernels(base))


def record(index: int) -> Model:
    """The model at compiled-loop index ``index``; a chain's with N = 0 (its coordinates
    start with the base's; its state size is read from the state vector)."""
    if index < len(MODELS):
        return MODELS[index]
    return _bead_model(BEAD_BASES[index - len(MODELS)], 0)


def kernels_of(index: int):
    """The kernels module (rhs, tether_margins, body_radii, ...) of loop index ``index``."""
    return KERNELS[index] if index < len(KERNELS) else record(index).module


def bead_index(index: int) -> bool:
    """True for a bead chain's loop index (its state size is not a constant)."""
    return index >= len(MODELS)


def get_model(name: str, supported=None, what: str = "") -> Model:
    """The registered model called ``name``.

    Parameters
    ----------
    name : str
        Model name.
    supported : sequence of str, optional
        Names this caller can handle (default: every model).
    what : str, optional
        The feature asking, for the error message (e.g. ``"equilibrium"``).

    Returns
    -------
    Model

    Raises
    ------
    ValueError
        One line naming the model and the allowed values.
    """
    allowed = NAMES if supported is None else tuple(supported)
    if (chain := bead_split(name)) is not None and supported is None:
        return _bead_model(*chain)
    if name not in BY_NAME:
        raise ValueError(f"model = {name!r}: allowed values {', '.join(allowed)}")
    if name not in allowed:
        raise ValueError(f"model = {name!r}: {what or 'this'} supports {', '.join(allowed)} "
                         f"(not yet the {BY_NAME[name].geometry} / {BY_NAME[name].orbit}-orbit "
                         f"models)")
    return BY_NAME[name]


def model_index(name: str, supported=None, what: str = "") -> int:
    """Index of model ``name`` for the compiled kernels (see :func:`get_model`)."""
    return get_model(name, supported, what).index


#: the free-orbit twin of each circular model (``orbit = "free"``), from each free
#: module's generated ``CIRCULAR_TWIN``; ``printed`` has none (nor ``3d-exact-gravity``)
FREE_VARIANTS = {m.module.CIRCULAR_TWIN: m.name for m in MODELS if m.orbit == "free"}


def model_for_orbit(name: str, orbit: str = "circular") -> str:
    """The model that runs ``name`` in orbit mode ``orbit``.

    Parameters
    ----------
    name : str
        Requested model (``--model``).
    orbit : str, optional
        The satellite's ``orbit``: ``"circular"`` (``name`` itself) or ``"free"``
        (its free twin, :data:`FREE_VARIANTS`; a free model stays itself).

    Returns
    -------
    str
        Model name.

    Raises
    ------
    ValueError
        One line: a model with no free twin (``printed``, ``3d-exact-gravity``), or
        a free-orbit model asked to run a circular orbit (the run would decay while
        its satellite, summary and files said "circular").
    """
    m = get_model(name)
    if m.orbit == "free" and orbit != "free":
        twin = {v: k for k, v in FREE_VARIANTS.items()}.get(name)
        raise ValueError(f"model = {name!r} is a free-orbit model but the satellite's orbit = "
                         f"{orbit!r}: give the satellite orbit = 'free' "
                         f"(sat.replace(orbit='free'), --set orbit=free)"
                         + (f" or use model = {twin!r}" if twin else ""))
    if orbit != "free" or m.orbit == "free":
        return name
    if name not in FREE_VARIANTS:
        raise ValueError(f"model = {name!r} has no free-orbit variant (orbit = 'free'); "
                         f"allowed: {', '.join(FREE_VARIANTS)}")
    return FREE_VARIANTS[name]
