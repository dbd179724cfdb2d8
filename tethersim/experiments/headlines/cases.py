"""The thesis's SatI headline claims as cases, and each claim as a test on a run's row."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from tethersim.analysis.classify import CLASSES, FAILED, UPSIDE_DOWN
from tethersim.analysis.metrics import SETTLING_TOL
from tethersim.model.params import edge_value, with_values
from tethersim.model.satellite import Satellite

MODELS = ("derived", "printed", "objective-damper")
SCHEMES = ("rk4-thesis", "rk4-half", "rk4-quarter", "dop853")
STEP_DIVISORS = {"rk4-thesis": 1, "rk4-half": 2, "rk4-quarter": 4}
NEAR = math.pi / 4  # rad: an equilibrium counts as "near" its guess within this
CONTINUATION_JUMP = 0.7  # rad: a continued branch that jumps further is counted as lost
AGREE_TOL = 0.05  # rad: two schemes agree if θ differs by less than the ±0.05 band (p. 5-18)
SETTLES_IN = (36 * 3600.0, 72 * 3600.0)  # s: "a little over two days" (p. 5-7), <= 3 days (p. 5-6)

VERDICTS = ("survives", "does not survive", "depends on the damper model", "artefact of the step",
            "undecided: run longer")


@dataclass(frozen=True)
class Headline:
    """One thesis claim about SatI and the run that tests it.

    set_values: parameters set first, in edge units (c in N s/m; the moduli
      study ran with c = 0, p. 5-1); scale: factors applied next;
    periods, steps: the thesis's run (step = periods x orbital period / steps);
    check: the claim as a test on a run's row (see :func:`claim_holds`).
    """

    name: str
    page: str
    claim: str
    check: str
    scale: dict = field(default_factory=dict)
    set_values: dict = field(default_factory=dict)
    periods: float = 50.0
    steps: int = 10_000

    def satellite(self, sat: Satellite) -> Satellite:
        s = with_values(sat, self.set_values) if self.set_values else sat
        if self.scale:
            s = with_values(s, {k: edge_value(s, k) * f for k, f in self.scale.items()})
        return s

    def step(self, sat: Satellite) -> float:
        """The thesis's RK4 step [s] for this run."""
        return self.periods * sat.period / self.steps

    @property
    def change(self) -> str:
        parts = [f"{k} = {v:g}" for k, v in self.set_values.items()]
        parts += [f"{k} x{f:g}" for k, f in self.scale.items()]
        return ", ".join(parts) or "none"


UNDAMPED = {"c1": 0.0, "c2": 0.0}  # Sec 5.1: "the damping coefficient was held constant at zero"
MODULI_RUN = {"set_values": UNDAMPED, "periods": 5.0, "steps": 1500}  # 17.70 s/step (p. 5-1)

HEADLINES = (
    Headline("nominal", "5-7", "nominal damping: mean pitch 0.02 rad, settled (±0.05 rad) "
             "after a little over two days", "settles"),
    Headline("moduli-nominal", "5-2, 5-3", "nominal moduli, c = 0: pitch oscillates between "
             "±π/6 without growing, mean 2.36° (0.041 rad)", "bounded", **MODULI_RUN),
    Headline("E1+50%", "5-4", "E1 only 50 % above nominal: the satellite tumbles end over end "
             "(Fig 5.4)", "tumbles", scale={"E1": 1.5}, **MODULI_RUN),
    Headline("E1-10%", "5-5", "a modulus about 10 % off nominal: pitch oscillates about ≈ π/2 "
             "(Fig 5.5)", "quarter", scale={"E1": 0.9}, **MODULI_RUN),
    Headline("E1+10%", "5-5", "a modulus about 10 % off nominal: pitch oscillates about ≈ π/2 "
             "(Fig 5.5)", "quarter", scale={"E1": 1.1}, **MODULI_RUN),
    Headline("E2-10%", "5-5", "a modulus about 10 % off nominal: pitch oscillates about ≈ π/2 "
             "(Fig 5.5)", "quarter", scale={"E2": 0.9}, **MODULI_RUN),
    Headline("E2+10%", "5-5", "a modulus about 10 % off nominal: pitch oscillates about ≈ π/2 "
             "(Fig 5.5)", "quarter", scale={"E2": 1.1}, **MODULI_RUN),
    Headline("damping-x10", "5-13", "nominal damping x10: steady pitch 3.18 rad, upside down "
             "(Fig 5.14)", "upside_down", scale={"c1": 10.0, "c2": 10.0}),
)
BY_NAME = {h.name: h for h in HEADLINES}

# (name, page, claim, lower case, raised case, claimed sign of d(mean pitch)/d(modulus))
TRENDS = (
    ("E1 trend", "5-5", "raising E1 lowers the mean pitch", "E1-10%", "E1+10%", -1),
    ("E2 trend", "5-5, 5-6", "raising E2 raises the mean pitch", "E2-10%", "E2+10%", +1),
)


# --- the claims as tests on a row ---------------------------------------------------
def yes_no(holds: dict) -> str:
    """{model: claim holds (True, False, None: undecided)} as "derived yes, printed no"."""
    word = {True: "yes", False: "no", None: "undecided"}
    return ", ".join(f"{m} {word[None if ok is None else bool(ok)]}" for m, ok in holds.items())


def claim_holds(check: str, row: dict) -> bool | None:
    """Whether a run (its row) shows what the thesis claims.

    settles      class "stable", settling time in SETTLES_IN (36-72 h) and
                 |mean pitch| <= 0.05 rad (p. 5-7: 0.02 rad, a little over two days)
    bounded      no pass over ±π and |mean pitch| <= 0.1 rad (p. 5-2: 0.041 rad)
    tumbles      at least one full revolution: max θ − min θ >= 2π (p. 5-4)
    quarter      π/4 <= |mean pitch| <= 3π/4, "about ninety degrees off" (p. 5-5)
    upside_down  class "upside_down", |θ_ss| > 3π/4 (p. 5-13: 3.18 rad)

    Returns None (undecided) for a run too short to decide its class
    (``row["decided"]`` false, tethersim.analysis.metrics.long_enough), unless
    what it already shows decides the claim.
    """
    if row["class"] == CLASSES[FAILED]:
        return False
    if not row.get("decided", True):  # too short to decide (metrics.long_enough)
        return _short_run_claim(check, row)
    mean = row["mean_pitch"]
    if check == "settles":
        return (row["class"] == "stable" and SETTLES_IN[0] / 3600 <= row["settling_h"]
                <= SETTLES_IN[1] / 3600 and abs(mean) <= SETTLING_TOL)
    if check == "bounded":
        return (not row["tumbled"]) and abs(mean) <= 0.1
    if check == "tumbles":
        return row["revolutions"] >= 1.0
    if check == "quarter":
        return math.pi / 4 <= abs(mean) <= 3 * math.pi / 4
    if check == "upside_down":
        return row["class"] == CLASSES[UPSIDE_DOWN]
    raise ValueError(f"unknown claim check {check!r}")


def _short_run_claim(check: str, row: dict) -> bool | None:
    """A claim on a run too short to decide: only what already happened decides it.

    A full turn shows "tumbles" and refutes "bounded"; every other claim (and
    those two, when nothing happened yet) waits for a run long enough: None.
    """
    if check == "tumbles" and row["revolutions"] >= 1.0:
        return True
    if check == "bounded" and row["tumbled"]:
        return False
    return None
