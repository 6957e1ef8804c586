"""Which pours lie in each body's support, kept as the pours grow
(bridge/exploration/pour_support.py)."""
from __future__ import annotations

import numpy as np

from pantarhei.bridge.exploration.pour_support import Support
from pantarhei.oracle.generative import in_support, sample

BODIES = [(), ("pour_to_side",), ("light_liquid", "pour_high"), ("pour_near_rim",)]


def test_a_grown_support_is_that_of_every_pour() -> None:
    """Asked, then grown by more pours and asked again, a Support gives
    each body the pours of all of them in its support, as a new one does."""
    P = np.vstack([sample(list(b), 6, i) for i, b in enumerate(BODIES)])
    support = Support(P[:7])
    first = [support(b).copy() for b in BODIES[:2]]
    support = support.grown(P)
    for b, m in zip(BODIES[:2], first):
        np.testing.assert_array_equal(m, in_support(P[:7], b))
    for b in BODIES:
        np.testing.assert_array_equal(support(b), in_support(P, b))
        assert len(support(b)) == len(P)
