"""Figures printed in docs/*.md and README.md, computed with the code and compared.

``python -m tools.docnumbers`` prints every listed figure beside its
computed value (``--slow`` adds those that need simulations) and, per doc, how
many of the numbers in its prose and tables the list covers.
"""
from tools.docnumbers.check import Figure, agrees, locate, numbers_in, parse, read
from tools.docnumbers.figures import FIGURES, QUANTITIES

__all__ = ["FIGURES", "QUANTITIES", "Figure", "agrees", "evaluate", "locate", "numbers_in",
           "parse", "read"]


def evaluate(fig: Figure) -> tuple:
    """(printed, computed, agrees) for one figure.

    Parameters
    ----------
    fig : Figure
        Where the figure is printed and which quantity computes it.

    Returns
    -------
    tuple of (str, float, bool)
        The number as printed, the computed value, and whether they agree.
    """
    _, printed = locate(read(fig.doc), fig.at)
    value = float(QUANTITIES[fig.key]())
    return printed, value, agrees(printed, value, fig.absolute, fig.rtol)
