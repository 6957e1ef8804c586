"""What a general rule means (bridge/learning/meaning.py): P(e | B), the
share of the pours `simulate --antecedent B` samples for B in which e
holds, learned from pours and their verdicts; NaN for a body that cannot
be sampled."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.learning.generalize import Settings
from pantarhei.bridge.learning.meaning import Meaning
from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

NAMES = load_vocabulary().expectation_names
MASS = load_vocabulary().parameter_names.index("particle_mass")
E = NAMES.index("no_spill")


def test_the_share_of_a_body_s_pours_that_keep_the_expectation() -> None:
    """A light liquid (100 to 800 mg a particle) always spills, any other
    never: the ordinary pour (1500 to 3000) and a heavy liquid keep no
    spill, a light liquid does not, pour from the side or not."""
    P = np.vstack([sample([], 120, 1), sample(["light_liquid"], 60, 2), sample(["heavy_liquid"], 60, 3)])
    Y = np.ones((len(P), len(NAMES)), dtype=bool)
    Y[:, E] = P[:, MASS] > 800
    meaning = Meaning(P, Y, Settings(seed=1, draws=16))
    T = meaning([(), ("light_liquid",), ("heavy_liquid",), ("light_liquid", "pour_to_side"),
                 ("light_liquid", "heavy_liquid")])
    assert T.shape == (5, len(NAMES))
    assert T[0, E] > 0.9 and T[2, E] > 0.9
    assert T[1, E] < 0.1 and T[3, E] < 0.1
    assert np.isnan(T[4]).all()                       # a liquid both light and heavy: no pour
    assert (np.delete(T[:4], E, axis=1) == 1.0).all()   # what always held holds


def test_a_body_asked_again_gets_the_same_estimate() -> None:
    """A model asked about bodies it estimated before (in another order,
    twice in one request, beside new ones) gives each the estimate a fresh
    model gives it; a body that cannot be sampled stays NaN."""
    P = np.vstack([sample([], 120, 1), sample(["light_liquid"], 60, 2)])
    Y = np.ones((len(P), len(NAMES)), dtype=bool)
    Y[:, E] = P[:, MASS] > 800
    bodies = [(), ("light_liquid",), ("pour_to_side",), ("light_liquid", "heavy_liquid")]
    once = Meaning(P, Y, Settings(seed=1, draws=16))(bodies)
    kept = Meaning(P, Y, Settings(seed=1, draws=16))
    kept(bodies[1:3])
    again = kept([bodies[2], *bodies, bodies[0]])
    np.testing.assert_array_equal(again[1:5], once)
    np.testing.assert_array_equal(again[0], once[2])
    np.testing.assert_array_equal(again[5], once[0])
