"""Which pours lie in the support of each body (could have been drawn for
it), kept as the pours grow: each step of the learning curiosity asks it
of hundreds of bodies, and the pours it asks of are the last step's and
a batch more."""
from __future__ import annotations

from typing import Sequence

import numpy as np

from pantarhei.oracle.generative import in_support


class Support:
    """Which pours of P lie in the support of each body (could have been
    drawn for it), each body's computed once for each pour: a step asks
    it for the value of a candidate and for the newness its own pours
    showed, and the next step's pours are these and more (`grown`)."""

    def __init__(self, P: np.ndarray) -> None:
        self.P = P
        self.masks: dict[tuple[str, ...], np.ndarray] = {}

    def grown(self, P: np.ndarray) -> Support:
        """This support for P, whose first rows are this one's pours."""
        self.P = P
        return self

    def __call__(self, body: Sequence[str]) -> np.ndarray:
        key = tuple(body)
        mask = self.masks.get(key, np.zeros(0, dtype=bool))
        if len(mask) < len(self.P):
            mask = np.concatenate([mask, in_support(self.P[len(mask):], key)])
            self.masks[key] = mask
        return mask
