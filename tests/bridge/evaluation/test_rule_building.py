"""bridge/evaluation/rule_building.py: Algorithm 1's rule building on any
pours: each antecedent's consequent from equation (1)'s weights (weighted
or argmax, failed pours left out), the theory of one rule per antecedent
and expectation, and what SWI-Prolog answers with it in scenes (verdicts
and likelihoods)."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN
from pantarhei.bridge.evaluation.rule_building import answer_matrix, consequents, predict, theory_of
from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().expectation_names
SPILL = NAMES.index("no_spill")


def pours_of(*antecedents: tuple[str, ...], n: int = 4) -> np.ndarray:
    return np.vstack([sample(list(a), n, 10 + i) for i, a in enumerate(antecedents)])


def test_the_consequent_is_the_weighted_majority_of_each_antecedents_own_pours():
    # pouring low and pouring high never share a pour: each antecedent
    # weighs only its own four pours
    ants = [("pour_low",), ("pour_high",)]
    P = pours_of(*ants)
    S = np.full((8, 9), 0.9)
    S[0:4, SPILL] = [0.1, 0.9, 0.9, 0.9]     # low: three of four keep no_spill
    S[4:8, SPILL] = [0.9, 0.1, 0.1, 0.1]     # high: one of four
    heads = consequents(ants, P, S)
    assert heads.dtype == bool and heads.shape == (2, 9)
    assert heads[0].all()
    assert not heads[1, SPILL] and heads[1, :SPILL].all()
    # argmax: the verdicts of the first pour of the largest (here equal) weight
    argmax = consequents(ants, P, S, mode="argmax")
    assert not argmax[0, SPILL] and argmax[1, SPILL]


def test_failed_pours_are_left_out_of_the_consequent():
    ants = [("pour_low",)]
    P = pours_of(*ants)
    S = np.full((4, 9), 0.9)
    S[2:] = np.nan                            # two failed pours: the two left keep everything
    assert consequents(ants, P, S).all()


def test_the_theory_has_one_learned_rule_per_antecedent_and_expectation():
    heads = np.ones((2, 9), dtype=bool)
    heads[1, SPILL] = False
    th = theory_of([("pour_low",), ("pour_to_side", "heavy_liquid")], heads, "two antecedents")
    assert th.source == "two antecedents"
    assert [r.id for r in th.rules] == [f"r{i}_{e}" for i in (1, 2) for e in NAMES]
    assert th.learned == {r.id for r in th.rules}
    assert {r.kind for r in th.rules} == {"defeasible"}
    assert th.rule("r1_no_spill").head == "no_spill" and th.rule("r1_no_spill").body == ("pour_low",)
    assert th.rule("r2_no_spill").head == "neg(no_spill)"
    assert th.rule("r2_source_clear").body == ("heavy_liquid", "pour_to_side")   # sorted


def test_answers_are_what_swi_prolog_concludes_with_the_rules_likelihoods():
    heads = np.ones((1, 9), dtype=bool)
    heads[0, SPILL] = False
    th = theory_of([("pour_to_side",)], heads, "side")
    # likelihoods as a learned theory records them: the confidence of the head
    th.provenance = [("r1_no_spill", "confidence_permille", 900),
                     ("r1_source_clear", "confidence_permille", 800),
                     ("r1_destination_upright", "confidence_permille", 550)]
    verdict, lik = answer_matrix(th, [["pour_to_side", "heavy_liquid"], ["pour_low"]])
    assert verdict.shape == lik.shape == (2, 9)
    up, clear = NAMES.index("destination_upright"), NAMES.index("source_clear")
    assert verdict[0, SPILL] == FAILS and lik[0, SPILL] == pytest.approx(0.1)   # 1 - 0.9
    assert verdict[0, clear] == HOLDS and lik[0, clear] == pytest.approx(0.8)
    # 0.55 lies within the uncertain band around one half: undecided, with its likelihood
    assert verdict[0, up] == UNKNOWN and lik[0, up] == pytest.approx(0.55)
    # a rule that records no confidence: decided, no likelihood
    first = NAMES.index("destination_still_approach")
    assert verdict[0, first] == HOLDS and np.isnan(lik[0, first])
    # no rule applies when not pouring from the side
    assert (verdict[1] == UNKNOWN).all() and np.isnan(lik[1]).all()
    assert np.array_equal(predict(th, [["pour_to_side", "heavy_liquid"], ["pour_low"]]), verdict)



def test_rules_are_named_as_explore_names_them():
    """theory_of's rules for the antecedents and consequents of a theory
    that explore/1 wrote are that theory's rules, ids included."""
    from pathlib import Path

    from pantarhei.bridge.theories.loading import read_theory

    fixture = Path(__file__).parents[1] / "exploration" / "fixtures" / "paper_synthetic_seed3.pl"
    written = read_theory(fixture)
    by_antecedent: dict[int, dict[str, object]] = {}
    for rid, key, value in written.provenance:
        if key == "antecedent":
            by_antecedent.setdefault(int(str(value)[1:]), {})[rid] = written.rule(rid)
    ants, heads = [], []
    for i in sorted(by_antecedent):
        rules = {r.head.removeprefix("neg(").rstrip(")"): r for r in by_antecedent[i].values()}
        ants.append(next(iter(rules.values())).body)
        heads.append([not rules[e].head.startswith("neg(") for e in NAMES])
    assert len(ants) > 3
    rebuilt = theory_of(ants, np.array(heads), "rebuilt")
    assert sorted((r.id, r.head, tuple(sorted(r.body))) for r in rebuilt.rules) == \
        sorted((r.id, r.head, tuple(sorted(r.body))) for r in written.rules)
