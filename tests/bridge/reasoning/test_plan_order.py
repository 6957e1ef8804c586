"""The order of the planner's search (bridge/reasoning/plan_order.py): the
manners a theory rates alike are tried as the pours seen predict, so a
plan late in the vocabulary's order is found within a small budget;
with clingo and an oracle of known answers."""
from __future__ import annotations

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.reasoning.plan_order import chances, inside, ranked_singles
from pantarhei.bridge.reasoning.plan_search import search
from pantarhei.bridge.theories.model import Rule, Theory

#: A theory that thinks every pour keeps the liquid in the bowl, so it
#: proposes the ordinary pour, and rates every manner alike.
CONFIDENT = Theory(rules=[Rule("r0", "defeasible", "liquid_leaves_source"),
                          Rule("r1", "defeasible", "no_spill")], source="confident.pl")
GOALS = ["no_spill"]
#: Where the known answer's pours keep the liquid in: pouring 40 mm or more
#: from the bowl's axis (the ordinary pour draws 0 to 80).
FAR = 40.0


def known(P: np.ndarray) -> np.ndarray:
    """Scores of known answers: every expectation holds, no_spill only
    where the source pours FAR or more from the destination's axis."""
    names = load_vocabulary().expectation_names
    x = list(load_vocabulary().parameter_names).index("pour_x")
    S = np.ones((len(P), len(names)))
    S[:, names.index("no_spill")] = (np.asarray(P)[:, x] >= FAR).astype(float)
    return S


def test_a_plan_late_in_the_vocabulary_is_found_within_a_small_budget() -> None:
    order = [c[0] for _, c in ranked_singles(CONFIDENT, ["no_spill", "liquid_leaves_source"], [])]
    late = order.index("pour_near_rim")
    assert late >= 10          # the vocabulary's order alone tries many first
    # the budget holds the ordinary pour's refutation, a few candidates and one plan verified
    for seed in (1, 2, 3):
        out = search(CONFIDENT, GOALS, [], known, verify_pours=10, min_success=0.9, seed=seed,
                     budget=40, learn=False)
        assert out.tried[0].plan.chosen == () and not out.tried[0].verified
        assert out.verified, out.reason
        assert out.verified[0].plan.chosen in {("pour_near_rim",), ("pour_to_side",),
                                               ("pour_far_away",)}
        assert len(out.tried) < late
        again = search(CONFIDENT, GOALS, [], known, verify_pours=10, min_success=0.9, seed=seed,
                       budget=40, learn=False)
        assert [t.plan.chosen for t in again.tried] == [t.plan.chosen for t in out.tried]


def test_a_candidate_is_estimated_from_the_pours_where_it_sets_its_parameters() -> None:
    P = sample([], 200, 5)
    S = known(P)
    x = list(load_vocabulary().parameter_names).index("pour_x")
    assert np.array_equal(inside(P, ["pour_near_rim"], []), (P[:, x] >= 40) & (P[:, x] <= 95))
    assert inside(P, ["pour_near_rim"], ["pour_near_rim"]).all()
    c = chances(P, S, GOALS, [["pour_near_rim"], ["pour_centred"], ["slow_retreat"]])
    near, centred, unrelated = c[:, 0]
    assert near > 0.9 and centred < 0.1
    # a manner of parameters the goals do not depend on keeps the share of all the pours
    assert abs(unrelated - (P[:, x] >= FAR).mean()) < 0.1
    # the second column: each goal's share multiplied (here, one goal: the same)
    assert np.allclose(c[:, 1], c[:, 0])
