"""A simulation worker process: `python -m pantarhei.oracle.worker IN OUT`,
where IN and OUT are inherited pipe descriptors (see `local_executor`).

It receives the oracle, then scores what it is sent until it is sent None,
and ends as soon as the process that started it is gone."""
from __future__ import annotations

import os
import pickle
import sys
import threading
import time
from multiprocessing.connection import Connection

from pantarhei.oracle import baseline
from pantarhei.oracle.base import Oracle
from pantarhei.oracle.execution import error_line


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
            conn.send((i, None, None, error_line(e), time.perf_counter() - t0))


if __name__ == "__main__":
    down, up = int(sys.argv[1]), int(sys.argv[2])
    # one duplex conversation over two one-way pipes
    inbox = Connection(down, writable=False)
    outbox = Connection(up, readable=False)

    class _Duplex:
        recv = inbox.recv
        recv_bytes = inbox.recv_bytes
        send = outbox.send

    worker_main(_Duplex())  # type: ignore[arg-type]
