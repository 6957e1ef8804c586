"""The inline executor: simulations in this process, one after the other
(no protection against crashes or hangs; for debugging and rendering), if
it was started with the oracle's environment; otherwise in one worker
process that is."""
from __future__ import annotations

import time
from typing import Optional, Sequence

import numpy as np

from pantarhei.oracle import baseline
from pantarhei.oracle.base import Oracle
from pantarhei.oracle.execution import ATTEMPTS, Done, Executor, OnResult, error_line
from pantarhei.oracle.local_executor import LocalExecutor


class InlineExecutor(Executor):
    """In this process, one at a time; an exception is retried once. A
    process not started with the oracle's environment would compute other
    numbers: then the simulations run in one worker process that is."""
    name = "inline"

    def __init__(self) -> None:
        self._worker: Optional[LocalExecutor] = None

    def run(self, oracle: Oracle, tasks: Sequence[tuple[int, np.ndarray]], on_result: OnResult,
            timeout: Optional[float]) -> None:
        if not baseline.started_with(oracle.environment()):
            if self._worker is None:
                self._worker = LocalExecutor(1)
            self._worker.run(oracle, tasks, on_result, timeout)
            return
        for i, p in tasks:
            err = None
            for attempt in range(1, ATTEMPTS + 1):
                t0 = time.perf_counter()
                try:
                    out = oracle.score(p)
                except Exception as e:  # recorded as a failed simulation
                    err = error_line(e)
                    continue
                on_result(Done(i, out.scores, out.record, None, attempt, time.perf_counter() - t0))
                break
            else:
                on_result(Done(i, None, None, err, ATTEMPTS, 0.0))

    def close(self) -> None:
        if self._worker is not None:
            self._worker.close()
            self._worker = None
