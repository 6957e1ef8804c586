"""Exploration: the share of wall time that is not simulation.

Runs Algorithm 1 on the synthetic oracle (whose scores cost nothing), so
that everything measured besides the oracle is the exploration's own
work: Prolog, sampling, the models and values of the candidates, plane
fits, checkpoints, the theory, trace and plot. The discovering curiosity
at growing budgets and the paper's at 25 rules, and the learning
curiosity (the default) at the paper's 775 pours, each the median of 3
seeds, are set against the simulation time the same number of PyBullet
pours takes on 2 workers (the cost of a pour measured here, on pours of
a few random valid antecedents), giving the share of a run that is not
simulation (target: at most 5%).

Also measured side by side: the qualify rules (held-out verdict accuracy
of the rules the paper's curiosity learns on the synthetic oracle) and the plane fits (how often
the steepest direction from a_0 is one the synthetic oracle really has,
with plain least squares and with the ridge penalty).
"""
from __future__ import annotations

import statistics
import tempfile
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

WORKERS = 2
#: (max rules, breadth): for the paper's curiosity the default breadth 3
#: empties A_new on the synthetic oracle after 28 antecedents, so the larger
#: budgets modify more broadly (the discovering curiosity has no breadth).
BUDGETS = ((5, 3), (10, 3), (25, 3), (50, 6))
REPEATS = 3


def run_options(max_rules: int, tmp: Path, seed: int = 1, breadth: int = 3,
                curiosity: str = "discover"):
    """The options of one measured run: the synthetic oracle, in this
    process, with the option table's other defaults (for the paper's
    curiosity slope 0: it follows every plane, a run that never stops
    early, and the breadth given, which the discovering curiosity does
    not read)."""
    from pantarhei.bridge.exploration.explore_call import ExploreOptions

    paper = {"slope": 0.0, "breadth": breadth} if curiosity == "paper" else {}
    return ExploreOptions(curiosity=curiosity, oracle="synthetic", budget=max_rules, seed=seed,
                   out=tmp / "t.pl", store=tmp / f"s{max_rules}-{seed}-{time.time_ns()}.sqlite",
                   progress=False, executor="inline", **paper)


def overhead(max_rules: int, tmp: Path, seed: int = 1, breadth: int = 3,
             curiosity: str = "discover") -> tuple[float, int, dict]:
    from pantarhei.bridge.exploration.explore_call import explore

    t = time.perf_counter()
    r = explore(run_options(max_rules, tmp, seed, breadth, curiosity))
    wall = time.perf_counter() - t
    return wall - r["timings"].get("oracle", 0.0), r["simulations"], r["timings"]


def learning_overhead(tmp: Path, seed: int) -> tuple[float, int]:
    """Seconds of a run of the learning curiosity on the synthetic oracle
    (its defaults: the paper's 775 pours) that are not the oracle's, and
    its simulations."""
    from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore

    t = time.perf_counter()
    r = explore(ExploreOptions(curiosity="learn", oracle="synthetic", seed=seed,
                               out=tmp / "learn.pl", store=tmp / f"learn-{seed}.sqlite",
                               progress=False, executor="inline"))
    return time.perf_counter() - t - r["timings"].get("oracle", 0.0), r["simulations"]


def pour_seconds(n: int = 6) -> float:
    """Mean seconds of one PyBullet pour (one worker) of the kind the
    discovering curiosity simulates: one pour each of n uniformly random
    valid antecedents (seeded)."""
    from pantarhei.bridge.reasoning.valid_scenes import random_antecedents
    from pantarhei.oracle.base import make_oracle
    from pantarhei.oracle.generative import sample
    from pantarhei.oracle.physics import PouringOracle

    oracle = make_oracle(PouringOracle.name)
    times = []
    for i, a in enumerate(random_antecedents(11, n)):
        p = sample(list(a), 1, seed=11 + i)[0]
        t = time.perf_counter()
        oracle.score(p)
        times.append(time.perf_counter() - t)
    return statistics.mean(times)


