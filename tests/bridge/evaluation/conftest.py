"""What the evaluation's tests share: a theory learned from the synthetic
oracle (with its store and every pour its run simulated), small enough
that an evaluation of it runs in seconds."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore


@pytest.fixture(scope="session")
def explored(tmp_path_factory) -> tuple[Path, Path, tuple[np.ndarray, np.ndarray]]:
    """The discovering curiosity, which probes candidates and sets some
    aside: its theory, its store and every pour it simulated. Without the
    priors' batch (prior_batch(0), an option of explore/1 alone): with it,
    this small run's last antecedent ends past the last whole batch both
    methods are compared at."""
    d = tmp_path_factory.mktemp("learned")
    r = explore(ExploreOptions(oracle="synthetic", executor="inline", progress=False,
                               curiosity="discover", prior_batch=0, budget=6, batch=12,
                               out=d / "t.pl", store=d / "s.sqlite"))
    return d / "t.pl", d / "s.sqlite", r["pours"]


@pytest.fixture(scope="session")
def learned(explored) -> tuple[Path, Path]:
    """The theory and its store."""
    return explored[0], explored[1]
