"""Verdicts: what a pour's scores say, and the codes of an answer.

A pour's verdict on an expectation is qualitative: it holds where the
oracle's score (0 to 1, oracle/scoring.py) is above the verdict threshold
of theory/defaults.pl (`verdicts`). A theory's answer to a scene is coded
per expectation as HOLDS (it concludes the expectation), FAILS (its
negation) or UNKNOWN (neither, or uncertain). The learners, the
exploration, the reasoning and the evaluation all read both here.
"""
from __future__ import annotations

import numpy as np

from pantarhei.theory import defaults

#: The codes of an answer, per expectation.
HOLDS, FAILS, UNKNOWN = 1, 0, -1


def verdicts(scores: np.ndarray) -> np.ndarray:
    """The qualitative verdicts of scores: True where a score is above the
    verdict threshold (default(verdict_threshold_permille, _) of
    theory/defaults.pl, one half)."""
    return np.asarray(scores, dtype=float) > float(defaults()["verdict_threshold"])
