"""How finely a pour is simulated (`Fidelity`): PyBullet's defaults and the
settings chosen by measurement. Read by the oracle (`physics`), by the
world it builds (`world`) and by the stepping of a pour (`stepping`);
imports nothing of the oracle, so that none of them imports another for
it."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional


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
