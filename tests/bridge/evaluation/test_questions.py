"""bridge/evaluation/questions.py: the questions a person would type, read
from questions.json in file order with their propositions sorted, each a
valid antecedent; and the pours sampled for each question's key (n per
question, seeded, each drawn for its own question)."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from pantarhei.bridge.evaluation import questions as Q
from pantarhei.bridge.evaluation.questions import KEY_POURS, Question, question_pours, questions
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.oracle.generative import in_support


def test_the_questions_in_file_order_with_their_propositions_sorted():
    asked = questions()
    data = json.loads((Path(Q.__file__).parent / "questions.json").read_text(encoding="utf-8"))
    assert [q.text for q in asked] == [q["text"] for q in data["questions"]]
    assert asked[0] == Question("pour from the side", ("pour_to_side",))
    # written light_liquid, end_upright, end_low in the file
    assert asked[3] == Question("a light liquid, righting the source up low above the bowl",
                                ("end_low", "end_upright", "light_liquid"))
    assert all(q.antecedent == tuple(sorted(q.antecedent)) for q in asked)


def test_every_question_is_a_valid_antecedent_asked_once():
    asked = questions()
    assert len({q.text for q in asked}) == len(asked)
    assert [q.text for q in asked if violations(q.antecedent)] == []


def test_question_pours_are_n_per_question_each_drawn_for_its_question():
    asked = [Question("side", ("pour_to_side",)), Question("light", ("light_liquid",)),
             Question("low and heavy", ("heavy_liquid", "pour_low"))]
    P, of = question_pours(asked, seed=5, n=4)
    assert P.shape == (12, 30)
    assert of.tolist() == [0] * 4 + [1] * 4 + [2] * 4
    for i, q in enumerate(asked):
        assert in_support(P[of == i], q.antecedent).all()
        others = [a for a in asked if a != q]
        assert not any(in_support(P[of == i], a.antecedent).all() for a in others)


def test_question_pours_are_seeded_and_a_question_keeps_its_pours_when_more_are_asked():
    asked = [Question("side", ("pour_to_side",)), Question("light", ("light_liquid",))]
    P, _ = question_pours(asked, seed=5, n=3)
    assert np.array_equal(P, question_pours(asked, seed=5, n=3)[0])
    assert not np.array_equal(P, question_pours(asked, seed=6, n=3)[0])
    more, _ = question_pours(asked + [Question("low", ("pour_low",))], seed=5, n=3)
    assert np.array_equal(more[:6], P)
    # the key's pours: KEY_POURS of each by default
    P20, of20 = question_pours(asked[:1], seed=5)
    assert len(P20) == KEY_POURS == 20 and set(of20.tolist()) == {0}
