"""Which parameters the ``--set``/``--scale`` options name, and refusing those a command sets.

A command that sets a parameter itself (a sweep axis, feasibility's altitude and air)
would otherwise apply the user's ``--set``/``--scale`` and then silently overwrite it:
:func:`refuse` stops such a command in one line before anything runs.
"""
from __future__ import annotations

import argparse
import re

from tethersim.cli import options


def named(args) -> list:
    """``[(flag, name), ...]`` of every ``--set``/``--scale`` as typed, e.g.
    ``("--scale", "E1")`` (names stripped; the values are parsed elsewhere)."""
    out = []
    for flag, attr in (("--set", "set"), ("--scale", "scale")):
        for text in getattr(args, attr, None) or ():
            out.append((flag, text.split("=", 1)[0].strip()))
    return out


def refuse(args, names, why: str) -> None:
    """Raise :class:`~tethersim.cli.options.UsageError` if a ``--set``/``--scale`` names
    one of ``names``; ``why`` completes "NAME: ..." (what sets it instead)."""
    for flag, name in named(args):
        if name in names:
            raise options.UsageError(f"{flag} {name}: {why(name) if callable(why) else why}")


class Once(argparse.Action):
    """An option that may be given once: a second one is refused (argparse keeps the last)."""

    def __call__(self, parser, namespace, values, option_string=None):
        if getattr(namespace, self.dest, None) is not None:
            parser.error(f"argument {option_string} given twice: give one grid (a comma list "
                         f"or START:STOP:COUNT)")
        setattr(namespace, self.dest, values)


def refuse_unused(args, sat, models, axes=()) -> None:
    """Refuse a ``--set``/``--scale`` (or a sweep axis in ``axes``) that every run of
    ``models`` ignores (:func:`tethersim.model.relevance.needs`): its run would be the
    same as without it.  One line naming the setting and what it needs."""
    from tethersim.model.relevance import needs
    given = ([(f"{flag} {name}", name) for flag, name in named(args)]
             + [(f"--{n} (sweep axis)", n) for n in axes])
    for label, name in given:
        why = [needs(name, sat, m) for m in models]
        if models and all(why):
            raise options.UsageError(f"{label}: {why[0]}")


def dash_hint(message: str) -> str:
    """argparse's "argument --X: expected one argument" with the way out: argparse takes a
    value starting with '-' (a negative number) for an option, ``--X=VALUE`` it does not."""
    m = re.fullmatch(r"argument (--[\w-]+)(?:/[^:]*)?: expected one argument", message)
    if not m:
        return message
    return (f"{message}; write {m.group(1)}=VALUE when VALUE starts with '-' (e.g. "
            f"{m.group(1)}=-1,0.004)")


def with_tethers_option(sat, args):
    """``--tethers MATERIAL:DIAMETER_MM[:KNOCKDOWN]`` applied to ``sat`` (one-line errors)."""
    from tethersim.model.materials import MATERIALS, with_tethers
    refuse(args, ("E1", "E2", "c1", "c2", "Fb1", "Fb2"),
           "--tethers sets it from the material; give one or the other")
    parts = args.tethers.split(":")
    usage = (f"--tethers {args.tethers!r}: expected MATERIAL:DIAMETER_MM[:KNOCKDOWN], "
             f"e.g. kevlar49:1 (materials: {', '.join(MATERIALS)})")
    if len(parts) not in (2, 3):
        raise options.UsageError(usage)
    try:
        numbers = [float(x) for x in parts[1:]]
    except ValueError:
        raise options.UsageError(usage) from None
    try:
        return with_tethers(sat, parts[0], numbers[0] * 1e-3, knockdown=numbers[1]
                            if len(numbers) > 1 else 1.0)
    except ValueError as exc:
        raise options.UsageError(f"--tethers: {exc}") from None
