"""End-body inertias of the 3-D models: the Satellite fields ``inertia``, ``I1``, ``I2``.

The 3-D models (docs/three-d.md) give the tip-mass (body 1) and the bus (body 2)
principal moments about their own centres, on the boom's roll, pitch and yaw
axes (yaw: about the boom).  Per body:

* ``inertia = "boxes"`` (default): the thesis's Eq 4.4, a cube of frontal area A,
  I = m · 2A / 12 about every axis;
* ``inertia = "points"``: all zero (point masses; yaw about the boom is then no
  degree of freedom, docs/three-d.md);
* ``I1`` / ``I2`` = (roll, pitch, yaw) [kg m²]: that body's moments, whatever
  ``inertia`` says (``inertia`` sets the default of a body without an override).

A rigid body's principal moments are non-negative and obey the triangle
inequality, each at most the sum of the other two (I_x = ∫(y² + z²) dm, ...);
zero on every axis (a point) is allowed.  A zero yaw moment therefore forces
equal roll and pitch moments of that body, which the kernels' point-mass branch
relies on (its ψ equation would otherwise be dropped with a residual
∝ I_roll − I_pitch).  The planar models ignore these fields (their pitch inertia
is the point masses', thesis Eq 3.30).
"""
from __future__ import annotations

import math

MODES = ("boxes", "points")
AXES = ("roll", "pitch", "yaw")
UNIT = "kg m^2"
# relative slack of the triangle inequality: rounding of the user's decimal digits only
TRIANGLE_RTOL = 1e-12


def _fail(sat, text: str):
    from tethersim.model.satellite import SatelliteError
    raise SatelliteError(f"{sat._where()}{text}")


def _shown(value) -> str:
    text = repr(value)
    return text if text.isprintable() else ascii(value)


def moments(value, name: str = "I1", fail=None) -> tuple:
    """Check one body's override and return it as a tuple of three floats.

    Parameters
    ----------
    value : sequence of 3 numbers
        (roll, pitch, yaw) [kg m²].
    name : str, optional
        The field named in an error (``I1`` or ``I2``).
    fail : callable, optional
        Called with the one-line message instead of raising ``ValueError``.

    Returns
    -------
    tuple of float

    Raises
    ------
    ValueError
        One line naming ``name``: not three finite numbers >= 0, or the triangle
        inequality of principal moments broken.

    Examples
    --------
    >>> moments([1, 2, 3])
    (1.0, 2.0, 3.0)
    """
    def bad(text):
        msg = f"{name} = {_shown(value)}: {text}"
        if fail is not None:
            fail(msg)
        raise ValueError(msg)

    shape = "must be 3 numbers [roll, pitch, yaw] in kg m^2, each finite and >= 0"
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__") \
            or len(value) != 3:
        bad(shape)
    out = []
    for v in value:
        if isinstance(v, bool) or not isinstance(v, (int, float)) and not hasattr(v, "__float__"):
            bad(shape)
        try:
            f = float(v)
        except (TypeError, ValueError, OverflowError):
            bad(shape)
        if not (math.isfinite(f) and f >= 0):
            bad(shape)
        out.append(f)
    total = sum(out)
    for axis, v in zip(AXES, out):
        others = total - v
        if v > others + TRIANGLE_RTOL * total:
            rest = " + ".join(a for a in AXES if a != axis)
            bad(f"{axis} {v:g} > {rest} {others:g} {UNIT}: a rigid body's principal moments "
                f"obey the triangle inequality, each <= the sum of the other two")
    return tuple(out)


def check(sat) -> None:
    """Validate (and normalise to tuples) ``inertia``, ``I1``, ``I2`` of ``sat`` in place.

    Parameters
    ----------
    sat : Satellite
        A satellite being created (frozen: normalised values are set with
        ``object.__setattr__``).

    Raises
    ------
    tethersim.model.satellite.SatelliteError
        One line naming the field and what is allowed.
    """
    if not isinstance(sat.inertia, str) or sat.inertia not in MODES:
        _fail(sat, f"inertia = {_shown(sat.inertia)}: allowed values {', '.join(MODES)}")
    for name in ("I1", "I2"):
        value = getattr(sat, name)
        if value is not None:
            object.__setattr__(sat, name, moments(value, name, lambda m: _fail(sat, m)))


def body_inertias(sat) -> dict:
    """Principal moments [kg m²] of the tip-mass (1) and bus (2) about their centres.

    Parameters
    ----------
    sat : Satellite
        Its ``inertia``, ``I1``, ``I2`` (this module's docstring).

    Returns
    -------
    dict
        ``{"I1_roll": ..., "I1_pitch": ..., "I1_yaw": ..., "I2_roll": ..., ...}``,
        the names of the 3-D models' parameters.

    Examples
    --------
    >>> import tethersim
    >>> sat = tethersim.load_preset("satI")
    >>> round(body_inertias(sat)["I2_pitch"], 3)  # 105 kg x 2 x 1.05 m² / 12
    18.375
    >>> body_inertias(sat.replace(inertia="points", I2=(1, 2, 3)))["I2_yaw"]
    3.0
    """
    out = {}
    for k, m, area, given in ((1, sat.m1, sat.A1, sat.I1), (2, sat.m2, sat.A2, sat.I2)):
        if given is not None:
            values = given
        elif sat.inertia == "points":
            values = (0.0, 0.0, 0.0)
        else:
            values = (m * 2 * area / 12,) * 3  # thesis Eq 4.4
        out.update({f"I{k}_{axis}": float(v) for axis, v in zip(AXES, values)})
    return out

