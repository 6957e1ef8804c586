"""What the evaluation's tests share: a theory learned from the synthetic
oracle (with its store and every pour its run simulated), small enough
that an evaluation of it runs in seconds; and two toy curiosities, one
whose theory is one layer and one whose theory is not."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore
from tests.conftest import toy_curiosity


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


@pytest.fixture(scope="session")
def toy_curiosities(tmp_path_factory):
    """Two toy curiosities loaded into the process's Prolog as
    interface.pl loads those of the list, and forgotten after: `one_layer`,
    whose theory is its learned layer alone, and `two_layers`, whose
    theory holds Algorithm 1's rules."""
    from pantarhei.bridge.engines.swipl import engine

    eng = engine()
    eng.use_module("curiosity")
    d = tmp_path_factory.mktemp("toys")
    for name, rules in (("one_layer", "false"), ("two_layers", "true")):
        path = d / f"{name}.pl"
        path.write_text(toy_curiosity(f"curiosity_layout_toy_{rules}", rules == "true"),
                        encoding="utf-8")
        eng.once("curiosity_interface:load_curiosity(C, F)", C=name, F=str(path))
    yield ("one_layer", "two_layers")
    eng.once("retractall(curiosity_interface:curiosity_module(one_layer, _)), "
             "retractall(curiosity_interface:curiosity_module(two_layers, _))")
