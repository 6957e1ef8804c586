"""Qualifying an explored antecedent: its consequent (one verdict per
expectation) from its weighted simulations."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.exploration.planes import MIN_WEIGHT
from pantarhei.theory.lexicon import load_vocabulary
from pantarhei.theory.option_table import option

#: Qualify modes, the choices of the option table's qualify row
#: (theory/defaults.pl): the weighted vote (default) and the paper's rule.
QUALIFY = option("qualify").choices


def consequent(S: np.ndarray, w: np.ndarray, mode: str) -> dict:
    """The consequent of one antecedent from its weighted simulations.

    argmax (the paper's rule): the verdicts (score > 1/2) of the simulation
    with the largest weight (the first of equals). weighted: per
    expectation, the verdict of the larger weight. The confidence of a
    verdict is the weighted share of simulations that agree with it."""
    expectations = load_vocabulary().expectation_names
    holds = verdicts(S)
    mass = float(w.sum())
    used = int((w > MIN_WEIGHT).sum())
    if mass <= 0:
        share = np.full(len(expectations), 0.5)
        mean = np.full(len(expectations), 0.5)
        chosen = share > 0.5
        best = -1
    else:
        share = (w[:, None] * holds).sum(axis=0) / mass
        mean = (w[:, None] * S).sum(axis=0) / mass
        best = int(np.argmax(w))
        chosen = holds[best] if mode == "argmax" else share > 0.5
    confidence = np.where(chosen, share, 1.0 - share)
    return {"simulations": used, "weight_mass_permille": int(round(1000 * mass)),
            "sample": best,
            "outcomes": [{"expectation": e, "holds": bool(chosen[k]),
                          "confidence_permille": int(round(1000 * confidence[k])),
                          "score_permille": int(round(1000 * mean[k]))}
                         for k, e in enumerate(expectations)]}
