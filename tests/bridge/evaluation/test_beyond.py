"""bridge/evaluation/beyond.py: a theory written by hand (pouring from the
side or far away spills), asked by SWI-Prolog, on the interaction pairs
and the random scenes keyed by the synthetic oracle; the headline rows
against their targets; the report's section."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.evaluation.beyond import beyond_figures, beyond_headline, beyond_section
from pantarhei.bridge.evaluation.pipeline import Evaluation
from pantarhei.bridge.theories.loading import load
from pantarhei.oracle.generative import to_dict
from pantarhei.oracle.synthetic import scores

HAND = """rule(d, defeasible, no_spill).
rule(side, defeasible, neg(no_spill)).
body(side, pour_to_side).
rule(far, defeasible, neg(no_spill)).
body(far, pour_far_away).
sup(side, d).
sup(far, d).
"""


def run(label: str, P: np.ndarray) -> np.ndarray:
    return np.array([scores(to_dict(p)) for p in P])


def test_a_hand_theory_on_the_pairs_and_the_random_scenes(tmp_path):
    path = tmp_path / "hand.pl"
    path.write_text(HAND)
    f = beyond_figures(load([str(path)]), run, 1)
    assert f["interactions"]["scenes"] == 64 and f["random"]["scenes"] == 40
    i = f["interactions"]
    # it says something only of no_spill, and is sure of it: no likelihoods to calibrate
    assert 0 < i["coverage"] < 0.2 and i["calibration"] is None
    assert i["contrast"] > 0 and 0 <= i["contrast_accuracy"] <= 1
    ev = Evaluation("t", "synthetic", {}, 24, beyond=f)
    rows = beyond_headline(ev)
    assert [r[2] for r in rows] == ["at least 90%", "at most 0.06", "none", "at least 95%",
                                    "at most 0.05"]
    assert rows[1][3] is False          # no calibration: not met
    assert "| pairs of pose propositions that may interact | 64 |" in "\n".join(
        beyond_section(ev, tmp_path))


def test_the_targets_of_the_headline():
    good = {"scenes": 64, "contrast": 60, "contrast_coverage": 1.0, "contrast_accuracy": 0.92,
            "calibration": 0.05, "confident_errors": 0}
    ev = Evaluation("t", "synthetic", {}, 24, beyond={"interactions": good, "random": {
        **good, "scenes": 40, "contrast_accuracy": 0.96, "calibration": 0.04}})
    assert all(met for *_, met in beyond_headline(ev))
    ev.beyond["interactions"]["confident_errors"] = 1
    ev.beyond["random"]["contrast_accuracy"] = 0.94
    assert [met for *_, met in beyond_headline(ev)] == [True, True, False, False, True]
    assert beyond_headline(Evaluation("t", "synthetic", {}, 24)) == []
