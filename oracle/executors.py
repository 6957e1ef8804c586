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

Workers only simulate: they get (index, parameterization) and send back
the outcome; storing results is the caller's business (`on_result`). Every
worker is started with the oracle's `environment()` (the baseline math of
`baseline`), and checks that it was before it simulates.
"""
from __future__ import annotations

import os
import pickle
import signal
import subprocess
import sys
import threading
import time
from abc import ABC, abstractmethod
from collections import deque
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from types import MappingProxyType
from typing import Any, Callable, Optional, Sequence

import numpy as np

from pantarhei.oracle import baseline
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


def _error(e: BaseException) -> str:
    return f"{type(e).__name__}: {e}".strip().splitlines()[0][:500]


def _died(code: Optional[int]) -> str:
    if code is not None and code < 0:
        try:
            return f"the worker died ({signal.Signals(-code).name})"
        except ValueError:
            pass
    return f"the worker died (exit code {code})"


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
                    err = _error(e)
                    continue
                on_result(Done(i, out.scores, out.record, None, attempt, time.perf_counter() - t0))
                break
            else:
                on_result(Done(i, None, None, err, ATTEMPTS, 0.0))

    def close(self) -> None:
        if self._worker is not None:
            self._worker.close()
            self._worker = None


# ----------------------------------------------------------------------------
# worker processes on this machine

def _exit_with_parent() -> None:
    """End this process as soon as its parent is gone (killed, say), even in
    the middle of a simulation."""
    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(3)

    threading.Thread(target=watch, daemon=True).start()


def worker_main(conn: Connection) -> None:
    """A worker: receive the oracle, then score what it is sent until it is
    sent None (run by `python -m pantarhei.oracle.worker`)."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)     # the physics engine's chatter must not reach the terminal
    _exit_with_parent()
    oracle: Oracle = pickle.loads(conn.recv_bytes())
    missing = baseline.unmet(oracle.environment())
    while True:
        try:
            msg = conn.recv()
        except (EOFError, OSError, KeyboardInterrupt):
            return
        if msg is None:
            return
        i, p = msg
        t0 = time.perf_counter()
        try:
            if missing:
                baseline.require(oracle.environment())
            out = oracle.score(p)
            conn.send((i, out.scores, out.record, None, time.perf_counter() - t0))
        except Exception as e:
            conn.send((i, None, None, _error(e), time.perf_counter() - t0))


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
                            failed(w, _died(w.exitcode))
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


# ----------------------------------------------------------------------------
# Ray

def _ray_score(oracle: Oracle, p: np.ndarray) -> tuple[np.ndarray, dict[str, Any], float]:
    baseline.require(oracle.environment())
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = os.dup(1)
    os.dup2(devnull, 1)
    try:
        t0 = time.perf_counter()
        out = oracle.score(p)
        return out.scores, out.record, time.perf_counter() - t0
    finally:
        os.dup2(saved, 1)
        os.close(saved)
        os.close(devnull)


#: Keeps a local Ray on loopback. Ray reads it when it is imported: it then
#: takes 127.0.0.1 as the node's address (ray.init turns a loopback
#: `_node_ip_address` into the machine's own), and its servers, the raylet's,
#: the workers' and the runtime-environment agent's listen there only.
LOCAL_RAY_ENV = MappingProxyType({"RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER": "0"})


def _import_ray_for_local() -> Any:
    """Ray, imported so that a local instance stays on loopback (RuntimeError
    if it was imported before without it)."""
    if "ray" not in sys.modules:
        saved = {k: os.environ.get(k) for k in LOCAL_RAY_ENV}
        os.environ.update(LOCAL_RAY_ENV)
        try:
            import ray
            import ray._private.ray_constants  # noqa: F401  (reads the setting)
        finally:
            for k, v in saved.items():
                if v is None:
                    os.environ.pop(k, None)
                else:
                    os.environ[k] = v
    import ray
    from ray._private import ray_constants

    if ray_constants.ENABLE_RAY_CLUSTER:
        raise RuntimeError("a local Ray would listen beyond loopback: ray was imported before "
                           f"without {', '.join(f'{k}={v}' for k, v in LOCAL_RAY_ENV.items())}")
    return ray


