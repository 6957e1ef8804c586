"""A simulation worker process: `python -m pantarhei.oracle.worker IN OUT`,
where IN and OUT are inherited pipe descriptors (see `executors`)."""
from __future__ import annotations

import sys
from multiprocessing.connection import Connection

from pantarhei.oracle.executors import worker_main

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
