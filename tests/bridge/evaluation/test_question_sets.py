"""bridge/evaluation/question_sets.py: the interaction questions and the
random scenes, keyed by the synthetic oracle's pours (whose answers are
known: pouring from the side or far away spills, a source upright pours
nothing)."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.verdicts import FAILS, HOLDS
from pantarhei.bridge.evaluation.question_sets import (confident_errors,
                                                       interaction_questions, keyed,
                                                       random_scenes, theory_behaviours)
from pantarhei.bridge.learning.general_rules import General, GeneralRule
from pantarhei.bridge.evaluation.questions import Question
from pantarhei.bridge.learning.askable import valid
from pantarhei.oracle.generative import to_dict
from pantarhei.oracle.synthetic import scores
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().expectation_names


def run(P: np.ndarray) -> np.ndarray:
    return np.array([scores(to_dict(p)) for p in P])


def test_the_interaction_questions_are_valid_pairs_of_pose_propositions():
    asked = interaction_questions()
    props = load_vocabulary().propositions
    assert len(asked) == 64 and len({q.antecedent for q in asked}) == 64
    for q in asked:
        assert len(q.antecedent) == 2 and valid(q.antecedent)
        assert {props[p].dimension for p in q.antecedent} <= {
            "pour_height", "pour_alignment", "pour_tilt", "approach_vertical",
            "approach_horizontal", "approach_speed"}


def test_random_scenes_are_seeded_valid_and_of_their_sizes():
    a, b = random_scenes(12, (5, 8), 3), random_scenes(12, (5, 8), 3)
    assert a == b and a != random_scenes(12, (5, 8), 4)
    assert all(5 <= len(q.antecedent) <= 8 and valid(q.antecedent) for q in a)


def test_keys_depart_from_the_ordinary_pour_where_the_pours_do():
    asked = [Question("from the side", ("pour_to_side",)), Question("light", ("light_liquid",))]
    ks = keyed("two", asked, run, n=12)
    spill = NAMES.index("no_spill")
    assert ks.clear[0, spill] and not ks.key[0, spill] and ks.contrast[0, spill]
    # the light liquid pours as the ordinary pour: nothing departs
    assert not ks.contrast[1].any()
    # answering the side's spill right, and for sure the other way: one confident error
    pred = np.where(ks.key, HOLDS, FAILS)
    lik = ks.key.astype(float)
    m = ks.measures(pred, lik)
    assert m["contrast_accuracy"] == 1.0 and m["confident_errors"] == 0
    lik[0, spill], pred[0, spill] = 0.9, HOLDS
    m = ks.measures(pred, lik)
    assert m["contrast_accuracy"] < 1.0 and m["confident_errors"] == 1


def test_a_confident_error_is_a_sure_likelihood_on_the_wrong_side():
    key = np.array([[True, False, True, True]])
    clear = np.array([[True, True, True, False]])
    lik = np.array([[0.1, 0.85, 0.55, 0.0]])
    # 0.1 for a key that holds, 0.85 for one that fails; 0.55 is unsure; the
    # last key is not clear
    assert confident_errors(lik, key, clear) == 2
    assert confident_errors(np.full((1, 4), np.nan), key, clear) == 0


def test_behaviours_in_a_theory_are_its_decided_answers_for_its_bodies():
    """Defaults that all hold, a side pour that spills, a far pour that
    spills and misses the bowl, and a light liquid whose spill is unsure:
    three behaviours (the ordinary pour's, the side's, the far pour's); the
    light liquid's answer is not decided."""
    sure = lambda i, body, e, holds, c=0.95: GeneralRule(f"g{i}_{e}", body, e, holds, 0, 0, c, 1)  # noqa: E731
    rules = [GeneralRule(f"g0_{e}", (), e, True, 0, 0, 0.95, 0) for e in NAMES]
    rules += [sure(1, ("pour_to_side",), "no_spill", False),
              sure(2, ("pour_far_away",), "no_spill", False),
              sure(3, ("pour_far_away",), "liquid_enters_destination", False),
              sure(4, ("light_liquid",), "no_spill", False, 0.55)]
    assert theory_behaviours(General(rules=rules)) == 3
