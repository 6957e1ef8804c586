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
(`bridge/evaluation/pipeline.py`, `general_answers.py`) learn through it.
Which learner is a setting: the `learner` row of the option table
(theory/defaults.pl), whose choices are the names of `LEARNERS` and whose
default is `default_learner()`; a learned theory records it
(`setting(learner, Name)`), and what learns a theory again reads it there
(`recorded_learner`). Adding a learner is a module in this folder with a
function of that interface, named in `LEARNERS` and among the choices of
the `learner` row.
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


def default_learner() -> str:
    """The name of the learner used where none is chosen: the default of
    the `learner` row of the option table (theory/defaults.pl)."""
    from pantarhei.theory import defaults

    return str(defaults()["learner"])


def learner(name: str | None = None) -> Learner:
    """The learner named `name` (None: `default_learner()`; ValueError for
    an unknown name)."""
    name = default_learner() if name is None else str(name)
    if name not in LEARNERS:
        raise ValueError(f"unknown learner '{name}' (choose {', '.join(LEARNERS)})")
    return LEARNERS[name]


def recorded_learner(settings: Mapping[str, Sequence]) -> str:
    """The learner a learned theory's setting/2 facts name (`settings`:
    key to values, as `bridge/theories/loading.settings` reads them), else
    `default_learner()` (a theory written before the learner was
    recorded, or by hand)."""
    values = settings.get("learner") or ()
    return str(values[0]) if values else default_learner()


def known_recorded_learner(settings: Mapping[str, Sequence], source: object) -> str:
    """recorded_learner, refused in one line (UserError naming `source`,
    the theory) when this version knows no learner of that name: what
    learns a theory's pours again (the evaluation, plan's refuted plans)
    reads its learner here."""
    from pantarhei.bridge.errors import UserError

    name = recorded_learner(settings)
    try:
        learner(name)
    except ValueError as e:
        raise UserError(f"{source}: setting(learner, _): {e}") from None
    return name
