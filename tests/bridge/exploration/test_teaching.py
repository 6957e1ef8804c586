"""bridge/exploration/teaching.py: the learning curiosity's value of a
candidate, on pours of the synthetic oracle, whose answers are known:
pouring from the side spills there, and the source's bounciness changes
nothing."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.teaching import (Weights, fitted_on, model, one_thread, shown_new,
                                                   teaching, thread_pools)
from pantarhei.bridge.verdicts import verdicts
from pantarhei.oracle.generative import sample, to_dict
from pantarhei.oracle.synthetic import scores


#: How far a candidate's answers would move and how uncertain its
#: likelihoods are, nothing for its batch's doubt and new behaviours.
ONLY_ANSWERS = Weights(1.0, 0.0, 0.0)


def pours(body, n, seed):
    P = sample(list(body), n, seed)
    return P, np.array([scores(to_dict(p)) for p in P])


def pooled(*parts):
    return np.vstack([p for p, _ in parts]), np.vstack([s for _, s in parts])


def test_the_model_is_fitted_again_as_the_pours_grow_by_a_fifth():
    sizes = [fitted_on(n) for n in range(0, 400)]
    assert sizes[:8] == list(range(8))
    assert all(0 < m <= n for n, m in enumerate(sizes) if n) and sizes == sorted(sizes)
    changes = [n for n in range(9, 400) if sizes[n] != sizes[n - 1]]
    assert all(b / a >= 1.15 for a, b in zip(changes, changes[1:]))


def test_a_proposition_that_changes_what_happens_teaches_more():
    P, S = pooled(pours([], 40, 1), pours(["pour_to_side"], 8, 2), pours(["bouncy_source"], 8, 3))
    found = teaching(P, S, [()], [("pour_to_side",), ("bouncy_source",)], ONLY_ANSWERS, 4, 1)
    side, bouncy = found.departure
    # pouring from the side spills: its answers move from the ordinary pour's
    assert side > 1.0 and bouncy < 0.3
    assert found.value[0] > found.value[1]


def test_an_explored_antecedent_is_valued_by_its_uncertainty_alone():
    P, S = pooled(pours([], 40, 1), pours(["pour_to_side"], 8, 2))
    found = teaching(P, S, [(), ("pour_to_side",)], [("pour_to_side",), ("light_liquid",)],
                     ONLY_ANSWERS, 4, 1)
    assert found.departure[0] == 0.0
    # an antecedent without pours of its own is the least certain
    assert found.uncertainty[1] > found.uncertainty[0] > 0
    # and without the weight of uncertainty, another batch of it teaches nothing
    assert teaching(P, S, [(), ("pour_to_side",)], [("pour_to_side",)], Weights(0.0), 4, 1).value == [0.0]


def test_the_same_pours_give_the_same_values():
    P, S = pooled(pours([], 24, 5), pours(["light_liquid"], 8, 6))
    cands = [("light_liquid",), ("pour_far_away",), ("light_liquid", "pour_high")]
    w = Weights(1.0, 1.0, 1.0)
    a = teaching(P, S, [(), ("light_liquid",)], cands, w, 4, 7, 3)
    b = teaching(P, S, [(), ("light_liquid",)], cands, w, 4, 7, 3, model(P, S, 7))
    assert a == b


def test_a_step_finds_the_pours_of_each_body_once(monkeypatch):
    """The value of a candidate counts its own pours, and its newness what
    they showed: which pours lie in a body's support is found once a step."""
    import pantarhei.bridge.exploration.pour_support as support_module
    import pantarhei.bridge.learning.meaning as meaning_module

    found, real = [], support_module.in_support

    def counted(P, body):
        found.append(tuple(body))
        return real(P, body)
    for module in (support_module, meaning_module):
        monkeypatch.setattr(module, "in_support", counted)
    P, S = pooled(pours([], 24, 5), pours(["light_liquid"], 8, 6))
    cands = [("light_liquid",), ("pour_far_away",), ("light_liquid", "pour_high")]
    value = teaching(P, S, [(), ("light_liquid",)], cands, Weights(1.0, 1.0, 2.0), 4, 7, 3).value
    assert set(cands) <= set(found) and len(found) == len(set(found))
    monkeypatch.undo()
    assert teaching(P, S, [(), ("light_liquid",)], cands, Weights(1.0, 1.0, 2.0), 4, 7, 3).value == value


def test_a_pair_teaches_only_where_its_propositions_interact():
    """Pouring from the side spills whatever the source's bounciness: the
    pair moves no answer away from pouring from the side alone, and a
    pair never explored is no candidate for its uncertainty."""
    P, S = pooled(pours([], 40, 1), pours(["pour_to_side"], 8, 2), pours(["bouncy_source"], 8, 3))
    found = teaching(P, S, [(), ("pour_to_side",), ("bouncy_source",)],
                     [("bouncy_source", "pour_to_side")], ONLY_ANSWERS, 4, 1)
    assert found.departure[0] < 0.3 and found.uncertainty == [0.0]


def test_doubt_is_where_the_model_cannot_tell_and_fades_with_own_pours():
    """The synthetic oracle spills past the rim: pours near the rim sit on
    the boundary, where the model of the pours is unsure; the ordinary
    pour, with many pours of its own, is known."""
    P, S = pooled(pours([], 40, 1), pours(["pour_to_side"], 8, 2), pours(["pour_near_rim"], 8, 4))
    found = teaching(P, S, [()], [(), ("pour_near_rim",), ("bouncy_source",)],
                     Weights(0.0, 1.0, 0.0), 4, 1, 5)
    ordinary, rim, bouncy = found.doubt
    assert rim > ordinary and rim > bouncy
    # with the doubt weighed alone, the value is the doubt less the share
    # of the candidate's own pours already known
    assert found.value[1] > found.value[0]
    # another 40 pours of the rim: less left to learn there
    P2, S2 = pooled((P, S), pours(["pour_near_rim"], 40, 9))
    again = teaching(P2, S2, [(), ("pour_near_rim",)], [("pour_near_rim",)],
                     Weights(0.0, 1.0, 0.0), 4, 1, 5)
    assert again.value[0] < found.value[1]


