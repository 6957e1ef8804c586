"""Equation (1), the weights of bridge/exploration/weights.py, on
hand-computed cases."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.weights import log_densities, weight, weights
from pantarhei.oracle.generative import from_dict, sample, to_dict


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
