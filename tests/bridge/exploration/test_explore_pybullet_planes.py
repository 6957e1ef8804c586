"""The permutation test on real PyBullet pours: a_0 and three neighbours,
simulated once through a store kept in pytest's cache (later runs read it).
Both bowls are round, so the yaw of the source (start, pour, end) cannot
change what happens: no plane may call it significant."""
from __future__ import annotations

import numpy as np
import pytest

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
