"""Measuring a theory against the oracle: held-out scenes, a decision tree
baseline, and the distinct behaviours a set of consequents shows.

Everything here takes the oracle's scores and a theory's predictions as
arrays, so the same measures serve the learned theory, the decision tree and
the theory built from random exploration.

Predictions are integer arrays (scenes x 9 expectations) of the answer
codes HOLDS, FAILS and UNKNOWN; verdicts are the oracle's scores against
the verdict threshold. Both are bridge/verdicts.py's.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN, verdicts


@dataclass(frozen=True)
class Accuracy:
    """Per expectation: how often the predictions decide (coverage), and how
    often a decided prediction is the simulation's verdict (accuracy)."""
    expectations: tuple[str, ...]
    decided: np.ndarray      # (9,) counts of decided predictions
    correct: np.ndarray      # (9,) counts of decided and right
    scenes: int

    @property
    def coverage(self) -> np.ndarray:
        return self.decided / max(self.scenes, 1)

    @property
    def accuracy(self) -> np.ndarray:
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.decided > 0, self.correct / np.maximum(self.decided, 1), np.nan)

    @property
    def overall_coverage(self) -> float:
        return float(self.decided.sum() / max(self.scenes * len(self.expectations), 1))

    @property
    def overall_accuracy(self) -> float:
        return float(self.correct.sum() / self.decided.sum()) if self.decided.sum() else float("nan")

    def as_dict(self) -> dict:
        """JSON-ready: an accuracy with nothing decided is None."""
        def num(x: float) -> float | None:
            return None if np.isnan(x) else float(x)

        return {"scenes": self.scenes, "coverage": self.overall_coverage,
                "accuracy": num(self.overall_accuracy),
                "per_expectation": {e: {"coverage": float(c), "accuracy": num(a)}
                                    for e, c, a in zip(self.expectations, self.coverage, self.accuracy)}}


def accuracy(predictions: np.ndarray, truth: np.ndarray) -> Accuracy:
    """Score predictions (HOLDS/FAILS/UNKNOWN) against verdicts (booleans)."""
    predictions = np.asarray(predictions)
    truth = np.asarray(truth, dtype=bool)
    if predictions.shape != truth.shape:
        raise ValueError(f"predictions {predictions.shape} and verdicts {truth.shape} differ in shape")
    decided = predictions != UNKNOWN
    correct = decided & ((predictions == HOLDS) == truth)
    return Accuracy(load_vocabulary().expectation_names, decided.sum(axis=0), correct.sum(axis=0),
                    len(truth))


def one_hot(antecedents: Sequence[Sequence[str]]) -> np.ndarray:
    """The qualitative features of scenes: one column per proposition, 1 where
    the scene's antecedent holds it."""
    names = sorted(load_vocabulary().propositions)
    column = {n: i for i, n in enumerate(names)}
    X = np.zeros((len(antecedents), len(names)), dtype=np.int8)
    for i, a in enumerate(antecedents):
        for p in a:
            X[i, column[p]] = 1
    return X


def tree_predictions(train: Sequence[Sequence[str]], train_verdicts: np.ndarray,
                     test: Sequence[Sequence[str]], seed: int) -> np.ndarray:
    """A scikit-learn decision tree trained on the same simulations, from the
    same qualitative features (one-hot antecedents), predicting the verdicts
    of the test scenes. It always decides."""
    from sklearn.tree import DecisionTreeClassifier

    return _per_expectation(lambda: DecisionTreeClassifier(random_state=seed, min_samples_leaf=3),
                            train, train_verdicts, test)


def model_predictions(train: Sequence[Sequence[str]], train_verdicts: np.ndarray,
                      test: Sequence[Sequence[str]], seed: int) -> dict[str, np.ndarray]:
    """The learned-model baselines: a decision tree and gradient boosting
    per expectation (scikit-learn), trained on scenes as one-hot
    propositions (for pours, their descriptions), predicting the test scenes.
    Both always decide."""
    from sklearn.ensemble import GradientBoostingClassifier

    return {"tree": tree_predictions(train, train_verdicts, test, seed),
            "boosting": _per_expectation(lambda: GradientBoostingClassifier(random_state=seed),
                                         train, train_verdicts, test)}


def _per_expectation(make, train: Sequence[Sequence[str]], train_verdicts: np.ndarray,
                     test: Sequence[Sequence[str]]) -> np.ndarray:
    """One classifier per expectation (`make()` a fresh one), fitted on the
    one-hot train scenes and predicting the test scenes; an expectation with
    one class in training is predicted as that class."""
    y = np.asarray(train_verdicts, dtype=bool)
    X, T = one_hot(train), one_hot(test)
    out = np.empty((len(T), y.shape[1]), dtype=int)
    for k in range(y.shape[1]):
        if y[:, k].all() or not y[:, k].any():      # one class: nothing to split
            out[:, k] = int(y[0, k])
        else:
            out[:, k] = make().fit(X, y[:, k]).predict(T).astype(int)
    return out


