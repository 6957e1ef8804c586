"""The local executor (the default): worker processes on this machine,
one per core, each started afresh (`python -m pantarhei.oracle.worker`)
with the oracle's environment. A simulation that kills its worker (a
segfault, say) or runs past the time limit is recorded as failed and
retried once in a fresh worker; the others go on."""
from __future__ import annotations

import os
import pickle
import subprocess
import sys
import time
from collections import deque
from multiprocessing.connection import Connection, wait
from typing import Optional, Sequence

import numpy as np

from pantarhei.oracle import baseline
from pantarhei.oracle.base import Oracle
from pantarhei.oracle.execution import ATTEMPTS, Done, Executor, OnResult, died


class _Worker:
    """A worker process started afresh (`python -m pantarhei.oracle.worker`),
    so that nothing of the main process is inherited or re-imported; it
    talks over a pair of pipes."""

    def __init__(self, oracle_bytes: bytes, env: dict[str, str]):
        down_r, down_w = os.pipe()
        up_r, up_w = os.pipe()
        self.process = subprocess.Popen(
            [sys.executable, "-m", "pantarhei.oracle.worker", str(down_r), str(up_w)],
            pass_fds=(down_r, up_w), stdin=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            start_new_session=True, env=baseline.child_environment(env))
        os.close(down_r)
        os.close(up_w)
        self.send = Connection(down_w, readable=False)
        self.conn = Connection(up_r, writable=False)
        self.send.send_bytes(oracle_bytes)
        self.task: Optional[tuple[int, np.ndarray, int]] = None
        self.started = 0.0

    @property
    def exitcode(self) -> Optional[int]:
        try:
            return self.process.wait(1)
        except subprocess.TimeoutExpired:
            return None

    def kill(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()
        self.send.close()
        self.conn.close()

    def stop(self) -> None:
        try:
            self.send.send(None)
        except OSError:
            pass
        try:
            self.process.wait(2)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.send.close()
        self.conn.close()


class LocalExecutor(Executor):
    """Worker processes on this machine, started afresh (nothing of the main
    process, such as its Prolog engine, is inherited)."""
    name = "local"

    def __init__(self, workers: Optional[int] = None):
        self._workers = max(1, workers or os.cpu_count() or 1)
        self._pool: list[_Worker] = []
        self._oracle_bytes: Optional[bytes] = None
        self._env: dict[str, str] = {}

    @property
    def workers(self) -> int:
        return self._workers

    def _ensure(self, oracle: Oracle, n: int) -> None:
        b = pickle.dumps(oracle)
        if b != self._oracle_bytes:
            self.close()
            self._oracle_bytes = b
            self._env = oracle.environment()
        while len(self._pool) < min(self._workers, n):
            self._pool.append(_Worker(b, self._env))

    def run(self, oracle: Oracle, tasks: Sequence[tuple[int, np.ndarray]], on_result: OnResult,
            timeout: Optional[float]) -> None:
        if not tasks:
            return
        self._ensure(oracle, len(tasks))
        queue: deque[tuple[int, np.ndarray, int]] = deque((i, p, 1) for i, p in tasks)
        left = len(tasks)

        def failed(w: _Worker, why: str) -> None:
            nonlocal left
            assert w.task is not None
            i, p, attempt = w.task
            if attempt < ATTEMPTS:
                queue.appendleft((i, p, attempt + 1))
            else:
                left -= 1
                on_result(Done(i, None, None, why, attempt, time.perf_counter() - w.started))
            w.task = None

        try:
            while left:
                for w in self._pool:
                    if w.task is None and queue:
                        w.task = queue.popleft()
                        w.started = time.perf_counter()
                        try:
                            w.send.send((w.task[0], w.task[1]))
                        except OSError:
                            pass    # it died: its pipe reports it below
                busy = [w for w in self._pool if w.task is not None]
                wait_for = None
                if timeout is not None:
                    now = time.perf_counter()
                    wait_for = max(0.0, min(w.started + timeout - now for w in busy))
                ready = wait([w.conn for w in busy], wait_for)
                for k, w in enumerate(list(self._pool)):
                    if w.task is None:
                        continue
                    if w.conn in ready:
                        try:
                            i, scores, record, error, secs = w.conn.recv()
                        except (EOFError, OSError):
                            failed(w, died(w.exitcode))
                            self._replace(k, w, oracle)
                            continue
                        _, _, attempt = w.task
                        if error is None:
                            left -= 1
                            w.task = None
                            on_result(Done(i, scores, record, None, attempt, secs))
                        else:
                            failed(w, error)
                    elif timeout is not None and time.perf_counter() - w.started > timeout:
                        failed(w, f"timed out after {timeout:g} s")
                        self._replace(k, w, oracle)
        except BaseException:
            # interrupted: in-flight simulations are lost, the workers with them
            self.close()
            raise

    def _replace(self, k: int, w: _Worker, oracle: Oracle) -> None:
        """Kill worker k and start an idle one in its place."""
        w.kill()
        self._pool[k] = _Worker(self._oracle_bytes or pickle.dumps(oracle), self._env)

    def close(self) -> None:
        for w in self._pool:
            w.stop()
        self._pool = []
