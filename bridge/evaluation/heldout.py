"""Held-out scenes: valid antecedents that exploration never explored,
drawn uniformly (by Prolog's validity:random_antecedents/3) or near given
antecedents (one or two propositions added), and how well each theory
predicts them: along the budget, and at its end beside a decision tree."""
from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from pantarhei.bridge.evaluation.measures import accuracy, distinct_behaviours, tree_predictions
from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.evaluation.rule_building import consequents, predict, theory_of
from pantarhei.bridge.exploration.simulation import iteration_seed
from pantarhei.bridge.reasoning.valid_scenes import random_antecedents, violations
from pantarhei.bridge.theories.model import Theory
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


def heldout_curves(ev, methods: dict, held: dict, samples: int, mode: str) -> None:
    """Behaviours, coverage and accuracy of each method's theory after each
    explored antecedent (the curves over the budget): `ev.curves`, and
    `ev.behaviours` at the end (`methods`: name -> inputs.Pours)."""
    R = min(len(m.P) for m in methods.values()) // samples
    out: dict[str, Any] = {"budget": [k * samples for k in range(1, R + 1)]}
    for method, m in methods.items():
        beh, cov, acc = [], {k: [] for k in held}, {k: [] for k in held}
        for r in range(1, R + 1):
            # the antecedents whose pours are all within the budget so far
            k = max(1, m.upto(r * samples))
            end = m.ends[k - 1]
            heads = consequents(m.antecedents[:k], m.P[:end], m.S[:end], mode)
            beh.append(distinct_behaviours(heads))
            th = theory_of(m.antecedents[:k], heads, f"{method}@{k}")
            for name, (sel, y) in held.items():
                a = accuracy(predict(th, sel), y)
                cov[name].append(a.overall_coverage)
                acc[name].append(None if np.isnan(a.overall_accuracy) else a.overall_accuracy)
        out[method] = {"behaviours": beh, "coverage": cov, "accuracy": acc}
        ev.behaviours[method] = beh[-1]
    ev.curves = out


def heldout_theories(ev, theory: Theory, methods: dict, held: dict,
                     samples: int, mode: str, seed: int) -> None:
    """Per held-out set: the accuracy of the learned theory, of the random
    exploration's theory, and of a decision tree trained on each method's
    pours: `ev.heldout`."""
    rnd = methods["random"]
    final = {"curiosity": theory,
             "random": theory_of(rnd.antecedents, consequents(rnd.antecedents, rnd.P, rnd.S, mode),
                                 "random")}
    for name, (sel, y) in held.items():
        out: dict[str, Any] = {"scenes": len(sel),
                               "mean_propositions": float(np.mean([len(s) for s in sel]))
                               if sel else 0.0}
        for label, th in final.items():
            out[f"{label}_theory"] = accuracy(predict(th, sel), y).as_dict()
        for label, m in methods.items():
            X = m.drawn
            okr = np.all(np.isfinite(m.S), axis=1)
            Xk = [x for x, o in zip(X, okr) if o]
            out[f"{label}_tree"] = accuracy(
                tree_predictions(Xk, verdicts(m.S[okr]), sel, seed), y).as_dict()
        ev.heldout[name] = out
