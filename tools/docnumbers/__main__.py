"""Print each listed doc figure beside its computed value, then coverage per doc."""
from __future__ import annotations

import sys

from tools.docnumbers import FIGURES, evaluate, locate, numbers_in, read


def main(argv=None) -> int:
    """Check the figures; return 1 when one disagrees.  ``--slow`` adds simulated ones."""
    argv = sys.argv[1:] if argv is None else argv
    slow = "--slow" in argv
    bad = 0
    for fig in FIGURES:
        if fig.slow and not slow:
            continue
        try:
            printed, value, ok = evaluate(fig)
        except LookupError as e:
            printed, value, ok = f"missing: {e}", float("nan"), False
        bad += not ok
        print(f"{'ok ' if ok else 'BAD'} {fig.doc:<24} {fig.key:<28} printed {printed:>10}  "
              f"computed {value:.6g}")
    docs = sorted({f.doc for f in FIGURES} | {"docs/metrics.md", "docs/sweeps.md",
                                             "docs/errata.md", "docs/numbers.md"})
    print("\ncoverage: numbers in prose and tables (not page, equation or figure numbers, "
          "not code) that a figure checks")
    for doc in docs:
        text = read(doc)
        at = {locate(text, f.at)[0] for f in FIGURES if f.doc == doc}
        nums = numbers_in(text)
        print(f"  {doc:<24} {sum(o in at for o, _ in nums):4d} of {len(nums):4d}")
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
