"""Held-out scenes: valid antecedents that exploration never explored,
drawn uniformly (by Prolog's validity:random_antecedents/3) or near given
antecedents (one or two propositions added)."""
from __future__ import annotations

from typing import Sequence

import numpy as np

from pantarhei.bridge.evaluation.measures import verdicts
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.reasoning.scenes import random_antecedents, violations
from pantarhei.oracle.generative import sample
from pantarhei.theory.lexicon import load_vocabulary


def random_exploration(seed: int, count: int, samples: int) -> tuple[list[tuple[str, ...]], np.ndarray]:
    """The random baseline's exploration at a budget: `count` uniformly random
    valid antecedents, `samples` pours of each (seeded as exploration seeds its
    iterations, so the same store serves every reader)."""
    ants = random_antecedents(seed + 7919, count)
    P = np.vstack([sample(list(a), samples, iteration_seed(seed + 7919, i))
                   for i, a in enumerate(ants, start=1)])
    return ants, P


def uniform_scenes(seed: int, n: int, exclude: set[tuple[str, ...]]) -> list[tuple[str, ...]]:
    """n distinct uniformly random valid antecedents, none in `exclude`."""
    out = [a for a in random_antecedents(seed, 2 * n) if a not in exclude]
    return list(dict.fromkeys(out))[:n]


def scene_pours(scenes: Sequence[Sequence[str]], seed: int) -> np.ndarray:
    """One pour of each held-out scene, shape (len(scenes), 30)."""
    if not scenes:
        return np.empty((0, len(load_vocabulary().parameters)))
    return np.vstack([sample(list(a), 1, iteration_seed(seed, 100_000 + j))
                      for j, a in enumerate(scenes)])


def simulated(scenes: Sequence[tuple[str, ...]], S: np.ndarray
              ) -> tuple[list[tuple[str, ...]], np.ndarray]:
    """The scenes whose one pour (a row of scores S) did not fail, and their
    verdicts."""
    ok = np.all(np.isfinite(S), axis=1)
    return [s for s, kept in zip(scenes, ok) if kept], verdicts(S[ok])


def near_antecedents(explored: Sequence[Sequence[str]], n: int, seed: int,
                     exclude: set[tuple[str, ...]]) -> list[tuple[str, ...]]:
    """n valid antecedents, each an explored antecedent with one or two
    propositions of dimensions it leaves open added; none in `exclude`."""
    v = load_vocabulary()
    rng = np.random.default_rng(seed)
    out: list[tuple[str, ...]] = []
    seen = set(exclude)
    for _ in range(200 * n):
        if len(out) == n:
            break
        base = list(explored[rng.integers(len(explored))])
        used = {v.propositions[p].dimension for p in base}
        free = sorted(p for p, d in v.propositions.items() if d.dimension not in used)
        k = int(rng.integers(1, 3))
        extra = [free[j] for j in rng.choice(len(free), size=k, replace=False)]
        cand = tuple(sorted(set(base) | set(extra)))
        if cand in seen or len({v.propositions[p].dimension for p in cand}) != len(cand):
            continue
        if violations(cand):
            continue
        seen.add(cand)
        out.append(cand)
    return out
