"""The learners: each named here, each a function from pours to general rules.

A learner is called as `learn(P, S, seed, bodies)`: P (n x 30) the pours'
parameterizations, S (n x 9) their scores (a pour whose simulation failed
has NaN scores; the learner leaves it out), `seed` for whatever the
learner draws (the same pours and seed give the same rules), and `bodies`
the bodies its rules may have besides the empty one (None: the askable
bodies, `askable.py`). It returns a `general_rules.General`: per
expectation a default with the empty body (`g0_<E>`) and further rules
`g<i>_<E>`, each with its evidence and confidence, and their superiority.

`layers.learn_general` is the one door to a learner: the exploration
(`general_layer`, which explore/1 calls) and the evaluation
(`bridge/evaluation/pipeline.py`, `general_answers.py`) learn through it,
with `DEFAULT_LEARNER`. Adding a learner is a module in this folder with a
function of that interface, named in `LEARNERS`.
"""
from __future__ import annotations

from types import MappingProxyType
from typing import Mapping, Optional, Protocol, Sequence

import numpy as np

from pantarhei.bridge.learning import generalize
from pantarhei.bridge.learning.general_rules import General


class Learner(Protocol):
    """The interface of a learner (see the module's text)."""

    def __call__(self, P: np.ndarray, S: np.ndarray, seed: int,
                 bodies: Optional[Sequence[Sequence[str]]]) -> General: ...


#: Every learner, by name.
LEARNERS: Mapping[str, Learner] = MappingProxyType({
    "general": generalize.learn,
})

#: The learner the exploration and the evaluation use.
DEFAULT_LEARNER = "general"


def learner(name: str) -> Learner:
    """The learner named `name` (ValueError for an unknown name)."""
    if name not in LEARNERS:
        raise ValueError(f"unknown learner '{name}' (choose {', '.join(LEARNERS)})")
    return LEARNERS[name]
