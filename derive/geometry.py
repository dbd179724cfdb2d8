"""Geometry kernels every generated model carries, whatever its coordinates.

The engine needs two facts about a model's state that it must not hard-code
for one layout (planar, free orbit, 3-D):

``tether_margins(y, p, g)``  g[j] = λ_j − l_j0 [m], tether j taut when g[j] > 0
                             (Eqs 3.39-3.42): where the right-hand side switches
``body_radii(y, p)``         (|R_1|, |R_2|, |R_3|) [m] of tip-mass, bus and balloon
                             from Earth's centre (Eqs 3.10-3.12), a tuple: each
                             body's own altitude, with no array to allocate

Each emitter (planar codegen, free-orbit codegen, 3-D codegen) passes the
components of the three body positions and the two tether vectors, printed
with its own printer; the lengths are written with ``math.hypot`` in the plane
(as the engine always computed them, so switch location is bit-identical) and
``math.sqrt`` of the sum of squares in 3-D.
"""
from __future__ import annotations

from .printer import INDENT, kernel


def _norm(components) -> str:
    if len(components) == 2:
        return f"math.hypot({components[0]}, {components[1]})"
    return "math.sqrt(" + " + ".join(f"({c})**2" for c in components) + ")"


def geometry_source(unpack: list, tethers, rests, bodies, note: str = "") -> list:
    """Source lines of ``tether_margins`` and ``body_radii``.

    Parameters
    ----------
    unpack : list of str
        Lines (indented once) that bind the state and parameter names (each
        kernel keeps those it reads).
    tethers : sequence of sequence of str
        Printed components of each tether vector (balloon to its end body).
    rests : sequence of str
        Code names of the tethers' rest lengths (l10, l20).
    bodies : sequence of sequence of str
        Printed components of each body's position from Earth's centre.
    note : str
        Where the positions come from (an equation or module), for the docstrings.
    """
    i1 = INDENT
    margins = kernel(
        ["@njit(cache=True, inline=\"always\")", "def tether_margins(y, p, g):",
         f'{i1}"""g[j] = λ_j − l_j0 [m]: tether j is taut when g[j] > 0 (Eqs 3.39-3.42)."""'],
        unpack, [f"{i1}g[{j}] = {_norm(c)} - {rest}" for j, (c, rest) in enumerate(zip(tethers, rests))])
    radii = kernel(
        ["@njit(cache=True, inline=\"always\")", "def body_radii(y, p):",
         f'{i1}"""(|R_1|, |R_2|, |R_3|) [m]: tip-mass, bus, balloon from Earth\'s centre.',
         "", f'{i1}Positions{note}.', f'{i1}"""'],
        unpack, [f"{i1}return ({', '.join(_norm(c) for c in bodies)})"])
    return margins + ["", ""] + radii
