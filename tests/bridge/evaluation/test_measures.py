"""The evaluation measures, on cases small enough to check by hand."""
import numpy as np
import pytest

from pantarhei.bridge.evaluation.measures import accuracy, distinct_behaviours, one_hot, tree_predictions
from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN, verdicts


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


def test_the_defaults_only_theory_and_its_contrast_keys():
    from pantarhei.bridge.evaluation.measures import contrast_keys, defaults_only

    Y = np.array([[1, 0], [1, 0], [0, 0], [1, 1]], dtype=bool)     # 3/4 hold, 1/4 hold
    verdict, share = defaults_only(Y, 2)
    assert verdict.tolist() == [[1, 0], [1, 0]] and share.tolist() == [[0.75, 0.25]] * 2
    key = np.array([[True, True], [False, False]])
    clear = np.array([[True, True], [True, False]])
    # where the defaults answer wrongly, among the clear keys only
    assert contrast_keys(key, clear, verdict).tolist() == [[False, True], [True, False]]


def test_calibration_is_the_mean_gap_over_the_keys_with_a_likelihood():
    from pantarhei.bridge.evaluation.measures import calibration

    share = np.array([[0.5, 1.0], [0.0, 0.2]])
    assert calibration(np.array([[0.7, 1.0], [np.nan, 0.0]]), share) == pytest.approx(0.4 / 3)
    assert calibration(np.full((2, 2), np.nan), share) is None


def test_an_answer_is_coherent_when_one_of_its_pours_shows_it():
    from pantarhei.bridge.evaluation.measures import coherent
    from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN

    # question 0's pours: (leaves, enters) = (1, 1) and (1, 0); question 1's: (0, 0)
    V = np.array([[1, 1], [1, 0], [0, 0]], dtype=bool)
    of = np.array([0, 0, 1])
    answers = np.array([[HOLDS, FAILS], [FAILS, HOLDS]])
    assert coherent(answers, V, of).tolist() == [True, False]
    # an undecided verdict constrains nothing
    assert coherent(np.array([[FAILS, UNKNOWN], [FAILS, UNKNOWN]]), V, of).tolist() == [False, True]
