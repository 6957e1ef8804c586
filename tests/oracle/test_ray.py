"""The Ray executor on a local Ray (2 CPUs, loopback): the same results as
the local workers, and the same handling of crashes and hangs."""
from __future__ import annotations

import numpy as np
import pytest

from pantarhei.oracle.executors import RayExecutor
from pantarhei.oracle.faults import FaultyOracle
from pantarhei.theory.lexicon import load_vocabulary

COUNT = load_vocabulary().parameter("particle_count").index
from pantarhei.oracle.generative import sample
from pantarhei.oracle.physics import PouringOracle
from pantarhei.oracle.simulator import Simulator

from .pours import CENTRED_LOW_TIPPED, HEAVY_DROP, pour

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def ray_executor():
    ex = RayExecutor(address=None, workers=2)
    assert ex.workers == 2
    yield ex
    ex.close()


def test_ray_gives_the_same_scores_as_this_machine(ray_executor, tmp_path):
    P = np.array([pour(**CENTRED_LOW_TIPPED), pour(**HEAVY_DROP)])
    here = np.array([PouringOracle().score(p).scores for p in P])
    sim = Simulator(PouringOracle(), ray_executor, store=None, timeout=120)
    assert np.array_equal(sim.simulate(P), here)
    assert all(r is not None and "fractions" in r for r in sim.last_records)


def test_ray_records_a_crash_and_a_hang_as_failed(ray_executor):
    P = sample([], 4, seed=3)
    P[:, COUNT] = [50, 51, 52, 53]
    sim = Simulator(FaultyOracle(crash=[51], hang=[52]), ray_executor, store=None, timeout=3)
    S = sim.simulate(P)
    assert np.isnan(S[1]).all() and np.isnan(S[2]).all()
    assert "timed out" in sim.last_errors[2]
    good = FaultyOracle()
    assert np.array_equal(S[[0, 3]], np.array([good.score(P[i]).scores for i in (0, 3)]))
