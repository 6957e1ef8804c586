"""Stability of the learned theory: theories learned with different seeds
agree on their decisions in the evaluation's uniformly random held-out
scenes (seed 1, 150 scenes, as `pantarhei evaluate` draws them).

    pantarhei explore --seed 2 --store runs/s2.sqlite --out runs/seed2.pl
    pantarhei explore --seed 3 --store runs/s3.sqlite --out runs/seed3.pl
    python -m benchmarks.stability theory/learned/pouring.pl runs/seed2.pl runs/seed3.pl

Prints, for each pair of theories, the share of (scene, expectation)
decisions they both make on which they agree.
"""
from __future__ import annotations

import itertools
import sys


def agreement(paths: list[str], scenes: int = 150, seed: int = 1) -> dict[tuple[str, str], float]:
    from pantarhei.bridge.evaluation.heldout import random_exploration, uniform_scenes
    from pantarhei.bridge.evaluation.explored_pours import read_learned
    from pantarhei.bridge.evaluation.rule_building import predict
    from pantarhei.bridge.theories.loading import load

    first = read_learned(paths[0])
    ants, _ = random_exploration(seed, sum(first.batches), int(first.setting("batch")))
    held = uniform_scenes(seed, scenes, set(ants) | set(first.antecedents))
    preds = {p: predict(load([p]), held) for p in paths}
    out = {}
    for a, b in itertools.combinations(paths, 2):
        both = (preds[a] != -1) & (preds[b] != -1)
        out[(a, b)] = float((preds[a] == preds[b])[both].mean()) if both.any() else float("nan")
    return out


def main(argv: list[str] | None = None) -> None:
    paths = list(sys.argv[1:] if argv is None else argv)
    if len(paths) < 2:
        raise SystemExit("give two or more learned theories (the first one's held-out scenes are used)")
    for (a, b), share in agreement(paths).items():
        print(f"{a} / {b}: agree on {100 * share:.1f}% of the decisions both make")


if __name__ == "__main__":
    main()
