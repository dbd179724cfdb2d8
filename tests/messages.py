"""What a refusal looks like to a user: one line, no traceback (issue 19)."""
from __future__ import annotations


def one_line(text: str) -> str:
    """The only line of ``text`` (stderr of a refused command, or an exception's message);
    fails on a traceback or on more than one line."""
    assert "Traceback" not in text
    lines = text.strip().splitlines()
    assert len(lines) == 1, text
    return lines[0]
