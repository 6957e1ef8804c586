"""The Ray executor: tasks on a Ray cluster (or on a local Ray started on
demand, listening on loopback only), each in a Ray worker started with the
oracle's environment, with the local executor's failure handling: a task
that fails or runs past the time limit is retried once."""
from __future__ import annotations

import os
import sys
import time
from collections import deque
from types import MappingProxyType
from typing import Any, Optional, Sequence

import numpy as np

from pantarhei.oracle import baseline
from pantarhei.oracle.base import Oracle
from pantarhei.oracle.execution import ATTEMPTS, Done, Executor, OnResult, error_line


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


#: Seconds to wait for a Ray cluster's address to answer before giving up
#: (ray.init itself waits minutes on an address that does not answer).
REACH_TIMEOUT = 5.0


def reach(address: str, timeout: float = REACH_TIMEOUT) -> None:
    """RuntimeError in one line unless a Ray cluster answers at `address`
    (HOST:PORT or ray://HOST:PORT; "auto" and other forms are left to
    ray.init): something listens there, and it speaks gRPC, as Ray's
    servers do (its first frame, after the client's HTTP/2 preface, is
    the server's SETTINGS). ray.init waits minutes, deaf to SIGTERM, on a
    port that is not Ray's."""
    import socket

    hostport = address.removeprefix("ray://")
    host, sep, port = hostport.rpartition(":")
    if not sep or not port.isdigit() or not host:
        return
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=timeout) as c:
            c.sendall(HTTP2_PREFACE + HTTP2_SETTINGS)
            frame = _read(c, 9)
    except socket.gaierror:
        raise RuntimeError(f"cannot reach a Ray cluster at {address}: no such host {host}") from None
    except OSError as e:
        why = "no answer" if isinstance(e, TimeoutError) else (e.strerror or str(e))
        raise RuntimeError(f"cannot reach a Ray cluster at {address}: {why} "
                           f"(within {timeout:g} s)") from None
    if len(frame) < 9 or frame[3] != 0x4:
        raise RuntimeError(f"cannot reach a Ray cluster at {address}: what listens there does "
                           "not speak gRPC, as Ray's servers do (is it the cluster's address?)")


#: The client's connection preface of HTTP/2 (RFC 9113, 3.4) and an empty
#: SETTINGS frame: a gRPC server answers with a SETTINGS frame of its own.
HTTP2_PREFACE = b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n"
HTTP2_SETTINGS = bytes([0, 0, 0, 0x4, 0, 0, 0, 0, 0])


def _read(conn, n: int) -> bytes:
    """Up to n bytes from a connection, fewer if it closes first."""
    out = b""
    while len(out) < n:
        part = conn.recv(n - len(out))
        if not part:
            break
        out += part
    return out


class RayExecutor(Executor):
    """Tasks on a Ray cluster at `address`, or on a local Ray started here
    with `workers` CPUs (all of them if None), listening on loopback only.
    Each task runs in a Ray worker started with the oracle's environment
    (a runtime environment's variables)."""
    name = "ray"

    def __init__(self, address: Optional[str] = None, workers: Optional[int] = None):
        if address:
            reach(address)
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
                        failed(task, error_line(e))
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
