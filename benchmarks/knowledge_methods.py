"""The ways of choosing pours that the knowledge benchmark
(benchmarks/knowledge.py, whose opening says what each does) compares: each
spends a budget of pours of its own choice and says, at each prefix of its
pours, the bodies its theory may have rules for (`Chosen`)."""
from __future__ import annotations

import json
import tempfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

#: The methods, in the order the report shows them.
METHODS = ("curiosity", "random", "random_valid", "designed", "uncertainty", "map_elites")


@dataclass
class Chosen:
    """A method's pours, in the order simulated, and the bodies its theory
    may have rules for once it has spent n pours."""
    P: np.ndarray
    S: np.ndarray
    bodies: Callable[[int], list[tuple[str, ...]] | None]   # None: every askable body


def _seed(seed: int, *words: str) -> int:
    return int(np.random.SeedSequence([int(seed), zlib.crc32(" ".join(words).encode())])
               .generate_state(1)[0])


def _batch() -> int:
    from pantarhei.theory import defaults
    return int(defaults()["learn_batch"])


def curiosity(seed: int, budget: int, oracle: str, store: Path, run,
              settings: dict | None = None) -> Chosen:
    """The learning curiosity's pours and, at each prefix, the antecedents
    explored by then (from its trace) that are its rules' bodies (every
    one but a whole); `settings` are options of explore other than their
    defaults."""
    from pantarhei.bridge.exploration.explore_call import ExploreOptions, explore
    from pantarhei.bridge.exploration.trace import explored_whole, trace_path

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "learned.pl"
        result = explore(ExploreOptions(oracle=oracle, curiosity="learn", pours=budget, seed=seed,
                                        out=out, store=store, progress=False,
                                        **(settings or {})))
        trace = [json.loads(line) for line in trace_path(out).read_text().splitlines()]
    P, S = result["pours"]
    steps = [(int(t["simulations"]), tuple(sorted(t["antecedent"]))) for t in trace
             if not explored_whole(t)]

    def bodies(n: int) -> list[tuple[str, ...]]:
        return list(dict.fromkeys(b for end, b in steps if end <= n))
    return Chosen(P, S, bodies)


def random_bodies(seed: int, budget: int, run) -> Chosen:
    """The ordinary pour, then random propositions and valid pairs."""
    from pantarhei.bridge.learning.askable import askable_bodies
    from pantarhei.oracle.generative import sample

    batch = _batch()
    pool = askable_bodies(2)[1:]
    rng = np.random.default_rng(_seed(seed, "random bodies"))
    order = [()] + [pool[i] for i in rng.permutation(len(pool))]
    steps = order[: -(-budget // batch)]
    P = np.vstack([sample(list(b), batch, _seed(seed, "random", *b)) for b in steps])[:budget]
    S = run(P)

    def bodies(n: int) -> list[tuple[str, ...]]:
        return steps[: max(1, n // batch)]
    return Chosen(P, S, bodies)


def random_valid(seed: int, budget: int, run) -> Chosen:
    """Uniformly random valid antecedents of the whole vocabulary, a batch
    of the curiosity's size each: random exploration, as `pantarhei
    evaluate` measures curiosity against."""
    from pantarhei.bridge.reasoning.valid_scenes import random_antecedents
    from pantarhei.oracle.generative import sample

    batch = _batch()
    steps = [tuple(sorted(a)) for a in random_antecedents(_seed(seed, "random valid") % 2**31,
                                                           -(-budget // batch))]
    P = np.vstack([sample(list(b), batch, _seed(seed, "random valid", *b))
                   for b in steps])[:budget]
    S = run(P)

    def bodies(n: int) -> list[tuple[str, ...]]:
        return list(dict.fromkeys(steps[: max(1, n // batch)]))
    return Chosen(P, S, bodies)


def designed(seed: int, budget: int, run) -> Chosen:
    """The ordinary pour and each proposition alone, one pour each in turn."""
    from pantarhei.oracle.generative import sample
    from pantarhei.theory.lexicon import load_vocabulary

    order = [()] + [(n,) for n in sorted(load_vocabulary().propositions)]
    rounds = -(-budget // len(order))
    draws = {b: sample(list(b), rounds, _seed(seed, "designed", *b)) for b in order}
    P = np.vstack([draws[b][r] for r in range(rounds) for b in order])[:budget]
    S = run(P)
    return Chosen(P, S, lambda n: order[: max(1, n)])


def uncertainty(seed: int, budget: int, run) -> Chosen:
    """Uncertainty sampling on a boosting model of the pours so far."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.learning.askable import askable_bodies
    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.bridge.learning.meaning import Meaning
    from pantarhei.oracle.generative import normalise, sample

    batch = _batch()
    pool = askable_bodies(2)[1:]
    rng = np.random.default_rng(_seed(seed, "uncertainty"))
    P = sample([], min(budget, 4 * batch), _seed(seed, "uncertainty start"))
    S = run(P)
    while len(P) < budget:
        picks = rng.integers(len(pool), size=256)
        C = np.vstack([sample(list(pool[i]), 1, int(rng.integers(2**31))) for i in picks])
        ok = np.all(np.isfinite(S), axis=1)
        model = Meaning(P[ok], verdicts(S[ok]), Settings(seed=seed), 50)
        q = np.clip(model.shares(normalise(C)), 1e-6, 1 - 1e-6)
        entropy = -(q * np.log(q) + (1 - q) * np.log(1 - q)).sum(axis=1)
        take = np.argsort(-entropy, kind="stable")[: min(batch, budget - len(P))]
        P = np.vstack([P, C[take]])
        S = np.vstack([S, run(C[take])])
    return Chosen(P, S, lambda n: None)


def map_elites_pours(seed: int, budget: int, run) -> Chosen:
    from pantarhei.bridge.evaluation.map_elites import map_elites

    qd = map_elites(run, budget, seed, batch=_batch())
    return Chosen(qd.P, qd.S, lambda n: None)