def test_newness_is_the_chance_of_a_behaviour_no_two_pours_showed():
    """A model that knows pouring far away misses the bowl, and only
    ordinary pours seen: a batch from far away would show a new behaviour;
    another batch of the ordinary pour would not."""
    P, S = pours([], 40, 1)
    knows = model(*pooled((P, S), pours(["pour_far_away"], 24, 3)), 1)
    found = teaching(P, S, [()], [(), ("pour_far_away",)], Weights(0.0, 0.0, 1.0), 4, 1, 2,
                     knows)
    assert found.newness[0] < 0.2 < found.newness[1]
    assert found.value[1] > found.value[0]


def test_a_pair_of_one_pose_is_a_suspect_before_it_has_pours():
    """Height and position both set the pouring pose: the pair may interact
    where neither alone shows it, so before any pour of its region it is
    valued by its uncertain likelihoods; a pair of a pose and the source's
    material is not, and the suspect's uncertainty fades once it has
    pours."""
    P, S = pooled(pours([], 40, 1), pours(["pour_centred"], 8, 2), pours(["pour_very_high"], 8, 3),
                  pours(["bouncy_source"], 8, 4))
    explored = [(), ("pour_centred",), ("pour_very_high",), ("bouncy_source",)]
    cands = [("pour_centred", "pour_very_high"), ("bouncy_source", "pour_very_high")]
    found = teaching(P, S, explored, cands, ONLY_ANSWERS, 4, 1)
    assert found.uncertainty[0] > 0 and found.uncertainty[1] == 0.0
    P2, S2 = pooled((P, S), pours(["pour_centred", "pour_very_high"], 16, 5))
    again = teaching(P2, S2, explored, cands[:1], ONLY_ANSWERS, 4, 1)
    assert 0 < again.uncertainty[0] < found.uncertainty[0]


def test_newness_fades_where_pours_keep_showing_what_was_seen():
    """Learning progress: 40 ordinary pours of the synthetic oracle show two
    behaviours, so 4 of them showed one new when simulated (the first two
    of each): whatever the model says, the ordinary pour's newness is near
    that share; a region without pours keeps the model's chance."""
    P, S = pours([], 40, 1)
    behaviours = np.unique(verdicts(S), axis=0).shape[0]
    out = shown_new(np.array([0.9, 0.9]), P, S, [(), ("pour_far_away",)], 4.0)
    assert out[0] == pytest.approx((4 * 0.9 + 2 * behaviours) / 44)
    assert out[1] == 0.9


def test_a_whole_is_valued_by_its_newness_alone_counted_whole():
    """A candidate named among the wholes is one no question says: it
    moves no answer and narrows no likelihood a question asks, so only its
    newness counts, with no part's subtracted; the same body not named so
    is valued as before."""
    P, S = pours([], 40, 1)
    knows = model(*pooled((P, S), pours(["pour_far_away"], 24, 3)), 1)
    whole = ("light_liquid", "pour_far_away", "pour_high")
    w = Weights(1.0, 1.0, 2.0)
    found = teaching(P, S, [()], [whole, ("pour_far_away",)], w, 4, 1, 2, knows, wholes=[whole])
    assert found.departure[0] == found.uncertainty[0] == found.doubt[0] == 0.0
    assert found.newness[0] > 0.2
    assert found.value[0] == pytest.approx(2.0 * found.newness[0], abs=1e-6)
    # as a body a question could say, its parts' newness is subtracted
    # (pouring far away alone shows the new behaviour as well) and its doubt counts
    asked = teaching(P, S, [()], [whole, ("pour_far_away",)], w, 4, 1, 2, knows)
    assert asked.newness[0] < found.newness[0]


def test_a_whole_is_new_where_its_consequent_is_none_explored_has():
    """The synthetic oracle spills from far away whatever else is said: on
    the same pours, a whole that pours far away is sure to have a new
    consequent while only the ordinary pour is explored, and no likelier
    than a whole that pours as the ordinary pour does once pouring far
    away is explored too."""
    P, S = pooled(pours([], 40, 1), pours(["pour_far_away"], 24, 3))
    far = ("bouncy_source", "light_liquid", "pour_far_away")
    plain = ("bouncy_source", "heavy_source", "light_liquid")
    w = Weights(0.0, 0.0, 1.0)
    before = teaching(P, S, [()], [far, plain], w, 4, 1, 2, wholes=[far, plain]).newness
    after = teaching(P, S, [(), ("pour_far_away",)], [far, plain], w, 4, 1, 2, wholes=[far, plain]).newness
    assert before[0] > 0.9 > before[1]
    assert after[0] < before[0] and after[0] == pytest.approx(after[1], abs=0.05)


def test_the_model_is_fitted_and_asked_on_one_thread() -> None:
    # the boosting's OpenMP among the pools limited, through a controller kept across calls
    from threadpoolctl import threadpool_info

    threads = thread_pools()
    for _ in range(2):
        with one_thread(threads):
            pools = threadpool_info()
            assert any(p["user_api"] == "openmp" for p in pools)
            assert all(p["num_threads"] == 1 for p in pools)
