"""`pantarhei ask --check 10`: how long a person waits for one question's
answers checked against 10 pours of it simulated (PyBullet, the oracle
the shipped theory was learned from), each run with a store of its own so
that every pour is simulated afresh.

The command is started as a user starts it; the median of REPEAT runs'
wall time is printed. Target: at most 10 s on 2 cores.
"""
from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: Runs of the command (PANTARHEI_BENCH_CHECK_REPEAT).
REPEAT = int(os.environ.get("PANTARHEI_BENCH_CHECK_REPEAT", "3"))
QUESTION = "pour from the side"
POURS = 10
TARGET_S = 10.0


def command(store: Path) -> list[str]:
    pantarhei = [sys.executable, "-m", "pantarhei.bridge"]
    script = Path(sys.executable).with_name("pantarhei")
    if script.is_file():                  # the installed command, as a user types it
        pantarhei = [str(script)]
    return [*pantarhei, "ask", QUESTION, "--check", str(POURS), "--store", str(store)]


def once() -> float:
    """Seconds of one run, with a fresh store (RuntimeError if it failed)."""
    with tempfile.TemporaryDirectory(prefix="pantarhei-bench-check-") as d:
        argv = command(Path(d) / "store.sqlite")
        start = time.perf_counter()
        p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           stdin=subprocess.DEVNULL, text=True)
        took = time.perf_counter() - start
    if p.returncode != 0 or "checked: " not in p.stdout:
        raise RuntimeError(f"{' '.join(argv)} exited {p.returncode}: {p.stderr.strip()[-300:]}")
    return took


def main() -> None:
    times = [once() for _ in range(REPEAT)]
    median = statistics.median(times)
    verdict = "met" if median <= TARGET_S else "MISSED"
    print(f'pantarhei ask "{QUESTION}" --check {POURS}: median {median:.2f} s of {REPEAT} runs '
          f"(each {', '.join(f'{t:.2f}' for t in times)} s), {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.1f}; "
          f"target {TARGET_S:.0f} s: {verdict}")


if __name__ == "__main__":
    main()
