"""The order in which the planner searches manners in the simulation,
when the theory proposes no plan it has not tried.

Every manner proposition alone with the given context is a candidate
(then the pairs of the PAIRED best), most promising first as the theory
predicts the goals (its likelihoods multiplied). Where the theory rates
candidates alike (as it does for every manner when its rules of the
context outweigh those of the manners), the pours the search has seen
order them: every plan verified leaves pours drawn for its antecedent
that met the goals or did not, and those lying where a candidate sets
its parameters apart from the context estimate its share (the others
varying as the pours seen vary them), shrunk towards the share of all
the pours seen by PRIOR pours' weight (the mean of a beta posterior);
each goal's share, multiplied, orders those alike still. A manner whose
range holds the pours that met the goals comes first, one whose range
holds those that missed last, one no pour seen lies in between; each
candidate refuted adds its pours, and the order is drawn again before
every plan. Where the theory tells candidates apart, it orders them.
"""
from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING, Sequence

import numpy as np

from pantarhei.oracle.generative import InvalidAntecedent, distribution
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.reasoning.planning import Plan
from pantarhei.bridge.theories.model import Theory, complement

if TYPE_CHECKING:
    from pantarhei.bridge.reasoning.plan_trials import Trial

#: The singles whose pairs the search tries.
PAIRED = 8
#: The weight, in pours, of the prior share (that of every pour seen) in a
#: candidate's estimate.
PRIOR = 2.0


def ranked_singles(theory: Theory, goals: list[str], given: list[str]
                   ) -> list[tuple[float, tuple[str, ...]]]:
    """Every manner proposition alone with the given context, each valid,
    with its promise (the theory's likelihoods of the goals multiplied; an
    undecided goal one half); most promising first, then in the
    vocabulary's order."""
    from pantarhei.bridge.reasoning.valid_scenes import violations

    vocab = load_vocabulary()
    taken = {vocab.propositions[p].dimension for p in given}
    manners = [p for p, x in vocab.propositions.items()
               if vocab.dimensions[x.dimension].role == "manner" and x.dimension not in taken]
    singles = [(p,) for p in manners if not violations([*given, p])]
    scored = sorted((-promise(theory, goals, given, c), i, c) for i, c in enumerate(singles))
    return [(-s, c) for s, _, c in scored]


def next_plan(given: list[str], singles: list[tuple[float, tuple[str, ...]]], goals: list[str],
              seen: list[tuple[np.ndarray, np.ndarray]], tried: Sequence[Trial],
              exclude: set) -> Plan | None:
    """The search's most promising plan not tried and not in `exclude`
    (candidates over the singles ordered by by_model); None: none left."""
    done = {t.plan.chosen for t in tried} | exclude
    ordered = by_model(singles, goals, given, seen)
    return next((p for p in candidates(given, ordered, tried, goals, seen) if p.chosen not in done),
                None)


def by_model(singles: list[tuple[float, tuple[str, ...]]], goals: list[str], given: list[str],
             seen: list[tuple[np.ndarray, np.ndarray]]) -> list[tuple[float, tuple[str, ...]]]:
    """The singles, most promising first as before, those the theory
    rates alike in the order of their chance by a model of the pours seen
    (chances); as they were while it cannot tell."""
    chance = _chances(seen, goals, [(*given, *c) for _, c in singles], given)
    if chance is None:
        return singles
    order = sorted(range(len(singles)),
                   key=lambda i: (-singles[i][0], -chance[i][0], -chance[i][1], i))
    return [singles[i] for i in order]


def promise(theory: Theory, goals: list[str], given: list[str], chosen: tuple[str, ...]) -> float:
    """The theory's likelihoods of the goals given the context and `chosen`,
    multiplied (an undecided goal one half)."""
    from pantarhei.bridge.reasoning.answers import what_happens

    said = {a.expectation: a.likelihood for a in what_happens(theory, [*given, *chosen])}
    s = 1.0
    for g in goals:
        negated = g.startswith("neg(")
        like = said.get(complement(g) if negated else g)
        s *= 0.5 if like is None else (1 - like if negated else like)
    return s


