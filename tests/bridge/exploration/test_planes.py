"""The weighted plane fits of bridge/exploration/planes.py, on known
linear functions."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.planes import best_abs_slope, plane_fit
from pantarhei.oracle.generative import normalise, sample


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
