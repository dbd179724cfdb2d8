"""Model variants available to the runtime (all produced by derive/).

derived           default: the clean derivation of the thesis model
printed           Eqs 3.48-3.50 exactly as printed (errata in docs/errata.md)
exact-gravity     no binomial expansion of 1/|r|
objective-damper  Kelvin-Voigt tether dampers (stretch rate only)
"""
from __future__ import annotations

from tethersim.generated.dispatch import MODEL_NAMES

DEFAULT_MODEL = "derived"


def model_index(model: str) -> int:
    """Index of a model name for the jitted dispatcher; clear error if unknown."""
    try:
        return MODEL_NAMES.index(model)
    except ValueError:
        raise ValueError(f"model = {model!r}: allowed values {', '.join(MODEL_NAMES)}") from None