def candidates(given: list[str], singles: list[tuple[float, tuple[str, ...]]],
               tried: Sequence[Trial], goals: Sequence[str] = (),
               seen: Sequence[tuple[np.ndarray, np.ndarray]] = ()) -> list[Plan]:
    """The singles (ranked_singles), then the valid pairs of the PAIRED
    best: a single tried counts by the share of its pours that met every
    goal, one not tried by its promise; the pairs of the best first, those
    alike in the order of their chance by the pours `seen` (chances)."""
    from pantarhei.bridge.reasoning.valid_scenes import violations

    rates = {t.plan.chosen: t.rate for t in tried}
    value = {c: rates.get(c, theirs) for theirs, c in singles}
    ranked = sorted(range(len(singles)), key=lambda i: (-value[singles[i][1]], i))
    top = [singles[i][1][0] for i in ranked[:PAIRED]]
    rank = {p: k for k, p in enumerate(top)}
    pairs = [tuple(sorted(pair)) for pair in combinations(top, 2) if not violations([*given, *pair])]
    est = _chances(seen, goals, [(*given, *c) for c in pairs], given)
    chance = dict(zip(pairs, [tuple(-x for x in e) for e in est] if est is not None
                      else [(0.0, 0.0)] * len(pairs)))
    pairs.sort(key=lambda c: (-(value[(c[0],)] + value[(c[1],)]), chance[c],
                              sorted(rank[p] for p in c)))
    return [Plan(c, tuple(sorted([*given, *c]))) for c in [*(c for _, c in singles), *pairs]]


def chances(P: np.ndarray, S: np.ndarray, goals: Sequence[str],
            antecedents: Sequence[Sequence[str]], context: Sequence[str] = ()) -> np.ndarray | None:
    """len(antecedents) x 2: for each antecedent, the estimated share of
    pours drawn for it that meet every goal, and the estimated shares of
    each goal multiplied (which still ranks candidates when no pour met
    every goal). A share is estimated from the pours P (scores S; those
    that did not finish left out) that could have been drawn for the
    antecedent: the share that met the goals, shrunk towards the share of
    all the pours by PRIOR pours' weight (the mean of a beta posterior).
    An antecedent that cannot be sampled gets 0; None when no pour
    finished."""
    from pantarhei.bridge.reasoning.planning import goals_met

    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    done = np.all(np.isfinite(S), axis=1) if len(S) else np.zeros(0, dtype=bool)
    if not done.any():
        return None
    P, S = P[done], S[done]
    Y = np.column_stack([goals_met(S, list(goals))] + [goals_met(S, [g]) for g in goals])
    prior = Y.mean(axis=0)
    out = np.zeros((len(antecedents), 2))
    for i, a in enumerate(antecedents):
        try:
            m = inside(P, a, context)
        except InvalidAntecedent:
            continue
        share = (Y[m].sum(axis=0) + PRIOR * prior) / (m.sum() + PRIOR)
        out[i] = share[0], np.prod(share[1:])
    return out


def inside(P: np.ndarray, antecedent: Sequence[str], context: Sequence[str]) -> np.ndarray:
    """Which pours P lie where the antecedent sets the parameters it sets
    apart from the context (a relative one, against its base's value);
    InvalidAntecedent for one that cannot be sampled."""
    a, c = distribution(list(antecedent)), distribution(list(context))
    changed = (a.low != c.low) | (a.high != c.high) | (a.base != c.base)
    m = np.ones(len(P), dtype=bool)
    for i in np.flatnonzero(changed):
        lo, hi = a.low[i], a.high[i]
        if a.base[i] >= 0:
            b = P[:, a.base[i]]
            lo, hi = np.maximum(a.bound_low[i], b + lo), np.minimum(a.bound_high[i], b + hi)
        m &= (P[:, i] >= lo) & (P[:, i] <= hi)
    return m


def _chances(seen: Sequence[tuple[np.ndarray, np.ndarray]], goals: Sequence[str],
             antecedents: Sequence[Sequence[str]], context: Sequence[str]) -> np.ndarray | None:
    """chances() over the pours of every plan seen; None when none is."""
    if not seen or not antecedents:
        return None
    return chances(np.vstack([P for P, _ in seen]), np.vstack([S for _, S in seen]), goals,
                   antecedents, context)
