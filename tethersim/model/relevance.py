"""Which satellite settings a run uses: a setting that the model or orbit ignores is named.

Some settings matter only to some runs: the solar and geomagnetic indices and the
epoch only to NRLMSISE-00 air, the re-entry altitude only to a free orbit (a circular
one is held at its altitude), and the out-of-plane start and the end-body moments only
to the 3-D models.  Accepting them silently would give a run identical to one
without them; :func:`needs` says what such a setting needs instead.
"""
from __future__ import annotations

from tethersim.model.presets import INITIAL_3D_KEYS
from tethersim.model.registry import get_model, model_for_orbit

MSIS_ONLY = ("f107", "f107a", "ap", "epoch")
FREE_ONLY = ("reentry_altitude",)  # eccentricity and j2 on a circular orbit are refused
THREE_D_ONLY = ("inertia", "I1", "I2", *INITIAL_3D_KEYS)


def needs(name: str, sat, model: str) -> str | None:
    """What setting ``name`` (a ``--set`` name) needs to matter in a run of ``model``.

    Parameters
    ----------
    name : str
        A parameter or option name (tethersim.model.params).
    sat : Satellite
        The satellite as it will run (its orbit and atmosphere).
    model : str
        The requested model (a free orbit runs its free twin).

    Returns
    -------
    str or None
        None when the run uses ``name``; else one phrase, e.g. ``"ignored by
        atmosphere = 'vallado': needs atmosphere = nrlmsise00"``.
    """
    if name in MSIS_ONLY and sat.atmosphere != "nrlmsise00":
        return (f"ignored with atmosphere = {sat.atmosphere!r} (only NRLMSISE-00 uses it): "
                f"needs atmosphere = nrlmsise00")
    if name in FREE_ONLY and sat.orbit != "free":
        return (f"ignored on orbit = {sat.orbit!r} (held at its altitude, it never "
                f"re-enters): needs orbit = free")
    if name in THREE_D_ONLY:
        m = get_model(model_for_orbit(model, sat.orbit))
        if m.geometry != "3d":
            return f"ignored by the planar model {m.name!r}: needs a 3-D model (--model 3d, ...)"
    return None