def question_key(S: np.ndarray, of: np.ndarray, n_questions: int) -> tuple[np.ndarray, np.ndarray]:
    """Per question and expectation: the majority verdict of the question's
    pours (`of[i]` is the question of pour i), and whether it is clear (at
    least 75% of them agree)."""
    V = verdicts(S)
    share = np.array([V[of == i].mean(axis=0) for i in range(n_questions)])
    return share >= 0.5, (share >= 0.75) | (share <= 0.25)


def question_misses(answers, key, clear) -> list[tuple[list[int], list[int]]]:
    """Per question: the expectations of its clear cases the answers get
    wrong, and those they leave undecided (answers HOLDS/FAILS/UNKNOWN)."""
    out = []
    for a, k, c in zip(answers, key, clear):
        wrong = [e for e in range(len(a)) if c[e] and a[e] != UNKNOWN and bool(a[e]) != bool(k[e])]
        open_ = [e for e in range(len(a)) if c[e] and a[e] == UNKNOWN]
        out.append((wrong, open_))
    return out


def question_scores(predictions: np.ndarray, key: np.ndarray, clear: np.ndarray) -> dict[str, float]:
    """Coverage (decided among the clear cases) and accuracy (right among
    the decided clear cases) of predictions of the questions."""
    decided = (np.asarray(predictions) != UNKNOWN) & clear
    right = ((np.asarray(predictions) == HOLDS) == key) & decided
    return {"clear": int(clear.sum()), "coverage": float(decided.sum() / max(clear.sum(), 1)),
            "accuracy": float(right.sum() / max(decided.sum(), 1))}


def question_shares(S: np.ndarray, of: np.ndarray, n_questions: int) -> np.ndarray:
    """Per question and expectation: the share of the question's pours in
    which the expectation holds."""
    V = verdicts(S)
    return np.array([V[of == i].mean(axis=0) for i in range(n_questions)])


def defaults_only(train_verdicts: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The defaults-only baseline for n questions: one verdict per
    expectation, the majority of all the pours learned from, whatever is
    asked; and as its likelihood the share of those pours that keep it."""
    share = np.asarray(train_verdicts, dtype=float).mean(axis=0)
    verdict = np.where(share >= 0.5, HOLDS, FAILS)
    return np.tile(verdict, (n, 1)), np.tile(share, (n, 1))


def contrast_keys(key: np.ndarray, clear: np.ndarray, default: np.ndarray) -> np.ndarray:
    """The clear keys whose verdict differs from the defaults-only answer
    (`default`: its verdicts, questions x 9): where knowing the question
    matters."""
    return clear & (key != (np.asarray(default) == HOLDS))


def calibration(likelihood: np.ndarray, share: np.ndarray) -> float | None:
    """The mean absolute difference between the likelihoods stated and the
    shares of the questions' pours, over every key with a likelihood."""
    d = np.abs(np.asarray(likelihood, dtype=float) - share)
    d = d[np.isfinite(d)]
    return float(d.mean()) if len(d) else None


def coherent(predictions: np.ndarray, V: np.ndarray, of: np.ndarray) -> np.ndarray:
    """Per question: whether its decided verdicts, taken together, are a
    behaviour one of its own pours shows (`V`: the pours' verdicts, `of`:
    each pour's question)."""
    out = np.zeros(len(predictions), dtype=bool)
    for i, a in enumerate(np.asarray(predictions)):
        on = a != UNKNOWN
        rows = V[of == i][:, on]
        out[i] = bool((rows == (a[on] == HOLDS)).all(axis=1).any()) if len(rows) else False
    return out


def question_measures(predictions: np.ndarray, likelihood: np.ndarray, share: np.ndarray,
                      key: np.ndarray, clear: np.ndarray, contrast: np.ndarray,
                      V: np.ndarray, of: np.ndarray) -> dict[str, float | int | None]:
    """Every question measure of one theory or model: coverage and accuracy
    on the clear keys, accuracy on the contrast keys (and their coverage),
    calibration, and the share of coherent answers."""
    out = question_scores(predictions, key, clear)
    c = question_scores(predictions, key, contrast)
    out.update(contrast=c["clear"], contrast_coverage=c["coverage"],
               contrast_accuracy=c["accuracy"], calibration=calibration(likelihood, share),
               coherent=float(coherent(predictions, V, of).mean()))
    return out


def distinct_behaviours(consequents: np.ndarray) -> int:
    """How many distinct qualitative behaviours (distinct rows of verdicts)."""
    rows = np.asarray(consequents, dtype=bool)
    return len({tuple(r) for r in rows})
