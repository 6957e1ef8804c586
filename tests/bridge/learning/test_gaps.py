"""The learner's own pours (bridge/learning/gaps.py): for the ordinary pour
and each proposition asked alone, enough pours that could have been drawn
for it."""
import numpy as np

from pantarhei.bridge.learning.gaps import gap_pours, thin_bodies
from pantarhei.oracle.generative import in_support, sample
from pantarhei.theory.lexicon import load_vocabulary

PROPS = sorted(load_vocabulary().propositions)


def test_with_no_pours_every_body_is_thin():
    thin = dict(thin_bodies(np.empty((0, 30)), 5))
    assert set(thin) == {()} | {(p,) for p in PROPS}
    assert set(thin.values()) == {5}


def test_pours_drawn_for_a_body_count_for_it_and_no_more_are_asked():
    P = np.vstack([sample([], 7, 1), sample(["heavy_liquid"], 12, 2)])
    thin = dict(thin_bodies(P, 12))
    assert thin[()] == 5                      # 7 ordinary pours of 12
    assert ("heavy_liquid",) not in thin
    # a heavy liquid's pours are not ordinary ones, nor a light liquid's
    assert thin[("light_liquid",)] == 12


def test_the_gap_pours_fill_every_body_and_are_seeded():
    P = sample(["pour_far_away", "heavy_liquid"], 20, 3)
    extra = gap_pours(P, 4, seed=9)
    assert np.array_equal(extra, gap_pours(P, 4, seed=9))
    assert not np.array_equal(extra, gap_pours(P, 4, seed=10))
    both = np.vstack([P, extra])
    assert thin_bodies(both, 4) == []
    assert in_support(extra, ["light_liquid"]).sum() >= 4
