"""Defeasible reasoning: prediction (Prolog), planning (clingo), and the
scalable benchmark theories of Maher et al. (2001) in both engines.

Targets: what_happens on a 1,000-rule theory <= 10 ms; plan over the full
vocabulary with a 1,000-rule theory <= 1 s; time growing near-linearly
with the size of the benchmark theories.
"""
from __future__ import annotations

import os
import random
import statistics
import time

from pantarhei.bridge.theories import families as bench
from pantarhei.bridge.reasoning.planning import plan
from pantarhei.bridge.reasoning.answers import what_happens
from pantarhei.bridge.reasoning.logic import Semantics, asp_conclusions, prolog_load
from pantarhei.theory.lexicon import load_vocabulary

#: Largest benchmark theory (rules); PANTARHEI_BENCH_MAX_RULES=10000 for a quick run.
MAX_RULES = int(os.environ.get("PANTARHEI_BENCH_MAX_RULES", "100000"))
#: Largest benchmark theory for clingo (PANTARHEI_BENCH_ASP_MAX_RULES).
ASP_MAX_RULES = min(MAX_RULES, int(os.environ.get("PANTARHEI_BENCH_ASP_MAX_RULES", "100000")))


def _median(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def _scenes(n: int, seed: int) -> list[list[str]]:
    """Random valid scenes: one proposition from each of 6 random dimensions."""
    from pantarhei.bridge.reasoning.valid_scenes import violations

    vocab = load_vocabulary()
    rng = random.Random(seed)
    out = []
    while len(out) < n:
        dims = rng.sample(sorted(vocab.dimensions), 6)
        scene = sorted(rng.choice(vocab.dimensions[d].values) for d in dims)
        if not violations(scene):
            out.append(scene)
    return out


def prediction() -> None:
    theory = bench.pouring(1000, seed=1)
    e = prolog_load(theory)
    e.use_module("queries")
    scenes = _scenes(30, seed=2)
    times_prolog, times_full = [], []
    for s in scenes:
        scene = "[" + ", ".join(s) + "]"
        r = e.once(f"statistics(cputime, T0), queries:what_happens({scene}, Os), "
                           f"statistics(cputime, T1), T is T1 - T0, length(Os, 9)")
        times_prolog.append(float(r["T"]))
        times_full.append(_median(lambda: what_happens(theory, s), 1))
    med = statistics.median(times_prolog) * 1000
    print(f"what_happens/2, 1,000-rule theory, median of {len(scenes)} scenes: {med:.2f} ms "
          f"(target <= 10 ms: {'met' if med <= 10 else 'MISSED'})")
    print(f"  with reasons in words, from Python (pyswip): "
          f"{statistics.median(times_full) * 1000:.1f} ms")


def planning() -> None:
    theory = bench.pouring(1000, seed=1)
    vocab = load_vocabulary()
    rng = random.Random(3)
    cases = []
    while len(cases) < 5:
        goals = [e if rng.random() < 0.5 else f"neg({e})" for e in rng.sample(vocab.expectation_names, 2)]
        given = [rng.choice(vocab.dimensions[d].values) for d in ("liquid_weight", "liquid_amount")]
        try:
            plan(theory, goals, given, alternatives=0)
        except Exception:
            continue
        cases.append((goals, given))
    times = [_median(lambda: plan(theory, g, c, alternatives=0), 1) for g, c in cases]
    alt = [_median(lambda: plan(theory, g, c, alternatives=4), 1) for g, c in cases]
    med = statistics.median(times)
    print(f"plan, full vocabulary, 1,000-rule theory, 2 goals, median of {len(cases)}: {med * 1000:.0f} ms "
          f"(target <= 1 s: {'met' if med <= 1 else 'MISSED'}); with 4 alternatives: "
          f"{statistics.median(alt) * 1000:.0f} ms")


def scaling() -> None:
    sizes = [s for s in (1000, 10000, 100000) if s <= MAX_RULES]
    print("benchmark theories: seconds for all conclusions (load included); "
          "ratio = time per rule relative to the smallest size")
    print(f"  {'theory':8} {'rules':>7} {'prolog s':>9} {'ratio':>6} {'asp s':>8} {'ratio':>6}  known answers")
    for name in bench.NAMES:
        base_p = base_a = None
        for size in sizes:
            b = bench.of_size(name, size)
            t = time.perf_counter()
            from pantarhei.bridge.reasoning.logic import prolog_conclusions_batch

            (c,) = prolog_conclusions_batch([(b.theory, Semantics())])
            tp = time.perf_counter() - t
            ok = b.proved <= set(c["+d"]) and b.refuted <= set(c["-d"])
            base_p = base_p or tp / b.size
            line = f"  {name:8} {b.size:>7} {tp:>9.2f} {tp / b.size / base_p:>6.2f}"
            if b.size <= ASP_MAX_RULES:
                t = time.perf_counter()
                ca = asp_conclusions(b.theory, Semantics())
                ta = time.perf_counter() - t
                ok = ok and ca == c
                base_a = base_a or ta / b.size
                line += f" {ta:>8.2f} {ta / b.size / base_a:>6.2f}"
            else:
                line += f" {'-':>8} {'-':>6}"
            print(line + f"  {'ok' if ok else 'WRONG'}", flush=True)


def main() -> None:
    prediction()
    planning()
    scaling()


if __name__ == "__main__":
    main()
