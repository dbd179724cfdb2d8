"""The progress bar of simulate()'s runs (tqdm), moved out of engine/simulate.py."""
from __future__ import annotations

from tqdm.auto import tqdm


def progress_bar(total, desc, progress, factory=tqdm):
    """A tqdm bar over ``total`` orbits (None: shown after a second; False: never)."""
    return factory(total=total, desc=desc, unit="orbit", delay=0.0 if progress else 1.0,
                disable=(progress is False), leave=False,
                bar_format="{l_bar}{bar}| {n:.1f}/{total:.1f} orbits [{elapsed}<{remaining}]")


def advance(bar, orbits: float) -> None:
    """Move the bar to ``orbits`` done, never past its total: the chunks' float sums
    overshoot it by an ulp or so, and tqdm then warns 'clamping frac'."""
    bar.update(max(0.0, min(orbits, bar.total) - bar.n))
