"""The MAP-Elites baseline (pyribs) on the synthetic oracle, and the
behaviours-seen measure every search method is compared by."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.evaluation.map_elites import behaviours_seen, map_elites
from pantarhei.oracle.generative import sample
from pantarhei.oracle.synthetic import SyntheticOracle
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()


def synthetic(P: np.ndarray) -> np.ndarray:
    oracle = SyntheticOracle()
    return np.array([oracle.score(p).scores for p in P])


def test_behaviours_seen_counts_verdict_vectors_shown_twice():
    S = np.array([[0.9] * 9, [0.8] * 9, [0.1] * 9, [0.2] + [0.9] * 8, [0.3] + [0.7] * 8,
                  [np.nan] * 9, [np.nan] * 9])
    assert behaviours_seen(S) == 2            # all-hold twice, first-fails twice; all-fail once
    assert behaviours_seen(S, at_least=1) == 3


@pytest.fixture(scope="module")
def searched():
    return map_elites(synthetic, budget=310, seed=1)


def test_map_elites_spends_the_budget_within_the_bounds(searched):
    lo = np.array([p.low for p in V.parameters])
    hi = np.array([p.high for p in V.parameters])
    assert searched.P.shape == (310, 30) and searched.S.shape == (310, 9)
    assert np.all(searched.P >= lo) and np.all(searched.P <= hi)
    assert np.allclose(searched.S, synthetic(searched.P))
    # one cell per distinct verdict vector among the pours
    assert searched.cells == behaviours_seen(searched.S, at_least=1)


def test_map_elites_is_seeded_and_searches_beyond_the_prior(searched):
    again = map_elites(synthetic, budget=310, seed=1)
    assert np.array_equal(again.P, searched.P)
    assert not np.array_equal(map_elites(synthetic, budget=62, seed=2).P, searched.P[:62])
    # the emitter moves away from its prior start: more behaviours than as many prior pours
    prior = synthetic(sample([], 310, seed=1))
    assert behaviours_seen(searched.S) > behaviours_seen(prior)
