"""Loading a theory file: Python's reader (what ask, plan, convert and
conclusions read) and SWI-Prolog's (theory_files:load_theory_facts/2, what
defeasible:load_theory/1 reads), on random learned theories of pouring of
1,000 to 100,000 rules (bridge/theories/families.pouring, written in the
native format: rule, body and learned facts).

Target: 100,000 rules load in at most 10 s; time per rule flat (ratio
near 1) from 1,000 to 100,000 rules. Also timed: defeasible:load_theory/1
whole, which adds the superiority that specificity gives learned rules,
pair by pair: in these random theories (bodies of 1 to 4 of ~60
propositions) the pairs grow with the square of the rules, and so does its
time per rule.
"""
from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from pantarhei.bridge.theories import families, loading
from pantarhei.theory import THEORY_DIR

#: Largest theory (rules); PANTARHEI_BENCH_MAX_RULES=10000 for a quick run.
MAX_RULES = int(os.environ.get("PANTARHEI_BENCH_MAX_RULES", "100000"))
TARGET_RULES, TARGET_S = 100_000, 10.0


def python_load(path: Path, repeat: int) -> float:
    """Median wall seconds of loading.load (read, checked, merged)."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        loading.load(path, check=False)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def prolog_load(path: Path, repeat: int) -> float | None:
    """Median CPU seconds of theory_files:load_theory_facts/2 in swipl
    (start-up not counted); None without swipl."""
    goal = (f"use_module('{THEORY_DIR / 'theory_files'}'), "
            f"forall(between(1, {repeat}, I), (atom_concat(scratch, I, M), statistics(cputime, T0), "
            f"load_theory_facts('{path}', M), statistics(cputime, T1), T is T1 - T0, format('~w~n', [T])))")
    out = _swipl(goal)
    return None if out is None else statistics.median(float(x) for x in out.split())


def prolog_theory(path: Path) -> tuple[float, int] | None:
    """CPU seconds of defeasible:load_theory/1 (read, checked, prepared),
    and the superiority pairs it holds then."""
    goal = (f"use_module('{THEORY_DIR / 'defeasible'}'), statistics(cputime, T0), "
            f"load_theory('{path}'), statistics(cputime, T1), T is T1 - T0, "
            "aggregate_all(count, defeasible:superior(_, _), N), format('~w ~w~n', [T, N])")
    out = _swipl(goal)
    if out is None:
        return None
    t, n = out.split()
    return float(t), int(n)


def _swipl(goal: str) -> str | None:
    swipl = shutil.which("swipl")
    if swipl is None:
        return None
    p = subprocess.run([swipl, "--stack-limit=8g", "-q", "-g", goal, "-t", "halt"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(p.stderr.strip())
    return p.stdout


def main() -> None:
    sizes = [s for s in (1_000, 10_000, 100_000) if s <= MAX_RULES]
    print("loading a native theory of n random learned rules of pouring; "
          "ratio = time per rule relative to the smallest size")
    print(f"  {'rules':>7} {'MB':>6} {'python s':>9} {'ratio':>6} {'prolog s':>9} {'ratio':>6}"
          f" {'load_theory s':>13} {'ratio':>6} {'sup pairs':>10}")
    base_py = base_pl = base_th = None
    with tempfile.TemporaryDirectory(prefix="pantarhei-bench-") as tmp:
        for n in sizes:
            path = Path(tmp) / f"pouring{n}.pl"
            path.write_text(families.pouring(n, seed=1).native())
            repeat = 3 if n < 100_000 else 1
            py = python_load(path, repeat)
            pl = prolog_load(path, repeat)
            base_py = base_py or py / n
            line = f"  {n:>7} {path.stat().st_size / 1e6:>6.1f} {py:>9.2f} {py / n / base_py:>6.2f}"
            if pl is not None:
                base_pl = base_pl or pl / n
                line += f" {pl:>9.2f} {pl / n / base_pl:>6.2f}"
                th, pairs = prolog_theory(path)
                base_th = base_th or th / n
                line += f" {th:>13.2f} {th / n / base_th:>6.2f} {pairs:>10,}"
            print(line, flush=True)
            if n == TARGET_RULES:
                worst = max(py, pl or 0.0)
                print(f"  {n:,} rules load in {worst:.1f} s at most "
                      f"(target <= {TARGET_S:.0f} s: {'met' if worst <= TARGET_S else 'MISSED'})")
    shipped = loading.DEFAULT_THEORY
    if shipped.is_file():
        print(f"  the shipped theory ({shipped.name}): python {python_load(shipped, 5) * 1000:.0f} ms, "
              f"prolog {(prolog_load(shipped, 5) or 0) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
