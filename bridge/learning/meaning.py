"""What a general rule means, and how the learner knows it: P(e | B).

A rule `B => e` (or `B => neg(e)`) speaks of the pours `pantarhei simulate
--antecedent B` samples for B: B as asked, everything it leaves unsaid as
the ordinary pour (the priors). Its `confidence` is the share of those
pours that keep its head, so the likelihood that e holds when B is asked
is the confidence of a rule for e, one minus that of a rule for neg(e).
Its evidence is the pours learned from that could have been drawn for B
(in the support of P(.|B)): `support` of them, `kept` of which keep the
head.

How P(e | B) is known. A gradient-boosted classifier of each verdict from
the 30 parameters is trained on every pour (the model of the pours), and
averaged over `draws` parameterizations drawn from P(.|B) (`Meaning`).
Importance weights alone cannot do it: an explored antecedent moves the
parameters it names outside what a short question draws, so few explored
pours lie in the support of P(.|B) for most B.
"""
from __future__ import annotations

import zlib
from typing import Protocol, Sequence

import numpy as np

from pantarhei.oracle.generative import InvalidAntecedent, in_support, normalise, sample


class Drawing(Protocol):
    """What the model reads of the learner's settings (generalize.Settings,
    which it does not import: the learner imports the model): the seed of
    its boosting and of its draws, and the draws per body."""

    @property
    def seed(self) -> int: ...

    @property
    def draws(self) -> int: ...


def _seed(seed: int, body: Sequence[str]) -> int:
    return int(np.random.SeedSequence([int(seed), zlib.crc32(" ".join(body).encode())])
               .generate_state(1)[0])


def held_in_support(P: np.ndarray, Y: np.ndarray, body: Sequence[str]) -> tuple[np.ndarray, int]:
    """The evidence of pours P (verdicts Y) for `body`: per expectation,
    how many of the pours that could have been drawn for it (in the
    support of P(.|B)) hold it, and how many such pours there are."""
    m = in_support(P, list(body)) if len(P) else np.zeros(0, dtype=bool)
    return Y[m].sum(axis=0), int(m.sum())


def pooled(held, n, model, model_pours: float):
    """A body's likelihood with its own pours counted beside the model's
    estimate (`model`), which counts as `model_pours` pours: `held` of
    its `n` pours keep the expectation (numbers or arrays of them)."""
    return (held + model_pours * model) / (n + model_pours)


class Meaning:
    """P(e | B) for every expectation e: the model of the pours (one
    gradient-boosted classifier per expectation, on the 30 parameters),
    averaged over parameterizations drawn from P(.|B)."""

    def __init__(self, P: np.ndarray, Y: np.ndarray, settings: Drawing,
                 iterations: int = 150):
        """The model of pours P with verdicts Y; `iterations` rounds of
        boosting at a learning rate of 15 / iterations (fewer, coarser
        rounds for a quicker model)."""
        from sklearn.ensemble import HistGradientBoostingClassifier

        self.settings = settings
        X = normalise(P)
        #: P(e | B) per body already estimated: the draws for B depend on
        #: B and the seed alone, so the estimate is the same each time.
        self.estimated: dict[tuple[str, ...], np.ndarray] = {}
        self.models: list = []
        for k in range(Y.shape[1]):
            y = Y[:, k]
            if y.all() or not y.any():
                self.models.append(float(y[0]) if len(y) else 0.5)
                continue
            m = HistGradientBoostingClassifier(max_depth=3, max_iter=iterations,
                                               learning_rate=15 / iterations,
                                               min_samples_leaf=10, early_stopping=False,
                                               random_state=settings.seed)
            self.models.append(m.fit(X, y))

    def __call__(self, bodies: Sequence[tuple[str, ...]]) -> np.ndarray:
        """len(bodies) x 9: the estimated P(e | B); NaN where B cannot be
        sampled. Shorter bodies, which more questions fall back on, get
        more draws: `draws` for a pair, 4 times as many for one
        proposition, 16 times for the empty body."""
        keys = [tuple(b) for b in bodies]
        fresh = [k for k in dict.fromkeys(keys) if k not in self.estimated]
        rows, ok, sizes = [], [], []
        for b in fresh:
            self.estimated[b] = np.full(len(self.models), np.nan)
            n = self.settings.draws * {0: 16, 1: 4}.get(len(b), 1)
            try:
                rows.append(sample(list(b), n, _seed(self.settings.seed, b)))
            except InvalidAntecedent:
                continue
            ok.append(b)
            sizes.append(n)
        if rows:
            p = self.shares(normalise(np.vstack(rows)))
            ends = np.cumsum(sizes)
            for b, start, end in zip(ok, ends - sizes, ends):
                self.estimated[b] = p[start:end].mean(axis=0)
        return np.array([self.estimated[k] for k in keys]).reshape(len(keys), len(self.models))

    def shares(self, X: np.ndarray) -> np.ndarray:
        """len(X) x 9: the chance that each expectation holds, per pour
        (rows of normalised parameters)."""
        return np.column_stack([np.full(len(X), m) if isinstance(m, float) else m.predict_proba(X)[:, 1]
                                for m in self.models])