class RayExecutor(Executor):
    """Tasks on a Ray cluster at `address`, or on a local Ray started here
    with `workers` CPUs (all of them if None), listening on loopback only.
    Each task runs in a Ray worker started with the oracle's environment
    (a runtime environment's variables)."""
    name = "ray"

    def __init__(self, address: Optional[str] = None, workers: Optional[int] = None):
        if address:
            import ray
        else:
            ray = _import_ray_for_local()
        self._ray = ray
        self._started = False
        if not ray.is_initialized():
            if address:
                ray.init(address=address, include_dashboard=False, log_to_driver=False)
            else:
                ray.init(num_cpus=workers or os.cpu_count(), include_dashboard=False,
                         log_to_driver=False, _node_ip_address="127.0.0.1")
            self._started = True
        self._remote = ray.remote(num_cpus=1, max_retries=0)(_ray_score)
        self._slots = max(1, int(ray.cluster_resources().get("CPU", 1)))

    @property
    def workers(self) -> int:
        return self._slots

    def run(self, oracle: Oracle, tasks: Sequence[tuple[int, np.ndarray]], on_result: OnResult,
            timeout: Optional[float]) -> None:
        ray = self._ray
        if not tasks:
            return
        ref_oracle = ray.put(oracle)
        env = oracle.environment()
        remote = self._remote.options(runtime_env={"env_vars": env}) if env else self._remote
        queue: deque[tuple[int, np.ndarray, int]] = deque((i, p, 1) for i, p in tasks)
        flying: dict[Any, tuple[int, np.ndarray, int, float]] = {}
        left = len(tasks)

        def failed(task: tuple[int, np.ndarray, int, float], why: str) -> None:
            nonlocal left
            i, p, attempt, started = task
            if attempt < ATTEMPTS:
                queue.appendleft((i, p, attempt + 1))
            else:
                left -= 1
                on_result(Done(i, None, None, why, attempt, time.perf_counter() - started))

        try:
            while left:
                while queue and len(flying) < self._slots:
                    i, p, attempt = queue.popleft()
                    flying[remote.remote(ref_oracle, p)] = (i, p, attempt, time.perf_counter())
                wait_for = None
                if timeout is not None:
                    now = time.perf_counter()
                    wait_for = max(0.0, min(t[3] + timeout - now for t in flying.values()))
                ready, _ = ray.wait(list(flying), num_returns=1, timeout=wait_for)
                for ref in ready:
                    task = flying.pop(ref)
                    try:
                        scores, record, secs = ray.get(ref)
                    except Exception as e:  # the task raised, or its worker died
                        failed(task, _error(e))
                        continue
                    left -= 1
                    on_result(Done(task[0], scores, record, None, task[2], secs))
                if timeout is not None:
                    now = time.perf_counter()
                    for ref, task in list(flying.items()):
                        if now - task[3] > timeout:
                            ray.cancel(ref, force=True)
                            del flying[ref]
                            failed(task, f"timed out after {timeout:g} s")
        except BaseException:
            for ref in flying:
                ray.cancel(ref, force=True)
            raise

    def close(self) -> None:
        if self._started and self._ray.is_initialized():
            self._ray.shutdown()
            self._started = False


EXECUTORS = ("local", "ray", "inline")


def make_executor(name: str, workers: Optional[int] = None,
                  ray_address: Optional[str] = None) -> Executor:
    if name == "local":
        return LocalExecutor(workers)
    if name == "ray":
        return RayExecutor(ray_address, workers)
    if name == "inline":
        return InlineExecutor()
    raise ValueError(f"unknown executor '{name}' (choose {', '.join(EXECUTORS)})")
