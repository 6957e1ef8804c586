"""How the exploration reaches the oracle: the simulator it opens, the
oracle's identity (version and settings) and the seed of each iteration."""
from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from pantarhei.bridge.errors import UserError


def iteration_seed(seed: int, iteration: int) -> int:
    """The sampling seed of an iteration, derived from the run's seed."""
    return int(np.random.SeedSequence([int(seed), int(iteration)]).generate_state(1)[0])


def batch_seed(seed: int, iteration: int, attempt: int = 0) -> int:
    """The sampling seed of an iteration's batch: the iteration's own for
    its first candidate (attempt 0), one of its own for a candidate probed
    after others were set aside."""
    s = iteration_seed(seed, iteration)
    return s if not attempt else int(np.random.SeedSequence([s, int(attempt)]).generate_state(1)[0])


def open_simulator(oracle: str, executor: str = "local", workers: int | None = None,
                   store: str | Path | None = None, ray_address: str | None = None,
                   oracle_options: dict | None = None) -> Any:
    """The simulator: `simulate(P) -> scores` with NaN rows for failures,
    every result kept in the store and never simulated twice."""
    from pantarhei.oracle.simulator import make_simulator

    return make_simulator(oracle, executor=executor, workers=workers, store=str(store),
                          ray_address=ray_address, **(oracle_options or {}))


def oracle_identity(name: str, options: dict | None = None) -> tuple[str, dict]:
    """The oracle's version and settings (UserError for an unknown name)."""
    from pantarhei.oracle.base import ORACLES, make_oracle

    if name not in ORACLES:
        raise UserError(f"unknown oracle '{name}' (choose {' or '.join(ORACLES)})")
    try:
        o = make_oracle(name, **(options or {}))
    except ImportError as e:
        raise UserError(f"the {name} oracle cannot be loaded: {e}") from None
    return str(o.version), dict(o.settings())
