"""Novelty on the synthetic oracle, whose answers are known: a forest of
prior pours predicts that a proposition the oracle ignores shows nothing
new, and that pouring from the side (which spills) gives a new consequent;
a probe of a few real pours says the same, and counts a split verdict as a
toss."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.exploration.novelty import (PASS, known, majority,
                                                  new_reproduced, novelties, probe_score)
from pantarhei.oracle.generative import sample
from pantarhei.oracle.synthetic import DEPENDS, scores
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
NAMES = V.parameter_names
A0 = ["pour_mid_height", "pour_near_rim", "pour_steeply_tilted"]
IGNORED = "sticky_liquid"          # the synthetic oracle has no viscosity
SIDE = ["pour_mid_height", "pour_steeply_tilted", "pour_to_side"]


def synthetic(P: np.ndarray) -> np.ndarray:
    return np.array([scores(dict(zip(NAMES, p))) for p in P])


def consequent(props: list[str]) -> tuple[bool, ...]:
    """The oracle's own consequent of an antecedent (the verdicts most of its pours show)."""
    return tuple(bool(v) for v in (synthetic(sample(props, 400, 9)) > 0.5).mean(axis=0) > 0.5)


def knowing_a0():
    """What an exploration knows after two batches of a_0 and some pours
    elsewhere (a few for every proposition: the ordinary pour alone never
    pours from the side)."""
    P = np.vstack([sample(A0, 62, 1)] + [sample([p], 8, 2) for p in V.propositions])
    return known(P, synthetic(P), [consequent(A0)], samples=31, seed=1, forest_seed=2)


def test_the_ignored_proposition_is_not_novel_and_the_side_pour_is():
    assert all("viscosity" not in d for deps in DEPENDS.values() for d in deps)
    assert consequent(A0 + [IGNORED]) == consequent(A0) != consequent(SIDE)   # the known answers
    dull, side = novelties(knowing_a0(), [sorted(A0 + [IGNORED]), SIDE])
    # the side pour surely has a new consequent; the dull one probably has a_0's
    # (not surely: its pours, as a_0's, are mixed on three expectations)
    assert side["new_consequent"] > 0.99 and side["novelty"] > 0.75
    assert dull["new_consequent"] < 0.5 and dull["novelty"] < side["novelty"] - 0.4


def test_estimates_are_seeded_and_below_one():
    cands = [sorted(A0 + [IGNORED]), SIDE, ["heavy_liquid", "pour_tilted_back"]]
    a, b = novelties(knowing_a0(), cands), novelties(knowing_a0(), cands)
    assert a == b
    assert all(0.0 <= f["novelty"] < 1.0 for f in a)


def test_with_no_pours_everything_is_new():
    empty = known(np.empty((0, len(NAMES))), np.empty((0, len(V.expectations))), [],
                  samples=31, seed=1, forest_seed=2)
    (f,) = novelties(empty, [A0])
    assert f["new_consequent"] == 1.0 and f["unseen"] == 1.0


def test_the_chance_of_a_new_reproduced_consequent():
    decided = np.array([1.0] * 5 + [0.0] * 4)
    none = np.empty((0, 9), dtype=bool)
    assert majority(np.array([0.5]), 31)[0] == 0.5 == majority(np.array([0.5]), 30)[0]
    assert majority(np.array([0.6]), 31)[0] > 0.85
    assert new_reproduced(decided, 31, none) == 1.0
    assert new_reproduced(decided, 31, np.array([decided > 0.5])) == 0.0
    split = decided.copy()
    split[5] = 0.5                  # a toss on one verdict: two batches agree half the time
    assert abs(new_reproduced(split, 31, none) - 0.5) < 1e-9
    assert abs(new_reproduced(split, 31, np.array([decided > 0.5])) - 0.25) < 1e-9


def test_a_probe_reads_its_few_pours_as_evidence_not_certainty():
    new = np.array([[0.9] * 5 + [0.1] * 4] * 8)          # eight pours, all alike
    known_c = [tuple([True] * 9)]
    assert probe_score(new, 31, known_c) > 0.99
    assert probe_score(new, 31, [tuple(bool(v) for v in new[0] > 0.5)]) < 0.01
    split = new.copy()
    split[:4, 5] = 0.9                                   # four of eight hold: a toss
    assert abs(probe_score(split, 31, known_c) - 0.5) < 0.01
    failed = np.vstack([split, np.full((3, 9), np.nan)])  # failed pours say nothing
    assert probe_score(failed, 31, known_c) == probe_score(split, 31, known_c)
    one = new[:1]                   # one pour is weak evidence: (1 + 1) / (1 + 2) for each
    assert 0.5 < probe_score(one, 31, known_c) < probe_score(new, 31, known_c)


def test_probes_of_the_synthetic_oracle_pass_the_side_pour_and_not_a_0_again():
    a0 = consequent(A0)
    assert probe_score(synthetic(sample(SIDE, 8, 4)), 31, [a0]) >= PASS
    assert probe_score(synthetic(sample(sorted(A0 + [IGNORED]), 8, 4)), 31, [a0]) < 0.1
