"""bridge/evaluation/heldout.py: held-out scenes (uniformly random valid
antecedents by SWI-Prolog, or explored ones with one or two propositions
added; never an excluded one), their pours and verdicts, the random
baseline's exploration, and on small hand-built pours the curves over the
budget and the final theories and decision trees, with figures worked out
by hand."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.evaluation.heldout import (heldout_curves, heldout_theories,
                                                 near_antecedents, random_exploration,
                                                 scene_pours, simulated, uniform_scenes)
from pantarhei.bridge.evaluation.pipeline import Evaluation, Pours
from pantarhei.bridge.evaluation.rule_building import theory_of
from pantarhei.bridge.reasoning.valid_scenes import violations
from pantarhei.oracle.generative import in_support, sample
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
SPILL = V.expectation_names.index("no_spill")


def test_random_exploration_draws_samples_pours_of_each_valid_antecedent():
    ants, P = random_exploration(seed=3, count=4, samples=5)
    assert len(ants) == 4 and P.shape == (20, 30)
    for i, a in enumerate(ants):
        assert not violations(a)
        assert in_support(P[5 * i:5 * (i + 1)], a).all()
    again, P2 = random_exploration(seed=3, count=4, samples=5)
    assert again == ants and np.array_equal(P, P2)


def test_uniform_scenes_are_distinct_valid_and_never_excluded():
    scenes = uniform_scenes(seed=4, n=12, exclude=set())
    assert len(scenes) == 12 and len(set(scenes)) == 12
    assert not any(violations(s) for s in scenes)
    fewer = uniform_scenes(seed=4, n=12, exclude=set(scenes[:3]))
    assert not set(scenes[:3]) & set(fewer)
    assert fewer[:9] == scenes[3:]


def test_near_antecedents_add_one_or_two_propositions_of_open_dimensions():
    explored = [("pour_low",), ("heavy_liquid", "pour_to_side")]
    near = near_antecedents(explored, 15, seed=2, exclude={("pour_low", "pour_upright")})
    assert len(near) == 15 and len(set(near)) == 15
    for a in near:
        assert a == tuple(sorted(a)) and not violations(a)
        assert a != ("pour_low", "pour_upright")
        base = [x for x in explored if set(x) < set(a) and 1 <= len(a) - len(x) <= 2]
        assert base, a
        assert len({V.propositions[p].dimension for p in a}) == len(a)
    assert near == near_antecedents(explored, 15, seed=2, exclude={("pour_low", "pour_upright")})


def test_one_pour_of_each_scene_and_the_verdicts_of_those_that_did_not_fail():
    scenes = [("pour_low",), ("pour_to_side", "heavy_liquid"), ("light_liquid",)]
    P = scene_pours(scenes, seed=1)
    assert P.shape == (3, 30)
    assert all(in_support(P[j:j + 1], s)[0] for j, s in enumerate(scenes))
    assert scene_pours([], seed=1).shape == (0, 30)
    S = np.array([[0.9] * 9, [np.nan] * 9, [0.1] + [0.9] * 8])
    kept, y = simulated(scenes, S)
    assert kept == [("pour_low",), ("light_liquid",)]
    assert y.tolist() == [[True] * 9, [False] + [True] * 8]


def hand_pours(ants: list[tuple[str, ...]], spills: list[bool], n: int = 3, seed: int = 1) -> Pours:
    """n pours of each antecedent; every expectation holds, but no_spill
    fails in the pours of the antecedents marked to spill."""
    P = np.vstack([sample(list(a), n, seed + i) for i, a in enumerate(ants)])
    S = np.full((len(P), 9), 0.9)
    for i, s in enumerate(spills):
        if s:
            S[n * i:n * (i + 1), SPILL] = 0.1
    return Pours(list(ants), P, S)


def test_the_curves_over_the_budget_after_each_antecedent():
    # curiosity: pouring low keeps everything, then pouring high spills;
    # random: two antecedents that no held-out scene holds
    methods = {"curiosity": hand_pours([("pour_low",), ("pour_high",)], [False, True]),
               "random": hand_pours([("pour_very_high",), ("pour_below_rim",)], [False, False])}
    near = [("heavy_liquid", "pour_high"), ("heavy_liquid", "pour_low")]
    held = {"near": (near, np.ones((2, 9), dtype=bool))}     # nothing spills there
    ev = Evaluation("t", "synthetic", {}, 6)
    heldout_curves(ev, methods, held, samples=3, mode="weighted")
    c = ev.curves
    assert c["budget"] == [3, 6]
    assert c["curiosity"]["behaviours"] == [1, 2] and c["random"]["behaviours"] == [1, 1]
    assert ev.behaviours == {"curiosity": 2, "random": 1}
    # after pouring low: the second scene decided, all right; then both,
    # pouring high wrongly spilling
    assert c["curiosity"]["coverage"]["near"] == [0.5, 1.0]
    assert c["curiosity"]["accuracy"]["near"] == [1.0, pytest.approx(17 / 18)]
    assert c["random"]["coverage"]["near"] == [0.0, 0.0]
    assert c["random"]["accuracy"]["near"] == [None, None]


def test_the_final_theories_and_trees_on_each_held_out_set():
    cur = hand_pours([("pour_low",)], [False])
    rnd = hand_pours([("pour_high",)], [True])
    scenes = [("heavy_liquid", "pour_high"), ("heavy_liquid", "pour_low"), ("pour_centred",)]
    held = {"near": (scenes, np.ones((3, 9), dtype=bool)),
            "uniform": ([], np.zeros((0, 9), dtype=bool))}
    theory = theory_of([("pour_low",)], np.ones((1, 9), dtype=bool), "learned")
    ev = Evaluation("t", "synthetic", {}, 3)
    heldout_theories(ev, theory, {"curiosity": cur, "random": rnd}, held, 3, "weighted", seed=1)
    h = ev.heldout["near"]
    assert h["scenes"] == 3 and h["mean_propositions"] == pytest.approx(5 / 3)
    # the learned theory decides the scene poured low only, rightly
    assert h["curiosity_theory"]["coverage"] == pytest.approx(1 / 3)
    assert h["curiosity_theory"]["accuracy"] == 1.0
    # random exploration's theory (rebuilt from its pours) spills when pouring high: wrong there
    assert h["random_theory"]["coverage"] == pytest.approx(1 / 3)
    assert h["random_theory"]["accuracy"] == pytest.approx(8 / 9)
    assert h["random_theory"]["per_expectation"]["no_spill"] == {"coverage": pytest.approx(1 / 3),
                                                                 "accuracy": 0.0}
    # the trees always decide: curiosity's saw nothing spill, random's saw only spills
    assert h["curiosity_tree"]["coverage"] == 1.0 and h["curiosity_tree"]["accuracy"] == 1.0
    assert h["random_tree"]["accuracy"] == pytest.approx(8 / 9)
    assert ev.heldout["uniform"]["scenes"] == 0 and ev.heldout["uniform"]["mean_propositions"] == 0.0
