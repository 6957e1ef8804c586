"""What every executor keeps to: the `Executor` interface (simulate every
task, call `on_result` once per task as it finishes), the final word on a
task (`Done`), how many attempts a simulation gets, and how a failure is
worded."""
from __future__ import annotations

import signal
from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

import numpy as np

from pantarhei.oracle.base import Oracle

#: Attempts per simulation: the first and one retry.
ATTEMPTS = 2


@dataclass
class Done:
    """The final word on one task: scores and record, or the error of its
    last attempt."""
    index: int
    scores: Optional[np.ndarray]
    record: Optional[dict[str, Any]]
    error: Optional[str]
    attempts: int
    seconds: float


OnResult = Callable[[Done], None]


class Executor(ABC):
    name = ""

    @abstractmethod
    def run(self, oracle: Oracle, tasks: Sequence[tuple[int, np.ndarray]], on_result: OnResult,
            timeout: Optional[float]) -> None:
        """Simulate every (index, p) and call `on_result` once per task as
        it finishes (in the calling thread)."""

    @property
    def workers(self) -> int:
        return 1

    def close(self) -> None:
        pass


def error_line(e: BaseException) -> str:
    """An exception as one line of at most 500 characters."""
    return f"{type(e).__name__}: {e}".strip().splitlines()[0][:500]


def died(code: Optional[int]) -> str:
    """Why a worker process ended, from its exit code."""
    if code is not None and code < 0:
        try:
            return f"the worker died ({signal.Signals(-code).name})"
        except ValueError:
            pass
    return f"the worker died (exit code {code})"
