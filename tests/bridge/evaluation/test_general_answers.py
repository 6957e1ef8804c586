"""bridge/evaluation/general_answers.py: the general theory asked the
questions of questions.json, with a stand-in oracle whose verdicts are
known (pouring from the side or far away spills, everything else holds)
and a hand-built shipped theory: each question's key and the contrast keys
where the defaults-only theory is wrong; the shipped theory's answers as
SWI-Prolog gives them; the general rules learned from the pours (and the
learner's own) beside gradient boosting and the defaults-only theory.

One stage on curiosity's pours (24 of them) takes a few seconds (the
learner's own pours, the general rules, boosting): it runs once for the
file."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.evaluation.general_answers import general_theories
from pantarhei.bridge.evaluation.pipeline import Evaluation, Pours
from pantarhei.bridge.evaluation.questions import questions
from pantarhei.bridge.evaluation.rule_building import theory_of
from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
SPILL = V.expectation_names.index("no_spill")
POUR_X = V.parameter_names.index("pour_x")
#: The propositions that put pour_x beyond 100 mm (its prior is 0 to 80).
AWAY = {"pour_to_side", "pour_far_away"}


def side_spills(P: np.ndarray) -> np.ndarray:
    """Every expectation holds, but no_spill fails 100 mm or more from the
    destination's axis."""
    S = np.full((len(P), 9), 0.9)
    S[:, SPILL] = np.where(np.asarray(P)[:, POUR_X] >= 100, 0.1, 0.9)
    return S


@pytest.fixture(scope="module")
def stage():
    """(the evaluation, the stages simulated: label and pours each)."""
    calls: list[tuple[str, int]] = []

    def run(label: str, P: np.ndarray) -> np.ndarray:
        calls.append((label, len(P)))
        return side_spills(P)

    P = np.vstack([sample(["pour_to_side"], 12, 1), sample(["pour_low"], 12, 2)])
    curiosity = Pours([("pour_to_side",), ("pour_low",)], P, side_spills(P))
    scenes = [("heavy_liquid", "pour_to_side"), ("pour_low",)]
    y = side_spills(np.vstack([sample(list(s), 1, 5) for s in scenes])) > 0.5
    heads = np.ones((1, 9), dtype=bool)
    heads[0, SPILL] = False
    shipped = theory_of([("pour_to_side",)], heads, "shipped")     # from the side: a spill
    ev = Evaluation("t", "synthetic", {}, 24)
    general_theories(ev, shipped, {"curiosity": curiosity}, {"uniform": (scenes, y)}, run,
                     seed=3, explored_seed=4)
    return ev, calls


def away(q) -> bool:
    return bool(AWAY & set(q.antecedent))


def test_each_questions_key_is_the_majority_of_its_pours(stage):
    ev, calls = stage
    g, asked = ev.general, questions()
    assert calls[0] == ("questions", 20 * len(asked))
    assert g["questions"] == [{"text": q.text, "antecedent": list(q.antecedent)} for q in asked]
    key, clear, share = (np.array(g[k]) for k in ("key", "clear", "share"))
    assert key.shape == clear.shape == share.shape == (len(asked), 9)
    # no_spill fails exactly for the questions that pour from the side or far away
    assert [bool(k) for k in key[:, SPILL]] == [not away(q) for q in asked]
    assert (np.delete(key, SPILL, axis=1) == 1).all()
    assert (clear == 1).all()                     # every pour of a question agrees
    assert share[:, SPILL].tolist() == [0.0 if away(q) else 1.0 for q in asked]
    assert "general" in ev.seconds


def test_the_contrast_keys_are_where_the_defaults_only_theory_is_wrong(stage):
    ev, _ = stage
    g, asked = ev.general, questions()
    n_away = sum(away(q) for q in asked)
    contrast = np.array(g["contrast"])
    # most pours keep no_spill: the defaults-only theory says so of every question
    assert contrast[:, SPILL].tolist() == [int(away(q)) for q in asked]
    assert contrast.sum() == n_away
    d = g["curiosity"]["defaults"]["questions"]
    assert d["clear"] == 9 * len(asked) and d["contrast"] == n_away
    assert d["coverage"] == 1.0 and d["contrast_accuracy"] == 0.0
    assert d["accuracy"] == pytest.approx(1 - n_away / (9 * len(asked)))


def test_the_shipped_theory_answers_as_swi_prolog_concludes(stage):
    ev, _ = stage
    asked = questions()
    s = ev.general["shipped"]
    side = [i for i, q in enumerate(asked) if "pour_to_side" in q.antecedent]
    for i, answer in enumerate(s["answers"]):
        assert answer == ([1] * 8 + [0] if i in side else [-1] * 9), asked[i].text
    q = s["questions"]
    assert q["coverage"] == pytest.approx(len(side) / len(asked))
    assert q["accuracy"] == 1.0 and q["contrast_accuracy"] == 1.0
    assert q["contrast_coverage"] == pytest.approx(len(side) / sum(away(x) for x in asked))
    assert q["calibration"] is None               # its rules record no likelihood
    assert s["general_rules"] == 0
    # the uniform scenes: the side pour decided (rightly), the low pour not
    assert (s["uniform"]["coverage"], s["uniform"]["accuracy"]) == (0.5, 1.0)


def test_the_general_rules_of_the_pours_and_the_learners_own_answer_every_question(stage):
    ev, calls = stage
    c = ev.general["curiosity"]
    own = [n for label, n in calls if label == "the learner's own pours"]
    assert len(own) == 1 and c["pours"] == 24 + own[0]
    heads = {(r["head"], tuple(r["body"])) for r in c["rules"]}
    assert ("no_spill", ()) in heads
    assert ("neg(no_spill)", ("pour_to_side",)) in heads
    assert ("neg(no_spill)", ("pour_far_away",)) in heads
    assert c["rules_per_expectation"] == pytest.approx(len(c["rules"]) / 9)
    q = c["questions"]
    assert q["coverage"] == 1.0 and q["accuracy"] == 1.0 and q["contrast_accuracy"] == 1.0
    assert c["uniform"]["accuracy"] == 1.0
    # gradient boosting of the same pours: the ceiling they support
    b = c["boosting"]["questions"]
    assert b["accuracy"] >= 0.95 and b["contrast_accuracy"] >= 0.95
    assert len(c["answers"]) == len(c["likelihood"]) == len(questions())
