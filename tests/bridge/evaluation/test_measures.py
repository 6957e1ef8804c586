"""The evaluation measures, on cases small enough to check by hand."""
import numpy as np
import pytest

from pantarhei.bridge.evaluation.measures import (FAILS, HOLDS, UNKNOWN, accuracy, distinct_behaviours,
                                         one_hot, tree_predictions, verdicts)


def test_accuracy_counts_only_decided_predictions():
    truth = np.zeros((4, 9), dtype=bool)
    truth[:2, 0] = True
    pred = np.full((4, 9), UNKNOWN)
    pred[:, 0] = [HOLDS, FAILS, FAILS, UNKNOWN]   # right, wrong, right, undecided
    a = accuracy(pred, truth)
    assert a.decided[0] == 3 and a.correct[0] == 2
    assert a.coverage[0] == pytest.approx(0.75)
    assert a.accuracy[0] == pytest.approx(2 / 3)
    assert np.isnan(a.accuracy[1]) and a.coverage[1] == 0
    assert a.overall_accuracy == pytest.approx(2 / 3)
    assert a.overall_coverage == pytest.approx(3 / 36)


def test_accuracy_refuses_mismatched_shapes():
    with pytest.raises(ValueError):
        accuracy(np.zeros((2, 9), dtype=int), np.zeros((3, 9), dtype=bool))


def test_verdicts_and_distinct_behaviours():
    s = np.array([[0.9] * 9, [0.1] * 9, [0.9] * 9, [0.5] * 9])
    v = verdicts(s)
    assert v[0].all() and not v[1].any() and not v[3].any()
    assert distinct_behaviours(v) == 2


def test_one_hot_marks_the_antecedent():
    X = one_hot([["pour_to_side", "pour_low"], []])
    assert X.shape == (2, 86) and X[0].sum() == 2 and X[1].sum() == 0


def test_tree_learns_a_rule_from_one_feature():
    # the verdict of expectation 8 (no_spill) fails exactly when pouring from the side
    rng = np.random.default_rng(0)
    pool = ["pour_low", "pour_high", "slow_approach", "fast_approach", "heavy_liquid"]
    train = [list(rng.choice(pool, 2, replace=False)) + (["pour_to_side"] if i % 2 else [])
             for i in range(60)]
    y = np.ones((60, 9), dtype=bool)
    y[:, 8] = [("pour_to_side" not in a) for a in train]
    test = [["pour_to_side", "pour_low"], ["pour_high"]]
    pred = tree_predictions(train, y, test, seed=1)
    assert list(pred[:, 8]) == [0, 1]
    assert (pred[:, :8] == 1).all()
