"""The front door: how long a person waits for `pantarhei --help` and for
one answer, beside plain SWI-Prolog answering what happens in a scene.

Each command is started afresh, as a user would (Python keeping its
compiled modules, as it does unless told not to), and its wall time taken
from start to exit. `ask` is timed on a question in the vocabulary's
words and on one as a person types it, which wants the reader's every
pattern (compiled by an earlier question and kept: pattern_store.py).
The commands take turns, so that the machine's load falls on each alike;
the median of REPEAT runs is printed, and the median of the ratios of
each `ask` to plain swipl, run by run.
Targets: --help <= 0.3 s; ask at most 1.3 times plain swipl's time.
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
#: A question as a person types it: the reader's every pattern is wanted.
TYPED = "will the bowl slide if I pour milk from a jug really high?"
PROPS = "[pour_to_side]"


def commands() -> list[tuple[str, list[str], float | None]]:
    """(what, argv, target in seconds) of each command timed."""
    pantarhei = [sys.executable, "-m", "pantarhei.bridge"]
    script = Path(sys.executable).with_name("pantarhei")
    if script.is_file():                  # the installed command, as a user types it
        pantarhei = [str(script)]
    out = [("pantarhei --help", [*pantarhei, "--help"], 0.3),
           (f'pantarhei ask "{QUESTION}"', [*pantarhei, "ask", QUESTION], None),
           (f'pantarhei ask "{TYPED}"', [*pantarhei, "ask", TYPED], None)]
    swipl = shutil.which("swipl")
    if swipl:
        out.append((f"swipl theory/pantarhei.pl, what_happens({PROPS}, O)",
                    [swipl, "-q", "-g", f"what_happens({PROPS}, O), print(O), nl", "-t", "halt",
                     str(PROLOG_ENTRY)], None))
    return out


#: How much longer than plain swipl `ask` may take.
ASK_RATIO = 1.3


def wall(argv: list[str]) -> float:
    """Seconds from starting `argv` to its exit (RuntimeError if it failed)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    start = time.perf_counter()
    p = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       stdin=subprocess.DEVNULL, text=True, env=env)
    took = time.perf_counter() - start
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(argv)} exited {p.returncode}: {p.stderr.strip()[-300:]}")
    return took


def main() -> None:
    cmds = commands()
    for _, argv, _ in cmds:
        wall(argv)                 # warm the file cache, and let Python compile its modules
    times: list[list[float]] = [[] for _ in cmds]
    for _ in range(REPEAT):        # in turns
        for i, (_, argv, _) in enumerate(cmds):
            times[i].append(wall(argv))
    width = max(len(c[0]) for c in cmds)
    print(f"start-up, wall seconds, median of {REPEAT} runs, the commands in turns "
          f"({os.cpu_count()} cores):")
    print(f"  {'command':<{width}}  median     min     max  target")
    for (what, _, target), ts in zip(cmds, times):
        med = statistics.median(ts)
        mark = "" if target is None else f"  <= {target:.1f} s {'met' if med <= target else 'MISSED'}"
        print(f"  {what:<{width}}  {med:6.3f}  {min(ts):6.3f}  {max(ts):6.3f}{mark}")
    if len(cmds) == 4:
        for i, what in ((1, "ask"), (2, "ask, a typed question")):
            ratio = statistics.median(a / s for a, s in zip(times[i], times[3]))
            print(f"  {what} / plain swipl, median of the runs' ratios: {ratio:.2f}x "
                  f"(target <= {ASK_RATIO:.1f}x: {'met' if ratio <= ASK_RATIO else 'MISSED'})")


if __name__ == "__main__":
    main()
