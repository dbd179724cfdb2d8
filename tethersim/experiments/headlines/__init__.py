"""The thesis's headline results for SatI, faithful (its RK4 step) and converged.

cases     the claims (Headline, HEADLINES, BY_NAME, TRENDS) and claim_holds
runs      equilibria near each claimed state and the runs of every case and scheme
verdicts  survives / does not survive / depends on the damper model / step artefact
scans     damping factor, RK4 step and initial-trail scans of the damping x10 case

Details and numbers: docs/headlines.md.
"""
from tethersim.experiments.headlines.cases import (
                                                  AGREE_TOL,
                                                  BY_NAME,
                                                  CONTINUATION_JUMP,
                                                  HEADLINES,
                                                  MODELS,
                                                  MODULI_RUN,
                                                  NEAR,
                                                  SCHEMES,
                                                  SETTLES_IN,
                                                  STEP_DIVISORS,
                                                  TRENDS,
                                                  UNDAMPED,
                                                  VERDICTS,
                                                  Headline,
                                                  claim_holds,
                                                  yes_no,
)
from tethersim.experiments.headlines.runs import case_analysis, row_of, run_case, run_headlines
from tethersim.experiments.headlines.scans import (
                                                  DAMPING_FACTORS,
                                                  damper_torque_at_rest,
                                                  damping_scan,
                                                  initial_scan,
                                                  step_scan,
)
from tethersim.experiments.headlines.verdicts import format_verdicts, verdicts

__all__ = ["AGREE_TOL", "BY_NAME", "CONTINUATION_JUMP", "DAMPING_FACTORS", "HEADLINES", "MODELS",
           "MODULI_RUN", "NEAR", "SCHEMES", "SETTLES_IN", "STEP_DIVISORS", "TRENDS", "UNDAMPED",
           "VERDICTS", "Headline", "case_analysis", "claim_holds", "yes_no", "damper_torque_at_rest",
           "damping_scan", "format_verdicts", "initial_scan", "row_of", "run_case",
           "run_headlines", "step_scan", "verdicts"]
