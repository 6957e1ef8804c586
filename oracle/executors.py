"""Executors: where simulations run.

* `InlineExecutor`: in this process, one after the other (no protection
  against crashes or hangs; for debugging and rendering), if it was started
  with the oracle's environment; otherwise in one worker process that is.
* `LocalExecutor` (the default): worker processes on this machine, one per
  core. A simulation that kills its worker (a segfault, say) or runs past
  the time limit is recorded as failed and retried once in a fresh worker;
  the others go on.
* `RayExecutor`: tasks on a Ray cluster (or a local Ray started on demand),
  with the same failure handling.

Each lives in a module of its own (`inline_executor`, `local_executor`,
`ray_executor`), keeping to `execution.Executor`; this module names them,
once (`EXECUTORS`; the option table of theory/defaults.pl offers the same
names, and a test keeps the two equal).
Workers only simulate: they get (index, parameterization) and send back
the outcome; storing results is the caller's business (`on_result`). Every
worker is started with the oracle's `environment()` (the baseline math of
`baseline`), and checks that it was before it simulates.
"""
from __future__ import annotations

from types import MappingProxyType
from typing import Callable, Mapping, Optional

from pantarhei.oracle.execution import Executor
from pantarhei.oracle.inline_executor import InlineExecutor
from pantarhei.oracle.local_executor import LocalExecutor
from pantarhei.oracle.ray_executor import RayExecutor

#: Each executor by name, and how it starts (workers, a Ray cluster's address).
EXECUTORS: Mapping[str, Callable[[Optional[int], Optional[str]], Executor]] = MappingProxyType({
    "local": lambda workers, address: LocalExecutor(workers),
    "ray": lambda workers, address: RayExecutor(address, workers),
    "inline": lambda workers, address: InlineExecutor(),
})


def make_executor(name: str, workers: Optional[int] = None,
                  ray_address: Optional[str] = None) -> Executor:
    """The executor named `name` (ValueError for an unknown name)."""
    if name not in EXECUTORS:
        raise ValueError(f"unknown executor '{name}' (choose {', '.join(EXECUTORS)})")
    return EXECUTORS[name](workers, ray_address)
