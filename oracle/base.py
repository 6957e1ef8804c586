"""What every oracle is: a deterministic function from a parameterization
to the 9 expectation scores.

An oracle is named in ORACLES and built by `make_oracle(name)`. It must be
picklable (it runs in worker processes) and deterministic: the same
parameterization gives the same scores in every run and every worker, on
every machine, when computed in a process started with its `environment()`.
"""
from __future__ import annotations

import importlib
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Any

import numpy as np

#: Oracle name -> "module:Class" under pantarhei.oracle.
ORACLES = {
    "pybullet": "pantarhei.oracle.physics:PouringOracle",
    "synthetic": "pantarhei.oracle.synthetic:SyntheticOracle",
    "faulty": "pantarhei.oracle.faults:FaultyOracle",   # test-only: really crashes or hangs
}
#: The oracles that simulate the world; the others are for tests (analytic
#: scores, faults), and `plan` verifies with none of them.
REAL_ORACLES = ("pybullet",)


@dataclass
class Outcome:
    """The scores of one simulation (in the vocabulary's expectation order,
    each in [0, 1]) and a short record of what happened."""
    scores: np.ndarray
    record: dict[str, Any] = field(default_factory=dict)


class Oracle(ABC):
    #: Short name, as in ORACLES.
    name: str = ""
    #: Bumped whenever the same parameterization may score differently.
    version: str = "0"

    def settings(self) -> dict[str, Any]:
        """Everything besides the parameterization that the scores depend on
        (JSON-serialisable): part of the key of stored results."""
        return {}

    def environment(self) -> dict[str, str]:
        """Environment variables a process must be started with to compute
        these scores (see `baseline`); executors start their workers with
        them. An oracle with any includes them in `settings()`."""
        return {}

    @abstractmethod
    def score(self, p: np.ndarray) -> Outcome:
        """Simulate one parameterization (30 numbers, theory units)."""


def make_oracle(name: str, **options: Any) -> Oracle:
    """Build the oracle called `name` (KeyError if there is none)."""
    module, cls = ORACLES[name].split(":")
    return getattr(importlib.import_module(module), cls)(**options)
