"""The permutation test of the planes (bridge/exploration/significance.py):
on noise and a known slope, against the plane fits, and on real PyBullet
pours: a_0 and three neighbours, simulated once through a store kept in
pytest's cache (later runs read it). Both bowls are round, so the yaw of
the source (start, pour, end) cannot change what happens: no plane may
call it significant."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.bridge.exploration.planes import plane_fit
from pantarhei.bridge.exploration.significance import permutation_test, shuffle_seed
from pantarhei.bridge.exploration.simulation import iteration_seed, open_simulator
from pantarhei.bridge.exploration.weights import log_densities, weights
from pantarhei.oracle.generative import normalise, sample
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

V = load_vocabulary()
YAW = [V.parameter_names.index(x) for x in ("start_yaw", "pour_yaw", "end_yaw")]
A0 = ["pour_mid_height", "pour_near_rim", "pour_steeply_tilted"]
NEIGHBOURS = [["pour_low", "pour_near_rim", "pour_steeply_tilted"],
              ["pour_mid_height", "pour_to_side", "pour_steeply_tilted"],
              ["pour_half_tilted", "pour_mid_height", "pour_near_rim"]]


@pytest.fixture(scope="module")
def pours(request, tmp_path_factory):
    # kept in pytest's cache between runs when it has one: simulated once
    cache = getattr(request.config, "cache", None)
    folder = (cache.mkdir("pantarhei-pybullet-pours") if cache is not None
              else tmp_path_factory.mktemp("pybullet-pours"))
    store = folder / "store.sqlite"
    ants = [A0] + NEIGHBOURS
    P = np.vstack([sample(a, 31 if i == 0 else 10, iteration_seed(1, i + 1))
                   for i, a in enumerate(ants)])
    sim = open_simulator("pybullet", "local", 1, store)
    try:
        S = np.asarray(sim.simulate(P, progress=False), dtype=float)
    finally:
        sim.close()
    ok = np.all(np.isfinite(S), axis=1)
    return ants, P[ok], S[ok]


def test_yaw_is_never_a_significant_direction(pours):
    ants, P, S = pours
    W = weights(log_densities(P, ants))
    d = defaults()
    alpha, ridge, shuffles = float(d["significance"]), float(d["ridge"]), int(d["permutations"])
    found = 0
    for i in range(len(ants)):
        t = permutation_test(normalise(P), S, W[i], ridge, shuffles,
                             shuffle_seed(1, i + 1, int((W[i] > 0).sum())))
        sig = t.significant(alpha)
        assert not sig[:, YAW].any(), (ants[i], np.argwhere(sig[:, YAW]))
        found += int(sig.any())
    # the test sees signal in these pours: it is not silent everywhere
    assert found >= 1


def test_noise_is_not_significant_and_a_real_slope_is():
    rng = np.random.default_rng(5)
    X = rng.random((60, 30))
    noise = rng.random((60, 9))
    t = permutation_test(X, noise, np.ones(60), 1.0, 199, seed=1)
    assert not t.significant(0.05).any()
    signal = noise.copy()
    signal[:, 4] = np.clip(X[:, 7] * 1.5 - 0.2, 0, 1)   # expectation 4 follows parameter 7
    t = permutation_test(X, signal, np.ones(60), 1.0, 199, seed=1)
    sig = t.significant(0.05)
    assert sig[4, 7] and sig.sum() == 1
    assert t.slopes(0.05)[4] == pytest.approx(abs(t.coef[4, 7]))
    # the same seed, the same shuffles
    again = permutation_test(X, signal, np.ones(60), 1.0, 199, seed=1)
    assert np.array_equal(again.p, t.p)


def test_the_planes_are_the_weighted_ridge_fits():
    rng = np.random.default_rng(3)
    X, S, w = rng.random((40, 30)), rng.random((40, 9)), rng.random(40)
    w[:5] = 0.0                                          # pours of other antecedents
    t = permutation_test(X, S, w, 1.0, 19, seed=0)
    planes = plane_fit(X, S, w, 1.0)
    assert np.allclose(t.coef, planes.coef) and np.allclose(t.mean, planes.mean)
    assert t.used == 35
