"""What one exploration under way holds (`Session`): its run key, store
and simulator, every pour so far and its scores, and what is cached on
them (the log densities, each antecedent's planes and their permutation
test, and what a curiosity's handlers keep between requests), from which
the weights and consequents of the explored antecedents are computed.
The `Host` of bridge/exploration/session.py owns the running one."""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Sequence

import numpy as np

from pantarhei.bridge.exploration.checkpoints import ExplorationStore
from pantarhei.bridge.exploration.planes import Planes, plane_fit
from pantarhei.bridge.exploration.progress import Bar
from pantarhei.bridge.exploration.qualify import consequent
from pantarhei.bridge.exploration.significance import Tested, permutation_test, shuffle_seed
from pantarhei.bridge.exploration.weights import weights
from pantarhei.oracle.generative import log_density

__all__ = ["Session"]


@dataclass
class Session:
    """One exploration under way: its run key, store and simulator, every
    pour so far, and what is cached on them. It holds no setting of the
    run: each request from Prolog carries those its handler needs
    (Prolog's settings are the only ones). The trace is the store's (its
    checkpoints), the symbolic state Prolog's."""
    run: str
    store: ExplorationStore
    simulator: Any
    oracle_version: str
    #: Every pour so far and its scores, in the order simulated: the
    #: numbers the planes, weights and models are fitted on. The record of
    #: them is the store's (the trace's draws and the simulator's results),
    #: from which a resumed run reads them back.
    params: np.ndarray
    scores: np.ndarray
    log_dens: dict[str, np.ndarray] = field(default_factory=dict)
    #: Per antecedent: ((weights, ridge), its planes).
    plane_cache: dict[str, tuple[tuple[np.ndarray, float], Planes | None]] = field(default_factory=dict)
    #: Per antecedent: ((weights, ridge, shuffles, seed), its tested planes).
    test_cache: dict[str, tuple[tuple[np.ndarray, float, int, int], Tested | None]] = \
        field(default_factory=dict)
    #: What a curiosity's handlers keep between requests (`kept`), each
    #: under a name of its own: (what it was computed from, the value).
    memo: dict[str, tuple[Any, Any]] = field(default_factory=dict)
    started: float = field(default_factory=time.monotonic)
    bar: Bar | None = None
    timings: dict[str, float] = field(default_factory=dict)
    #: Seconds since the start after each explored antecedent (kept out of the trace).
    elapsed: list[float] = field(default_factory=list)

    def kept(self, name: str, key: Any, make: Callable[[], Any]) -> Any:
        """What a curiosity's handler keeps under `name`: the value made
        from `key` last time, or `make()` when the key has changed."""
        if name not in self.memo or self.memo[name][0] != key:
            self.memo[name] = (key, make())
        return self.memo[name][1]

    @property
    def valid(self) -> np.ndarray:
        return np.all(np.isfinite(self.scores), axis=1)

    def log_density_of(self, aid: str, props: Sequence[str]) -> np.ndarray:
        """log P(p|a) over every simulation so far, extended as they come."""
        have = self.log_dens.get(aid)
        n = len(self.params)
        if have is None:
            have = log_density(self.params, props) if n else np.empty(0)
        elif len(have) < n:
            have = np.concatenate([have, log_density(self.params[len(have):], props)])
        self.log_dens[aid] = have
        return have

    def planes_of(self, aid: str, X: np.ndarray, S: np.ndarray, w: np.ndarray,
                  ridge: float) -> Planes | None:
        """The antecedent's planes (L2 penalty `ridge`), fitted again only
        when its weights changed: an antecedent whose support holds none of
        the new simulations, and none that a new antecedent shares, keeps
        its planes."""
        cached = self.plane_cache.get(aid)
        if cached is not None and cached[0][1] == ridge and _same_weights(cached[0][0], w):
            return cached[1]
        planes = plane_fit(X, S, w, ridge)
        self.plane_cache[aid] = ((w.copy(), ridge), planes)
        return planes

    def tested_of(self, number: int, aid: str, X: np.ndarray, S: np.ndarray,
                  w: np.ndarray, ridge: float, permutations: int, seed: int) -> Tested | None:
        """The antecedent's planes and their permutation test (`permutations`
        shuffles, seeded from the run's `seed`), done again only when its
        weights changed (as `planes_of`)."""
        cached = self.test_cache.get(aid)
        if (cached is not None and cached[0][1:] == (ridge, permutations, seed)
                and _same_weights(cached[0][0], w)):
            return cached[1]
        used = int(((w > 0) & np.all(np.isfinite(S), axis=1)).sum())
        tested = permutation_test(X, S, w, ridge, permutations, shuffle_seed(seed, number, used))
        self.test_cache[aid] = ((w.copy(), ridge, permutations, seed), tested)
        return tested

    def weight_matrix(self, entries: Sequence[dict]) -> np.ndarray:
        """Equation (1) for the explored antecedents over the simulations
        that did not fail: (antecedents, valid simulations)."""
        valid = self.valid
        ld = np.vstack([self.log_density_of(str(e["id"]), e["antecedent"])[valid] for e in entries])
        return weights(ld)

    def consequents(self, entries: Sequence[dict], mode: str) -> list[dict]:
        """Qualify each explored antecedent from its weighted simulations
        (`qualify.consequent`, in the order of `entries`)."""
        W = self.weight_matrix(entries)
        S = self.scores[self.valid]
        return [consequent(S, W[i], mode) for i in range(len(entries))]

    def verdicts(self, entries: Sequence[dict], mode: str) -> list[tuple[bool, ...]]:
        """The consequent of each explored antecedent as nine verdicts,
        qualified by `mode` (qualify.QUALIFY)."""
        return [tuple(o["holds"] for o in c["outcomes"]) for c in self.consequents(entries, mode)]


def _same_weights(w0: np.ndarray, w: np.ndarray) -> bool:
    """Whether weights w over the simulations so far are those cached (w0)
    with none on the simulations since: what was fitted on w0 still holds."""
    k = len(w0)
    return k <= len(w) and np.array_equal(w0, w[:k]) and not w[k:].any()