def qualify_accuracy(tmp: Path, seeds=(1, 2, 3)) -> dict[str, float]:
    from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore
    from pantarhei.oracle.generative import sample
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.oracle.synthetic import scores
    from pantarhei.theory.lexicon import load_vocabulary
    from pantarhei.theory import read_facts
    from pantarhei.theory.option_table import option

    v = load_vocabulary()
    names, expectations = v.parameter_names, list(v.expectation_names)
    out = {}
    for mode in option("qualify").choices:
        ok = total = 0
        for seed in seeds:
            path = tmp / f"q-{mode}-{seed}.pl"
            explore(ExploreOptions(curiosity="paper", oracle="synthetic", seed=seed, qualify=mode,
                            out=path, store=tmp / "q.sqlite", progress=False, executor="inline"))
            f = read_facts([path])
            body = defaultdict(list)
            for rid, p in f["body"]:
                body[rid].append(p)
            for rid, _, head in f["rule"]:
                neg = isinstance(head, tuple)
                k = expectations.index(head[1] if neg else head)
                for p in sample(body[rid], 100, seed=12345):
                    ok += verdicts(scores(dict(zip(names, p)))[k]) != neg
                    total += 1
        out[mode] = ok / total
    return out


def direction_hits(ridge: float, trials: int = 30) -> float:
    from pantarhei.bridge.exploration.planes import best_abs_slope, plane_fit
    from pantarhei.oracle.generative import normalise, sample
    from pantarhei.oracle.synthetic import DEPENDS, scores
    from pantarhei.theory.lexicon import load_vocabulary

    v = load_vocabulary()
    names, expectations = v.parameter_names, v.expectation_names
    hits = 0
    for seed in range(trials):
        P = sample(["pour_low", "pour_near_rim", "pour_steeply_tilted"], 31, seed=seed)
        S = np.array([scores(dict(zip(names, p))) for p in P])
        best = best_abs_slope(plane_fit(normalise(P), S, np.ones(len(P)), ridge))
        top = names[int(np.argmax(np.abs(best.gradient)))]
        hits += top in DEPENDS[expectations[best.expectation]]
    return hits / trials


def main() -> None:
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        overhead(2, tmp)                      # start Prolog and warm the caches
        pour = pour_seconds()
        print(f"one PyBullet pour of a random valid antecedent: {pour:.2f} s (mean of 6, "
              f"one worker); "
              f"{WORKERS} workers simulate {WORKERS / pour * 60:.0f} pours per minute")
        print(f"{'rules':>5} {'breadth':>7} {'sims':>5} {'overhead s':>11} {'per sim ms':>11} "
              f"{'sim s (2 workers)':>18} {'non-sim share':>14}")
        for budget, breadth in BUDGETS:
            runs = [overhead(budget, tmp, seed, breadth) for seed in range(1, REPEATS + 1)]
            over = statistics.median(r[0] for r in runs)
            sims = int(statistics.median(r[1] for r in runs))
            sim = sims * pour / WORKERS
            print(f"{budget:>5} {breadth:>7} {sims:>5} {over:>11.2f} {1000 * over / sims:>11.2f} "
                  f"{sim:>18.0f} {100 * over / (over + sim):>13.2f}%")
        paper = [overhead(25, tmp, seed, 3, "paper") for seed in range(1, REPEATS + 1)]
        over = statistics.median(r[0] for r in paper)
        sims = int(statistics.median(r[1] for r in paper))
        sim = sims * pour / WORKERS
        print(f"{25:>5} {'paper':>7} {sims:>5} {over:>11.2f} {1000 * over / sims:>11.2f} "
              f"{sim:>18.0f} {100 * over / (over + sim):>13.2f}%")
        learning = [learning_overhead(tmp, seed) for seed in range(1, REPEATS + 1)]
        over = statistics.median(r[0] for r in learning)
        sims = int(statistics.median(r[1] for r in learning))
        sim = sims * pour / WORKERS
        print(f"the learning curiosity (the default), {sims} pours: {over:.1f} s beside the "
              f"oracle ({1000 * over / sims:.0f} ms a pour), against {sim:.0f} s of PyBullet "
              f"pours on {WORKERS} workers: {100 * over / (over + sim):.1f}% not simulation")
        _, _, timings = overhead(25, tmp)
        parts = ", ".join(f"{k} {v:.2f} s" for k, v in sorted(timings.items()) if k != "oracle")
        print(f"where the overhead of 25 batches goes (besides Prolog itself): {parts}")
        acc = qualify_accuracy(tmp)
        print(f"qualify, held-out verdict accuracy of the paper's curiosity's rules on the "
              f"synthetic oracle (seeds 1-3): "
              f"weighted {100 * acc['weighted']:.1f}%, argmax {100 * acc['argmax']:.1f}% "
              f"(ratio {acc['weighted'] / acc['argmax']:.3f})")
        plain, ridged = direction_hits(0.0), direction_hits(1.0)
        print(f"steepest direction from a_0 on a known dependency (30 seeds): "
              f"least squares {100 * plain:.0f}%, ridge 1.0 {100 * ridged:.0f}%")


if __name__ == "__main__":
    main()
