"""The PyBullet oracle: a pour simulated and scored against the 9 expectations.

A fresh headless PyBullet world per simulation (so that every worker gives
the same result for the same parameterization): the ground, the destination
resting on it (free to slide or tip), the source held by a stiff constraint
that moves it from the start pose to the pouring pose (approach) and on to
the end pose (retreat), smoothstep-interpolated in position and slerped in
orientation, and the liquid as small spheres spawned at rest inside the
source at its start pose. Then everything settles.

This module is the oracle and its settings (`Fidelity`); the world is built
and the source moved in `world`, the pour is stepped, watched and recorded
in `stepping`.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from typing import Any, Optional

import numpy as np

from pantarhei.oracle import baseline, scoring
from pantarhei.oracle.base import Oracle, Outcome
from pantarhei.oracle.stepping import run
from pantarhei.theory.lexicon import load_vocabulary


@dataclass(frozen=True)
class Fidelity:
    """How finely a pour is simulated (part of the key of stored results)."""
    rate_hz: int = 240               # physics steps per second
    solver_iterations: int = 50
    settle_ms: int = 2000            # longest settling after the retreat
    early_stop: bool = False         # stop settling once everything is at rest
    particle_radius_mm: Optional[float] = None   # None: the scene's
    sample_hz: int = 60              # observations per second
    rest_speed: float = 0.02         # m/s: at rest below this speed
    ccd: bool = True                 # continuous collision detection for particles
    contact_mm: float = 20.0         # contact breaking threshold (PyBullet's default: 20 mm)

    def describe(self) -> str:
        return (f"{self.rate_hz} Hz, {self.solver_iterations} solver iterations, settle "
                f"{self.settle_ms} ms{' or until at rest' if self.early_stop else ''}")


#: PyBullet's defaults: 240 Hz, 50 solver iterations, the full duration.
DEFAULT_FIDELITY = Fidelity()
#: The settings chosen by measurement (`python -m benchmarks.oracle`).
#: Measured on 40 pours (two seeds of the benchmark's set) against the
#: defaults: 180 Hz agrees on 346 of 360 verdicts at 4.4-5.1x the speed,
#: 120 Hz on 342 at 6-7x; 180 Hz keeps a margin over 95%. 10 solver
#: iterations, a 2 mm contact threshold and the early stop cost no agreement.
CHOSEN_FIDELITY = Fidelity(rate_hz=180, solver_iterations=10, settle_ms=2000, early_stop=True,
                           sample_hz=30, contact_mm=2.0)
FIDELITIES = {"default": DEFAULT_FIDELITY, "chosen": CHOSEN_FIDELITY}


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
