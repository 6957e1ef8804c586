"""Qualify (bridge/exploration/qualify.py): an antecedent's consequent from
its weighted pours, by weighted vote or by the pour of largest weight."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.exploration.qualify import consequent as outcome


def test_outcome_weighted_vote_and_argmax():
    S = np.array([[0.9] * 9, [0.2] * 9, [0.3] * 9])
    w = np.array([0.5, 0.3, 0.4])
    weighted = outcome(S, w, "weighted")
    assert [o["holds"] for o in weighted["outcomes"]] == [False] * 9   # 0.7 of the weight fails
    assert weighted["outcomes"][0]["confidence_permille"] == round(1000 * 0.7 / 1.2)
    assert weighted["weight_mass_permille"] == 1200 and weighted["simulations"] == 3
    argmax = outcome(S, w, "argmax")
    assert argmax["sample"] == 0
    assert [o["holds"] for o in argmax["outcomes"]] == [True] * 9
    assert argmax["outcomes"][0]["confidence_permille"] == round(1000 * 0.5 / 1.2)
