"""Loading a theory file and answering with it: Python's reader (what plan,
convert and conclusions read), SWI-Prolog's
(theory_files:load_theory_facts/2) and defeasible:load_theory/1 whole (read,
checked, indexed), clingo's conclusions with one fact (derivability.lp), and
`pantarhei ask --theory` end to end (SWI-Prolog alone reads the file,
theory/ask.pl), on random learned theories of pouring
of 1,000 to 100,000 rules (bridge/theories/families.pouring, written in
the native format: rule, body and learned facts).

Targets: 100,000 rules load in at most 10 s in both engines, and `ask
--theory` of them answers in at most 15 s; time per rule flat (ratio near
1) from 1,000 to 100,000 rules. Specificity is looked up when asked, never
held pair by pair (the pairs grow with the square of the rules).
"""
from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from pantarhei.bridge.theories import families, loading
from pantarhei.theory import THEORY_DIR

#: Largest theory (rules); PANTARHEI_BENCH_MAX_RULES=10000 for a quick run.
MAX_RULES = int(os.environ.get("PANTARHEI_BENCH_MAX_RULES", "100000"))
TARGET_RULES, TARGET_S, TARGET_ASK_S = 100_000, 10.0, 15.0


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


def prolog_theory(path: Path) -> float | None:
    """CPU seconds of defeasible:load_theory/1 (read, checked, indexed)."""
    goal = (f"use_module('{THEORY_DIR / 'defeasible'}'), statistics(cputime, T0), "
            f"load_theory('{path}'), statistics(cputime, T1), T is T1 - T0, format('~w~n', [T])")
    out = _swipl(goal)
    return None if out is None else float(out)


def asp_answer(path: Path, fact: str) -> float:
    """Wall seconds of `pantarhei conclusions --engine asp` of the theory
    with `fact` added (clingo grounds and solves derivability.lp)."""
    with_fact = path.with_name(f"fact-{path.name}")
    with_fact.write_text(f"fact({fact}).\n" + path.read_text())
    return _timed([_pantarhei(), "conclusions", "--engine", "asp", str(with_fact)])


def ask(path: Path) -> float:
    """Wall seconds of `pantarhei ask "pour from the side" --theory FILE`."""
    return _timed([_pantarhei(), "ask", "pour from the side", "--theory", str(path)])


def _pantarhei() -> str:
    return str(Path(sys.executable).with_name("pantarhei"))


def _timed(argv: list[str]) -> float:
    t = time.perf_counter()
    p = subprocess.run(argv, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(p.stderr.strip())
    return time.perf_counter() - t


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
    print("loading a native theory of n random learned rules of pouring, and answering with it; "
          "ratio = time per rule relative to the smallest size")
    cols = ("python s", "prolog s", "load_theory s", "clingo s", "ask s")
    print(f"  {'rules':>7} {'MB':>6} " + " ".join(f"{c:>13} {'ratio':>6}" for c in cols))
    base: dict[str, float] = {}
    with tempfile.TemporaryDirectory(prefix="pantarhei-bench-") as tmp:
        for n in sizes:
            path = Path(tmp) / f"pouring{n}.pl"
            path.write_text(families.pouring(n, seed=1).native())
            repeat = 3 if n < 100_000 else 1
            times = {"python s": python_load(path, repeat), "prolog s": prolog_load(path, repeat),
                     "load_theory s": prolog_theory(path),
                     "clingo s": asp_answer(path, "pour_to_side"), "ask s": ask(path)}
            line = f"  {n:>7} {path.stat().st_size / 1e6:>6.1f}"
            for c in cols:
                t = times[c]
                if t is None:
                    line += f" {'n/a':>13} {'':>6}"
                    continue
                base.setdefault(c, t / n)
                line += f" {t:>13.2f} {t / n / base[c]:>6.2f}"
            print(line, flush=True)
            if n == TARGET_RULES:
                worst = max(times["python s"], times["prolog s"] or 0.0, times["load_theory s"] or 0.0)
                print(f"  {n:,} rules load in {worst:.1f} s at most "
                      f"(target <= {TARGET_S:.0f} s: {'met' if worst <= TARGET_S else 'MISSED'})")
                print(f"  ask --theory of {n:,} rules answers in {times['ask s']:.1f} s "
                      f"(target <= {TARGET_ASK_S:.0f} s: "
                      f"{'met' if times['ask s'] <= TARGET_ASK_S else 'MISSED'})")
    shipped = loading.DEFAULT_THEORY
    if shipped.is_file():
        print(f"  the shipped theory ({shipped.name}): python {python_load(shipped, 5) * 1000:.0f} ms, "
              f"prolog {(prolog_load(shipped, 5) or 0) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
