"""The exploration's simulations (bridge/exploration/simulation.py): every
batch's seed derived from the run's, and the oracle named by its version
and settings, with one line for an unknown one."""
from __future__ import annotations

import sqlite3

import numpy as np
import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.simulation import (batch_seed, iteration_seed, open_simulator,
                                                     oracle_identity)
from pantarhei.oracle.generative import sample


def test_seeds_are_derived_and_distinct():
    assert batch_seed(1, 3) == batch_seed(1, 3, 0) == iteration_seed(1, 3)
    seeds = {batch_seed(s, i, a) for s in (1, 2) for i in range(1, 6) for a in range(3)}
    assert len(seeds) == 30
    assert iteration_seed(1, 3) == iteration_seed(1, 3)


def test_the_oracle_is_known_by_its_version_and_settings():
    version, settings = oracle_identity("synthetic")
    assert version and isinstance(settings, dict)
    with pytest.raises(UserError, match="unknown oracle 'nope'"):
        oracle_identity("nope")


def test_a_simulator_keeps_every_result_in_its_store(tmp_path):
    P = sample(["pour_to_side"], 4, seed=1)
    sim = open_simulator("synthetic", "inline", None, tmp_path / "s.sqlite")
    try:
        S = np.asarray(sim.simulate(P, progress=False))
    finally:
        sim.close()
    assert S.shape == (4, 9)
    with sqlite3.connect(tmp_path / "s.sqlite") as db:
        assert db.execute("SELECT count(*) FROM simulation_results").fetchone()[0] == 4
    again = open_simulator("synthetic", "inline", None, tmp_path / "s.sqlite")
    try:
        assert np.array_equal(np.asarray(again.simulate(P, progress=False)), S)
    finally:
        again.close()
