"""One orbit per run at the command line: the orbit a free-orbit ``--model`` implies.

A free-orbit model (``free``, ``3d-free``, ...) runs a free orbit.  Every command that
takes ``--model`` or ``--models`` resolves its satellite through
:func:`tethersim.cli.options.satellite`, which calls :func:`orbit_of_models`, so the
satellite's orbit (and so the summary, files and plots, and the free orbit's default
per-body air) is the one the run has.  The library refuses the contradiction itself
(:func:`tethersim.model.registry.model_for_orbit`).
"""
from __future__ import annotations

from tethersim.cli import options


def _requested_models(args) -> tuple:
    if getattr(args, "models", None):
        return options.models(args)
    return (args.model,) if getattr(args, "model", None) else ()


def _set_orbit(args) -> str | None:
    """The last ``--set orbit=...`` value as typed (stripped), or None."""
    given = None
    for s in getattr(args, "set", None) or ():
        name, _, value = s.partition("=")
        if name.strip() == "orbit":
            given = value.strip()
    return given


def orbit_of_models(args, sat):
    """``sat`` in the orbit of the requested free-orbit models: one orbit per run.

    A free-orbit model (``--model free``, ``3d-free``, ...) runs a free orbit, so
    without an explicit ``--set orbit=...`` the satellite gets ``orbit = "free"``
    before anything runs (its summary, files and plots then say so); with an
    explicit ``--set orbit=circular`` the command is refused.

    Raises
    ------
    tethersim.cli.options.UsageError
        ``--set orbit=circular`` with a free-orbit model (one line).
    tethersim.model.satellite.SatelliteError
        The satellite cannot fly a free orbit (e.g. its re-entry altitude).
    """
    from tethersim.model.registry import BY_NAME, FREE_VARIANTS
    free = [m for m in _requested_models(args) if BY_NAME[m].orbit == "free"]
    if not free or sat.orbit == "free":
        return sat
    flag = "--models" if getattr(args, "models", None) else "--model"
    if _set_orbit(args) is not None:
        twins = {v: k for k, v in FREE_VARIANTS.items()}
        hint = (f", or use {flag} {twins[free[0]]} for the circular orbit" if free[0] in twins
                else "")
        raise options.UsageError(f"{flag} {free[0]} with --set orbit={sat.orbit}: a free-orbit "
                                 f"model runs a free orbit; drop --set orbit={sat.orbit}{hint}")
    try:
        return sat.replace(orbit="free")
    except ValueError as exc:
        raise type(exc)(f"{flag} {free[0]} (orbit = 'free'): {exc}") from None
