"""The four sets of generalized coordinates: planar or 3-D, on a circular or a free orbit.

Each is a :class:`derive.model.Coordinates` record: the state and parameter
symbols of the generated kernels (explicit orders, derive/symbols.py,
derive/three_d/symbols3d.py, derive/orbit.py, derive/three_d/free3d.py), the
kinematics and the Lagrange step of those coordinates.
"""
from __future__ import annotations

from . import orbit, pipeline, symbols
from .kinematics import planar_kinematics
from .model import Coordinates
from .three_d import free3d, pipeline3d, symbols3d
from .three_d.kinematics3d import kinematics_3d

PLANAR = Coordinates(
    "planar", "circular", symbols.STATE_NAMES, symbols.STATE_UNITS, symbols.STATE_SYMBOLS,
    symbols.ACCELERATION_SYMBOLS, pipeline.Q_SYMBOLS, symbols.PARAMETERS, symbols.TETHER_LENGTHS,
    planar_kinematics, symbols.state_substitution, pipeline.equations)

THREE_D = Coordinates(
    "3d", "circular", symbols3d.STATE_NAMES, symbols3d.STATE_UNITS, symbols3d.STATE_SYMBOLS,
    symbols3d.ACCELERATION_SYMBOLS, pipeline3d.Q_SYMBOLS, symbols3d.PARAMETERS,
    symbols3d.TETHER_LENGTHS, kinematics_3d, symbols3d.state_substitution, pipeline3d.equations)

FREE = Coordinates(
    "planar", "free", orbit.FREE_STATE_NAMES, orbit.FREE_STATE_UNITS, orbit.FREE_STATE_SYMBOLS,
    orbit.FREE_ACCELERATION_SYMBOLS, orbit.FREE_Q_SYMBOLS, orbit.FREE_PARAMETERS,
    symbols.TETHER_LENGTHS, orbit.free_kinematics, orbit.free_state_substitution,
    orbit.equations, expand_tethers=True)

FREE_3D = Coordinates(
    "3d", "free", free3d.FREE3D_STATE_NAMES, free3d.FREE3D_STATE_UNITS,
    free3d.FREE3D_STATE_SYMBOLS, free3d.FREE3D_ACCELERATION_SYMBOLS, free3d.FREE3D_Q_SYMBOLS,
    free3d.FREE3D_PARAMETERS, symbols.TETHER_LENGTHS, free3d.free3d_kinematics,
    free3d.free3d_substitution, free3d.equations, expand_tethers=True)

ALL = (PLANAR, THREE_D, FREE, FREE_3D)
