"""Held-out scenes: valid antecedents that exploration never explored,
drawn uniformly (by Prolog's validity:random_antecedents/3) or near given
antecedents (one or two propositions added)."""
from __future__ import annotations

from typing import Sequence

import numpy as np

from pantarhei.bridge.engines.swipl import engine
from pantarhei.bridge.reasoning.scenes import violations
from pantarhei.theory.lexicon import load_vocabulary


def random_antecedents(seed: int, n: int) -> list[tuple[str, ...]]:
    """n antecedents drawn uniformly from the valid ones (by Prolog)."""
    r = engine().once("validity:random_antecedents(Seed, N, As)", Seed=int(seed), N=int(n))
    return [tuple(str(p) for p in a) for a in r["As"]]


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
