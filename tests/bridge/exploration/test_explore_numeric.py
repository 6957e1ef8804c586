"""Equation (1) and the plane fits, on hand-computed cases."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.planes import best_abs_slope, plane_fit
from pantarhei.bridge.exploration.weights import log_densities, weight, weights
from pantarhei.bridge.exploration.qualify import consequent as outcome
from pantarhei.oracle.generative import from_dict, normalise, sample, to_dict
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()


def with_values(**values):
    p = to_dict(sample([], 1, seed=0)[0])
    p.update(values)
    return from_dict(p)


def test_weight_by_hand_two_antecedents():
    # pour_low draws pour_z from [0, 60]; the prior (the ordinary pour) from
    # [50, 120]; every other parameter has the same density under both.
    p = with_values(pour_z=55.0)
    low, free = ["pour_low"], []
    assert weight(low, p, [low, free]) == pytest.approx((1 / 60) / (1 / 60 + 1 / 70))
    assert weight(free, p, [low, free]) == pytest.approx((1 / 70) / (1 / 60 + 1 / 70))
    assert weight(low, p, [low]) == pytest.approx(1.0)


def test_weight_by_hand_three_antecedents_and_outside_support():
    # pour_near_rim draws pour_x from [40, 95], the prior from [0, 80]
    a, b, c = ["pour_low"], ["pour_low", "pour_near_rim"], []
    inside = with_values(pour_z=55.0, pour_x=60.0)
    da = (1 / 60) * (1 / 80)       # pour_z, pour_x under a
    db = (1 / 60) * (1 / 55)
    dc = (1 / 70) * (1 / 80)
    total = da + db + dc
    for ant, d in ((a, da), (b, db), (c, dc)):
        assert weight(ant, inside, [a, b, c]) == pytest.approx(d / total)
    outside = with_values(pour_z=100.0, pour_x=60.0)
    assert weight(a, outside, [a, b, c]) == 0.0
    assert weight(b, outside, [a, b, c]) == 0.0
    assert weight(c, outside, [a, b, c]) == pytest.approx(1.0)


def test_weights_in_log_space_do_not_underflow():
    ld = np.array([[-2000.0, -5000.0], [-2000.0 - np.log(3), -np.inf]])
    w = weights(ld)
    assert w[:, 0] == pytest.approx([0.75, 0.25])
    assert w[:, 1] == pytest.approx([1.0, 0.0])
    assert np.all(weights(np.full((2, 1), -np.inf)) == 0)


def test_weights_columns_sum_to_one_over_real_antecedents():
    ants = [["pour_low"], ["pour_mid_height", "light_liquid"], [], ["pour_to_side"]]
    P = np.vstack([sample(a, 20, seed=i) for i, a in enumerate(ants)])
    w = weights(log_densities(P, ants))
    assert w.shape == (4, 80)
    assert np.allclose(w.sum(axis=0), 1.0)
    own = np.repeat(np.arange(4), 20)     # each pour lies in the support it was drawn from
    assert np.all(w[own, np.arange(80)] > 0)
    assert np.all(w[2, 60:] == 0)         # the ordinary pour never pours from the side


def test_plane_fit_recovers_a_linear_function_and_the_steepest_plane():
    P = sample([], 200, seed=1)
    X = normalise(P)
    rng = np.random.default_rng(2)
    coef = np.zeros((9, 30))
    coef[3, 5] = 0.8
    coef[6, [2, 7]] = [-0.3, 0.25]
    S = 0.1 + X @ coef.T
    w = rng.uniform(0.1, 1.0, len(P))
    planes = plane_fit(X, S, w)
    assert np.allclose(planes.coef, coef, atol=1e-9)
    best = best_abs_slope(planes)
    assert best.expectation == 3 and best.slope == pytest.approx(0.8)
    assert np.argmax(np.abs(best.gradient)) == 5
    # rows with NaN scores or no weight take no part
    S2 = S.copy()
    S2[:5] = np.nan
    w2 = w.copy()
    w2[5:10] = 0
    planes2 = plane_fit(X, S2, w2)
    assert planes2.used == len(P) - 10
    assert np.allclose(planes2.coef, coef, atol=1e-9)
    assert plane_fit(X[:1], S[:1], w[:1]) is None


def test_ridge_shrinks_but_keeps_the_direction():
    P = sample([], 31, seed=3)
    X = normalise(P)
    S = np.zeros((31, 9))
    S[:, 0] = 0.2 + 0.6 * X[:, 10]
    plain = best_abs_slope(plane_fit(X, S, np.ones(31)))
    ridged = best_abs_slope(plane_fit(X, S, np.ones(31), ridge=1.0))
    assert np.argmax(np.abs(plain.gradient)) == np.argmax(np.abs(ridged.gradient)) == 10
    assert ridged.slope < plain.slope


def test_outcome_weighted_vote_and_argmax():
    S = np.array([[0.9] * 9, [0.2] * 9, [0.3] * 9])
    w = np.array([0.5, 0.3, 0.4])
    weighted = outcome(S, w, "weighted")
    assert [o["holds"] for o in weighted["outcomes"]] == [False] * 9   # 0.7 of the weight fails
    assert weighted["outcomes"][0]["confidence_permille"] == round(1000 * 0.7 / 1.2)
    assert weighted["weight_mass_permille"] == 1200 and weighted["simulations"] == 3
    argmax = outcome(S, w, "argmax")
    assert argmax["sample"] == 0
    assert [o["holds"] for o in argmax["outcomes"]] == [True] * 9
    assert argmax["outcomes"][0]["confidence_permille"] == round(1000 * 0.5 / 1.2)
