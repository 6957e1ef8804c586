"""oracle/worker.py: a worker process goes as soon as the process that
started it is gone, even in the middle of a simulation."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import numpy as np

from .pours import with_counts
from .stores import HANGING_RUN as SCRIPT


def test_workers_go_when_their_process_is_killed(tmp_path):
    # the worker stuck in the hanging simulation must not outlive the process
    P = with_counts([43])
    np.save(tmp_path / "P.npy", P)
    proc = subprocess.Popen([sys.executable, "-c", SCRIPT, str(tmp_path / "s.sqlite"),
                             str(tmp_path / "P.npy")])
    time.sleep(4)
    children = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True)
    workers = [int(x) for x in children.stdout.split()]
    assert workers
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    deadline = time.time() + 10
    while time.time() < deadline and any(_alive(w) for w in workers):
        time.sleep(0.2)
    assert not any(_alive(w) for w in workers)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie waiting for its reaper is gone for our purpose
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split()[2] != "Z"
    except FileNotFoundError:
        return False
