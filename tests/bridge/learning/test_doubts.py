"""Where the learner doubts its rules' answers (bridge/learning/doubts.py):
a body whose few own pours would be unlikely under a sure answer, and a
pair next to an explored pair that interacts."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.learning.doubts import exceptions, few_pours, neighbours, thinly_poured
from pantarhei.bridge.learning.general_rules import General, GeneralRule
from pantarhei.bridge.learning.generalize import Settings
from pantarhei.bridge.learning.meaning import Meaning
from pantarhei.bridge.verdicts import UNKNOWN
from pantarhei.oracle.generative import in_support, sample
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().expectation_names
E = "liquid_enters_destination"
K = NAMES.index(E)
FAST = Settings(seed=3, draws=24)
DEFAULT = GeneralRule(f"g0_{E}", (), E, True, 0, 0, 0.95, 0)


def test_two_pours_of_two_that_contradict_a_sure_answer_get_their_own_rule():
    """The default says yes 95%; both pours drawn for the pair keep the
    bowl empty: fewer than `doubt_support` pours, but 0 of 2 is unlikely
    (0.25%) under the answer, so the pair gets its own rule. One pour of
    two (10%) is not unlikely enough, nor is anything with `unlikely` 0."""
    pair = ("approach_raising", "pour_below_rim")
    target = np.array([0.95, 0.3])
    bodies, n = [(), pair], np.array([2, 2])        # the pair's two pours, in its support
    (rule,) = exceptions([DEFAULT], bodies, target, np.array([0, 0]), n, FAST)
    assert rule.body == pair and not rule.holds and abs(rule.likelihood - 0.3) < 1e-9
    assert rule.doubt == "pours_contradict"
    assert not exceptions([DEFAULT], bodies, target, np.array([1, 1]), n, FAST)
    off = Settings(seed=3, draws=24, unlikely=0.0)
    assert not exceptions([DEFAULT], bodies, target, np.array([0, 0]), n, off)


def _explored(pair_likelihood: float, pair=("pour_centred", "pour_very_high")):
    """Pours of `pair` (pouring very high over the centre: 6, none of which
    fills the bowl), and the likelihoods of the bodies explored: each part
    alone fills it, the pair `pair_likelihood`."""
    P = sample(list(pair), 6, 11)
    Y = np.ones((len(P), len(NAMES)), dtype=bool)
    Y[:, K] = False
    bodies = [(), *((x,) for x in pair), pair]
    return P, Meaning(P, Y, FAST), bodies, np.array([0.95, 0.95, 0.95, pair_likelihood])


def _own(P, bodies) -> np.ndarray:
    """The pours of P in each body's support."""
    return np.array([int(in_support(P, list(b)).sum()) for b in bodies])


def test_a_pair_next_to_one_that_interacts_says_maybe():
    """Pouring very high over the centre keeps the bowl empty, though each
    part fills it: pouring high over the centre, never poured, one rank
    along the height's scale, is answered maybe, not the default's sure
    yes; a pair two ranks away (below the rim) keeps the default's."""
    P, meaning, bodies, target = _explored(0.05)
    added = neighbours([DEFAULT], bodies, target, _own(P, bodies), K, meaning, P, FAST)
    said = {r.body: r for r in added}
    assert ("pour_centred", "pour_high") in said
    assert ("pour_below_rim", "pour_centred") not in said
    theory = General(rules=[DEFAULT] + added)
    assert theory.decide({"pour_centred", "pour_high"})[E][0] == UNKNOWN
    assert all(FAST.verdict(r.likelihood) == UNKNOWN for r in added)
    assert {(r.doubt, r.beside) for r in added} == {("beside_interaction", bodies[-1])}


def test_no_maybe_next_to_a_pair_that_does_not_interact():
    P, meaning, bodies, target = _explored(0.95)
    assert not neighbours([DEFAULT], bodies, target, _own(P, bodies), K, meaning, P, FAST)


def test_no_maybe_next_to_a_pair_of_two_groups():
    """A heavy liquid poured very high: the liquid and the pose are two
    groups of parameters, whose pairs are not suspects of an interaction
    as physics goes, so their neighbours keep the rules' answers."""
    P, meaning, bodies, target = _explored(0.05, ("heavy_liquid", "pour_very_high"))
    assert not neighbours([DEFAULT], bodies, target, _own(P, bodies), K, meaning, P, FAST)


def _one_pour(pair, fills: bool):
    """One pour drawn for `pair` among pours of the ordinary pour that fill
    the bowl; the pair's own pour fills it or not (`fills`)."""
    P = np.vstack([sample([], 12, 5), sample(list(pair), 1, 7)])
    Y = np.ones((len(P), len(NAMES)), dtype=bool)
    Y[-1, K] = fills
    return P, Y, Meaning(P, Y, FAST)


def test_a_pair_never_explored_whose_one_pour_departs_says_maybe():
    """Pouring high over the centre has no rule of its own; the one pour that
    could have been drawn for it keeps the bowl empty, against the
    default's sure yes: the pair is answered maybe, saying why, and its
    likelihood counts that pour beside the model's."""
    pair = ("pour_centred", "pour_high")
    P, Y, meaning = _one_pour(pair, False)
    pairs, held, n = thinly_poured(P, Y, FAST)
    assert pair in pairs and n[pairs.index(pair)] >= 1
    added = few_pours([DEFAULT], pairs, held[:, K], n, K, meaning, FAST)
    assert [r.body for r in added] == [pair] and added[0].doubt == "few_pours_depart"
    assert General(rules=[DEFAULT] + added).decide(set(pair))[E][0] == UNKNOWN


def test_no_maybe_where_the_pairs_pour_agrees_or_it_has_a_rule():
    """The pair's one pour fills the bowl: the default's yes stands. A
    pair with a rule of its own keeps that rule's answer."""
    pair = ("pour_centred", "pour_high")
    P, Y, meaning = _one_pour(pair, True)
    pairs, held, n = thinly_poured(P, Y, FAST)
    assert not few_pours([DEFAULT], pairs, held[:, K], n, K, meaning, FAST)
    P, Y, meaning = _one_pour(pair, False)
    pairs, held, n = thinly_poured(P, Y, FAST)
    own = GeneralRule(f"g1_{E}", pair, E, True, 1, 1, 0.9, 1)
    assert not few_pours([DEFAULT, own], pairs, held[:, K], n, K, meaning, FAST)


def test_a_pair_of_two_groups_is_no_suspect_of_few_pours():
    """A heavy liquid poured high: two groups of parameters, so its one
    departing pour is no sign of an interaction."""
    pair = ("heavy_liquid", "pour_high")
    P, Y, _ = _one_pour(pair, False)
    assert pair not in thinly_poured(P, Y, FAST)[0]
