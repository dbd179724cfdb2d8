"""Find a figure printed in a doc and compare it with the value the code computes.

A :class:`Figure` names a doc, a chain of anchor strings and the quantity (a key
of :data:`tools.docnumbers.quantities.QUANTITIES`).  The anchors are
found one after the other; the number printed right after the last one is the
figure.  It agrees when the computed value, rounded to the printed precision
(decimals, or the mantissa's decimals in ``3.99e-3`` form), is the printed
number.  Unicode minus signs, thousands commas and a leading ``+`` are read.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

NUMBER = re.compile(r"[−+-]?\d[\d,]*(?:\.\d+)?(?:e[−+-]?\d+)?")
ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Figure:
    """One number printed in a doc and the quantity that computes it.

    Attributes
    ----------
    doc : str
        Path of the doc relative to the repository root (``docs/headlines.md``).
    at : tuple of str
        Anchor strings, found in turn; the figure is the number right after the last.
    key : str
        The quantity in ``QUANTITIES`` (its value in the doc's unit).
    slow : bool
        True when computing it runs simulations (the ``slow`` test tier).
    absolute : bool
        Compare the magnitude only (the doc prints ``±`` or the sign in words).
    rtol : float
        A relative tolerance the doc states beside the figure, for a count that moves
        with the last bits of the arithmetic (taut/slack switches located in a bounce);
        0: the printed precision only.
    """

    doc: str
    at: tuple
    key: str
    slow: bool = False
    absolute: bool = False
    rtol: float = 0.0


def parse(text: str) -> tuple:
    """Read a printed number.

    Parameters
    ----------
    text : str
        The number as printed (``−0.0069``, ``10,000``, ``3.9e-5``).

    Returns
    -------
    tuple of (float, float)
        The value and half a unit of its last printed digit (the rounding tolerance).

    Examples
    --------
    >>> parse("−3.99e-3")
    (-0.00399, 5e-06)
    """
    s = text.replace("−", "-").replace(",", "")
    mant, _, exp = s.partition("e")
    decimals = len(mant.partition(".")[2])
    scale = 10.0 ** int(exp) if exp else 1.0
    return float(s), 0.5 * 10.0 ** (-decimals) * scale


def locate(text: str, at) -> tuple:
    """Position and text of the number after the anchors ``at`` in ``text``.

    Parameters
    ----------
    text : str
        The doc.
    at : sequence of str
        Anchors, found one after the other; white space matches any white space.

    Returns
    -------
    tuple of (int, str)
        Offset of the number in ``text`` and the number as printed.

    Raises
    ------
    LookupError
        When an anchor is missing or no number follows the last one.
    """
    pos = 0
    for a in at:
        # a space in an anchor matches any run of white space (docs wrap their lines)
        m = re.compile(r"\s+".join(re.escape(w) for w in re.split(r"\s+", a))
                       + (r"\s*" if a[-1:].isspace() else "")).search(text, pos)
        if m is None:
            raise LookupError(f"anchor {a!r} not found (after offset {pos})")
        pos = m.end()
    pos += len(text[pos:]) - len(text[pos:].lstrip(" "))
    m = NUMBER.match(text, pos)
    if m is None:
        raise LookupError(f"no number right after {at[-1]!r}: {text[pos:pos + 30]!r}")
    return m.start(), m.group(0)


def agrees(printed: str, value: float, absolute: bool = False, rtol: float = 0.0) -> bool:
    """True when ``value`` rounds to the ``printed`` number at its printed precision.

    Parameters
    ----------
    printed : str
        The number as the doc prints it.
    value : float
        The computed value, in the doc's unit.
    absolute : bool, optional
        Compare magnitudes (the doc gives the sign in words).
    rtol : float, optional
        Also agree within ``rtol`` of the printed number (a tolerance the doc states).

    Returns
    -------
    bool
        Whether ``|value - printed|`` is within half a unit of the last printed digit
        (or ``rtol`` of the printed number).

    Examples
    --------
    >>> agrees("80.97", 80.9714), agrees("88", 80.9714)
    (True, False)
    """
    number, half = parse(printed)
    if absolute:
        number, value = abs(number), abs(value)
    bound = max(half * (1 + 1e-9) + 1e-12 * abs(number), rtol * abs(number))
    return math.isfinite(value) and abs(value - number) <= bound


def read(doc: str) -> str:
    """The text of a doc, by its path relative to the repository root."""
    return (ROOT / doc).read_text(encoding="utf-8")


# numbers that are not figures: page, equation, figure, table and section numbers,
# and everything in code blocks (commands and their options)
_NOT_FIGURES = re.compile(r"(?:p\.|pp\.|Eqs?|Figs?|Figures?|Tables?|Sec|issue|E|N|TB)\s*$")


def numbers_in(text: str) -> list:
    """Every number in prose and tables, outside code, headings and references.

    Parameters
    ----------
    text : str
        A markdown doc.

    Returns
    -------
    list of (int, str)
        Offset and printed text of each number (page, equation, figure and table
        numbers, code spans and blocks, and headings left out).
    """
    out, in_code = [], False
    offset = 0
    for line in text.splitlines(keepends=True):
        if line.lstrip().startswith("```"):
            in_code = not in_code
        elif not in_code and not line.lstrip().startswith("#"):
            stripped = re.sub(r"`[^`]*`|\([^)]*\.md\)|\d-\d+", lambda m: " " * len(m.group(0)),
                              line)
            for m in NUMBER.finditer(stripped):
                before = stripped[max(0, m.start() - 9):m.start()]
                if not _NOT_FIGURES.search(before) and not stripped[m.start() - 1:m.start()].isalpha():
                    out.append((offset + m.start(), m.group(0)))
        offset += len(line)
    return out
