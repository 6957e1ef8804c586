"""The front door: how long a person waits for `pantarhei --help` and for
one answer, beside plain SWI-Prolog answering the same question.

Each command is started afresh, as a user would, and its wall time taken
from start to exit; the median of REPEAT runs is printed.
Targets (issue 30): --help <= 0.3 s, ask <= 0.5 s on 2 cores.
"""
from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

from pantarhei.theory import PROLOG_ENTRY

#: Runs of each command (PANTARHEI_BENCH_STARTUP_REPEAT).
REPEAT = int(os.environ.get("PANTARHEI_BENCH_STARTUP_REPEAT", "7"))
QUESTION = "pour from the side"
PROPS = "[pour_to_side]"


def commands() -> list[tuple[str, list[str], float | None]]:
    """(what, argv, target in seconds) of each command timed."""
    pantarhei = [sys.executable, "-m", "pantarhei.bridge"]
    script = Path(sys.executable).with_name("pantarhei")
    if script.is_file():                  # the installed command, as a user types it
        pantarhei = [str(script)]
    out = [("pantarhei --help", [*pantarhei, "--help"], 0.3),
           (f'pantarhei ask "{QUESTION}"', [*pantarhei, "ask", QUESTION], 0.5)]
    swipl = shutil.which("swipl")
    if swipl:
        out.append((f"swipl theory/pantarhei.pl, what_happens({PROPS}, O)",
                    [swipl, "-q", "-g", f"what_happens({PROPS}, O), print(O), nl", "-t", "halt",
                     str(PROLOG_ENTRY)], None))
    return out


def wall(argv: list[str]) -> float:
    """Seconds from starting `argv` to its exit (RuntimeError if it failed)."""
    start = time.perf_counter()
    p = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       stdin=subprocess.DEVNULL, text=True)
    took = time.perf_counter() - start
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(argv)} exited {p.returncode}: {p.stderr.strip()[-300:]}")
    return took


def main() -> None:
    rows = []
    for what, argv, target in commands():
        wall(argv)                                   # warm the file cache once
        times = [wall(argv) for _ in range(REPEAT)]
        rows.append((what, statistics.median(times), min(times), max(times), target))
    width = max(len(r[0]) for r in rows)
    print(f"start-up, wall seconds, median of {REPEAT} runs ({os.cpu_count()} cores):")
    print(f"  {'command':<{width}}  median     min     max  target")
    for what, med, lo, hi, target in rows:
        mark = "" if target is None else f"  <= {target:.1f} s {'met' if med <= target else 'MISSED'}"
        print(f"  {what:<{width}}  {med:6.3f}  {lo:6.3f}  {hi:6.3f}{mark}")


if __name__ == "__main__":
    main()
