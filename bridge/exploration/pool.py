"""The pours of a running exploration and what is fitted on them: the
`Session` that the foreign predicates of bridge/exploration/session.py act
on. It holds every simulation so far (those of the checkpoints and those
of the iteration under way), and caches, per explored antecedent, the log
densities of equation (1), its planes and their permutation test, fitted
again only when the antecedent's weights change."""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np

from pantarhei.bridge.exploration.novelty import Known
from pantarhei.bridge.exploration.planes import Planes, plane_fit
from pantarhei.bridge.exploration.qualify import consequent
from pantarhei.bridge.exploration.significance import Tested, permutation_test, shuffle_seed
from pantarhei.bridge.exploration.checkpoints import ExplorationStore
from pantarhei.bridge.exploration.weights import weights
from pantarhei.oracle.generative import log_density
from pantarhei.theory import defaults


@dataclass
class Session:
    """One exploration under way: its settings, run key, store and
    simulator, every pour so far, and what is cached on them. The trace
    is the store's (its checkpoints), the symbolic state Prolog's."""
    settings: dict
    run: str
    store: ExplorationStore
    simulator: Any
    oracle_version: str
    params: np.ndarray
    scores: np.ndarray
    pending: dict[int, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    log_dens: dict[str, np.ndarray] = field(default_factory=dict)
    plane_cache: dict[str, tuple[np.ndarray, Planes | None]] = field(default_factory=dict)
    test_cache: dict[str, tuple[np.ndarray, Tested | None]] = field(default_factory=dict)
    #: What the last novelty estimate knew: ((pours, antecedents), Known).
    known: tuple[tuple[int, int], Known] | None = None
    #: The learning curiosity's model of the pours: (pours it is fitted on, Meaning).
    teacher: tuple[int, Any] | None = None
    started: float = field(default_factory=time.monotonic)
    bar: Any = None
    timings: dict[str, float] = field(default_factory=dict)
    #: Seconds since the start after each explored antecedent (kept out of the trace).
    elapsed: list[float] = field(default_factory=list)
    #: Pours already in the pool of each probed (iteration, attempt).
    probed: dict[tuple[int, int], int] = field(default_factory=dict)

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

    def planes_of(self, aid: str, X: np.ndarray, S: np.ndarray, w: np.ndarray) -> Planes | None:
        """The antecedent's planes, fitted again only when its weights
        changed: an antecedent whose support holds none of the new
        simulations, and none that a new antecedent shares, keeps its planes."""
        cached = self.plane_cache.get(aid)
        if cached is not None and _same_weights(cached[0], w):
            return cached[1]
        planes = plane_fit(X, S, w, float(self.settings.get("ridge", defaults()["ridge"])))
        self.plane_cache[aid] = (w.copy(), planes)
        return planes

    def tested_of(self, number: int, aid: str, X: np.ndarray, S: np.ndarray,
                  w: np.ndarray) -> Tested | None:
        """The antecedent's planes and their permutation test, done again
        only when its weights changed (as `planes_of`)."""
        cached = self.test_cache.get(aid)
        if cached is not None and _same_weights(cached[0], w):
            return cached[1]
        used = int(((w > 0) & np.all(np.isfinite(S), axis=1)).sum())
        tested = permutation_test(X, S, w, float(self.settings.get("ridge", defaults()["ridge"])),
                                  int(self.settings["permutations"]),
                                  shuffle_seed(int(self.settings["seed"]), number, used))
        self.test_cache[aid] = (w.copy(), tested)
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

    def verdicts(self, entries: Sequence[dict]) -> list[tuple[bool, ...]]:
        """The consequent of each explored antecedent as nine verdicts,
        qualified as the run's settings say."""
        mode = str(self.settings.get("qualify", defaults()["qualify"]))
        return [tuple(o["holds"] for o in c["outcomes"]) for c in self.consequents(entries, mode)]


def _same_weights(w0: np.ndarray, w: np.ndarray) -> bool:
    """Whether weights w over the simulations so far are those cached (w0)
    with none on the simulations since: what was fitted on w0 still holds."""
    k = len(w0)
    return k <= len(w) and np.array_equal(w0, w[:k]) and not w[k:].any()
