"""describe(P): the generative models read backwards."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pantarhei.oracle.generative import describe, from_dict, sample
from pantarhei.theory.lexicon import load_vocabulary


def random_valid(seed: int) -> tuple[str, ...]:
    from pantarhei.bridge.reasoning.scenes import random_antecedents

    return random_antecedents(seed, 1)[0]


@pytest.mark.slow
@settings(derandomize=True, max_examples=60, deadline=None)
@given(seed=st.integers(0, 10**6), keep=st.integers(0, 2**30), draws=st.integers(0, 10**6))
def test_every_sample_is_described_by_a_superset_of_its_antecedent(seed, keep, draws):
    full = random_valid(seed)
    # any subset of a valid antecedent is valid: keep a random part of it
    a = tuple(p for i, p in enumerate(full) if keep >> (i % 30) & 1)
    for d in describe(sample(list(a), 20, draws)):
        assert set(a) <= set(d), sorted(set(a) - set(d))


def test_one_value_per_dimension_and_none_between_values():
    v = load_vocabulary()
    p = sample(["pour_to_side"], 1, 3)[0]
    row = {n: float(x) for n, x in zip(v.parameter_names, p)}
    row["pour_x"] = 100.0            # between pour_near_rim (40-95) and pour_to_side (105-165)
    row["particle_mass"] = 5000.0    # the lower end of heavy_liquid
    (d,) = describe(from_dict(row)[None, :])
    dims = [v.proposition(x).dimension for x in d]
    assert len(dims) == len(set(dims))
    assert "pour_alignment" not in dims
    assert "heavy_liquid" in d


def test_relative_models_are_judged_on_the_offset_from_their_base():
    v = load_vocabulary()
    row = {n: float(x) for n, x in zip(v.parameter_names, sample([], 1, 5)[0])}
    row.update(pour_x=60.0, start_x=160.0)     # 100 mm farther than the pour: moving closer
    (d,) = describe(from_dict(row)[None, :])
    assert "approach_moving_closer" in d and "approach_moving_away" not in d
    row.update(start_x=30.0)                   # 30 mm nearer: moving away
    (d,) = describe(from_dict(row)[None, :])
    assert "approach_moving_away" in d


def test_canonical_sorted_tuples():
    out = describe(sample(["light_liquid"], 5, 1))
    assert all(isinstance(d, tuple) and list(d) == sorted(set(d)) for d in out)
    assert describe(np.empty((0, 30))) == []
