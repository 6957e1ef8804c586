"""How the exploration reaches the oracle: the simulator it opens, the
oracle's identity (version and settings), the seed of each iteration, and
the pours of a run drawn again from its trace."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary

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


def batch_pours(antecedent: Sequence[str], batch: int, seed: int, iteration: int,
                attempt: int = 0) -> np.ndarray:
    """The batch of `batch` pours of an iteration's attempt: sampled for
    the antecedent with batch_seed's seed (the run's `seed`); a probe and
    the rest of its batch, or a draw read back from the trace, are slices
    of it."""
    return sample(list(antecedent), batch, batch_seed(seed, iteration, attempt))


@dataclass(frozen=True)
class Draw:
    """Pours of one step of a run as its trace line records them (`draws`,
    written by draws/6 of theory/curiosity/loop.pl): pours `first` to
    `last` - 1 of the batch of `batch` pours of `antecedent` sampled with
    the seed of the step's iteration and `attempt`."""
    #: The index of the step's trace line.
    step: int
    iteration: int
    antecedent: tuple[str, ...]
    attempt: int
    first: int
    last: int
    #: Whether the pours are the explored antecedent's (its batch, or its
    #: probe when it was kept), not a probe of a candidate set aside.
    explored: bool


def trace_draws(trace: Sequence[dict]) -> list[Draw]:
    """Every draw of a run's trace, in the order its pours were simulated;
    ValueError for a line without its draws (a trace written before they
    were recorded)."""
    out = []
    for step, line in enumerate(trace):
        try:
            draws = line["draws"]
            chosen = int(draws[-1]["attempt"])
            for d in draws:
                first, last = (int(x) for x in d["pours"])
                out.append(Draw(step, int(line["iteration"]), tuple(str(p) for p in d["antecedent"]),
                                int(d["attempt"]), first, last, int(d["attempt"]) == chosen))
        except (KeyError, IndexError, TypeError, ValueError):
            raise ValueError(f"line {step + 1} of the trace does not record its draws") from None
    return out


def drawn_pours(draws: Sequence[Draw], seed: int, batch: int) -> np.ndarray:
    """The pours of `draws`, drawn again as the run drew them (its `seed`,
    `batch` pours a batch), in order: (pours, parameters)."""
    rows = [batch_pours(d.antecedent, batch, seed, d.iteration, d.attempt)[d.first:d.last]
            for d in draws]
    if not rows:
        return np.empty((0, len(load_vocabulary().parameters)))
    return np.vstack(rows)


def open_simulator(oracle: str, executor: str | None = None, workers: int | None = None,
                   store: str | Path | None = None, ray_address: str | None = None,
                   oracle_options: dict | None = None) -> Any:
    """The simulator: `simulate(P) -> scores` with NaN rows for failures,
    every result kept in the store and never simulated twice; the executor
    by default theory/defaults.pl's (make_simulator)."""
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
