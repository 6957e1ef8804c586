"""The PyBullet oracle: a pour simulated and scored against the 9 expectations.

A fresh headless PyBullet world per simulation (so that every worker gives
the same result for the same parameterization): the ground, the destination
resting on it (free to slide or tip), the source held by a stiff constraint
that moves it from the start pose to the pouring pose (approach) and on to
the end pose (retreat), smoothstep-interpolated in position and slerped in
orientation, and the liquid as small spheres spawned at rest inside the
source at its start pose. Then everything settles.

This module is the oracle; how finely it simulates is `fidelity`'s
(`Fidelity`), the world is built and the source moved in `world`, the pour
is stepped, watched and recorded in `stepping`.
"""
from __future__ import annotations

from dataclasses import asdict, replace
from typing import Any

import numpy as np

from pantarhei.oracle import baseline, scoring
from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.fidelity import FIDELITIES, Fidelity
from pantarhei.oracle.stepping import run
from pantarhei.theory.lexicon import load_vocabulary


#: How the floating-point math of a pour is computed: "baseline", the same
#: routines on every x86-64 machine (see `baseline`), or "native", the ones
#: the libraries pick for this CPU (faster, not reproducible elsewhere).
MATHS = ("baseline", "native")


class PouringOracle(Oracle):
    """Scores a parameterization by simulating the pour in PyBullet."""
    name = "pybullet"
    version = "4"

    def __init__(self, fidelity: str | Fidelity = "chosen", math: str = "baseline",
                 **overrides: Any):
        if isinstance(fidelity, str):
            if fidelity not in FIDELITIES:
                raise ValueError(f"unknown fidelity '{fidelity}' (choose {', '.join(FIDELITIES)})")
            fidelity = FIDELITIES[fidelity]
        if math not in MATHS:
            raise ValueError(f"unknown math '{math}' (choose {', '.join(MATHS)})")
        self.fidelity = replace(fidelity, **overrides)
        self.math = math

    def settings(self) -> dict[str, Any]:
        return {**asdict(self.fidelity), "environment": self.environment()}

    def environment(self) -> dict[str, str]:
        return dict(baseline.ENVIRONMENT) if self.math == "baseline" else {}

    def cost(self, p: np.ndarray) -> float:
        """A rough relative cost of simulating p (for scheduling): particles
        times simulated seconds."""
        v = load_vocabulary()
        count = p[v.parameter("particle_count").index]
        ms = p[v.parameter("approach_duration").index] + p[v.parameter("retreat_duration").index]
        return float(count * (ms + self.fidelity.settle_ms / 4))

    def score(self, p: np.ndarray) -> Outcome:
        record = run(np.asarray(p, dtype=float), self.fidelity)
        return Outcome(scoring.scores(record), record)
