"""The general learner: general defeasible rules from every pour, each
with the likelihood of its head: a default per expectation, and the
contrasts that move it. What a rule means and how P(e | B) is known:
`meaning`; the rules and how they decide a question: `general_rules`.

How rules are found (per expectation, greedy). The bodies a person asks
about are the empty one, every valid proposition alone and every valid
pair (`max_body`, `askable`). The theory answers a body with its deciding
rule's likelihood (the highest ranked rule whose body it holds), and each
body costs |answered - P(e | B)|, plus `miss` where the two fall in
different bands (holds, uncertain, fails: `band`), weighted by how often
it is asked (the empty body `default_weight`, one proposition 1, a pair
`pair_weight`). The default (the empty body, likelihood P(e | ())) comes
first; then, while the expectation has fewer than `rules_per_expectation` rules, the
rule for the body whose own likelihood removes the most cost joins, as
long as it removes at least `min_gain`. A rule for one proposition answers
every pair that holds it and has no rule of its own; a pair gets a rule
where the two propositions interact: where neither proposition's rule
gives the pair's likelihood. Every pair of conflicting rules that can
apply together is ordered by rank (`Sup`).

Where the answers are doubted (doubts.py): the union of two sure rules
that conflict, a body whose own pours contradict a sure answer, a pair
next to an explored pair that interacts. Their rules come after the
contrasts, beyond `rules_per_expectation`.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from itertools import combinations
from typing import Sequence

import numpy as np

from pantarhei.oracle.generative import in_support
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.learning.askable import askable_bodies, together
from pantarhei.bridge.learning.doubts import doubts, exceptions, level, neighbours, few_pours, thinly_poured
from pantarhei.bridge.learning.general_rules import General, GeneralRule, Sup, verdict
from pantarhei.bridge.learning.meaning import Meaning, held_in_support, pooled


def _tuned(key: str, kind: type = float):
    """The default of a field: theory/defaults.pl's `general_KEY`."""
    return field(default_factory=lambda: kind(defaults()[f"general_{key}"]))


@dataclass(frozen=True)
class Settings:
    """The general learner's tuning, each default written once in
    theory/defaults.pl (`general_...`)."""
    rules_per_expectation: int = _tuned("rules_per_expectation", int)   # the default included
    max_body: int = _tuned("max_body", int)    # propositions in a body (0 to 2)
    draws: int = _tuned("draws", int)          # parameterizations drawn per body to estimate its likelihood
    seed: int = 1
    #: an answer whose likelihood lies within this of one half is uncertain
    #: (theory/defaults.pl's uncertain_band, which the Prolog answers read)
    band: float = field(default_factory=lambda: float(defaults()["uncertain_band"]))
    #: the cost of an answer in another band than the body's likelihood,
    #: beside the difference of the likelihoods
    miss: float = _tuned("miss")
    #: how much each kind of body counts: the empty one, one proposition
    #: (1), a pair
    default_weight: float = _tuned("default_weight")
    pair_weight: float = _tuned("pair_weight")
    #: the weighted cost a new rule must remove
    min_gain: float = _tuned("min_gain")
    #: the pours of their own below which the union of two conflicting
    #: rules' bodies, each rule at least `doubt_confidence` sure of its
    #: head, gets an uncertain rule (0: never)
    doubt_support: int = _tuned("doubt_support", int)
    doubt_confidence: float = _tuned("doubt_confidence")
    #: fewer pours of a body's own than `doubt_support` contradict a sure
    #: answer when their count would be less likely than this under it
    unlikely: float = _tuned("unlikely")
    #: how many pours the model's estimate counts as beside a body's own
    #: (the pours in its support), for a body of one proposition or more
    model_pours: float = _tuned("model_pours")

    def __post_init__(self) -> None:
        if self.rules_per_expectation < 1 or not 0 <= self.max_body <= 2:
            raise ValueError("rules_per_expectation must be at least 1 and max_body 0 to 2")
        if not 0 <= self.band < 0.5 or self.draws < 1:
            raise ValueError("band in [0, 1/2), draws at least 1")
        if min(self.miss, self.default_weight, self.pair_weight, self.min_gain,
               self.doubt_support, self.model_pours, self.unlikely) < 0:
            raise ValueError("miss, weights, min_gain, doubt_support and model_pours at least 0")

    def verdict(self, likelihood):
        """HOLDS, FAILS or UNKNOWN (uncertain) for a likelihood that e holds
        (a number or an array of them), as a rule of that likelihood would
        answer (`general_rules.verdict`)."""
        x = np.asarray(likelihood, dtype=float)
        return verdict(x >= 0.5, x, self.band)


def generalize(P: np.ndarray, S: np.ndarray, settings: Settings = Settings(),
               bodies: Sequence[Sequence[str]] | None = None) -> General:
    """The general rules of pours P (n x 30) with scores S (n x 9); pours
    with a failed simulation (a NaN score) are left out. The rules' bodies
    are chosen among `bodies` (and the empty one, the default's), or
    among the askable bodies when None."""
    from threadpoolctl import threadpool_limits

    # one thread: the models are small, and spinning threads on a shared
    # machine cost more than they give
    with threadpool_limits(1):
        return _generalize(P, S, settings, bodies)


def learn(P: np.ndarray, S: np.ndarray, seed: int,
          bodies: Sequence[Sequence[str]] | None = None) -> General:
    """The general rules of pours P with scores S, with the default
    `Settings` and `seed`, over `bodies` as `generalize`: this learner as
    `learners.py` names it."""
    return generalize(P, S, Settings(seed=int(seed)), bodies)


def _generalize(P: np.ndarray, S: np.ndarray, settings: Settings,
                among: Sequence[Sequence[str]] | None = None) -> General:
    vocab = load_vocabulary()
    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    ok = np.all(np.isfinite(S), axis=1)
    P, S = P[ok], S[ok]
    if not len(P):
        raise ValueError("no pours to generalize from")
    Y = verdicts(S)
    if among is None:
        bodies = askable_bodies(settings.max_body)
    else:
        bodies = list(dict.fromkeys([()] + [tuple(sorted(str(p) for p in b)) for b in among]))
    meaning = Meaning(P, Y, settings)
    T = meaning(bodies)
    known = np.isfinite(T[:, 0])
    bodies, T = [b for b, k in zip(bodies, known) if k], T[known]
    own = [held_in_support(P, Y, b) for b in bodies]      # per body: held per expectation, pours
    held, n = np.array([h for h, _ in own]), np.array([c for _, c in own])
    T = _with_own_pours(T, bodies, held, n, settings.model_pours)
    pairs, pair_held, pair_n = thinly_poured(P, Y, settings)
    out = General(band=settings.band)
    for k, e in enumerate(vocab.expectation_names):
        rules = _Contrasts(e, bodies, T[:, k], settings).learn()
        rules += doubts(rules, k, meaning, P, settings)
        rules += exceptions(rules, bodies, T[:, k], held[:, k], n, settings)
        rules += neighbours(rules, bodies, T[:, k], n, k, meaning, P, settings)
        rules += few_pours(rules, pairs, pair_held[:, k], pair_n, k, meaning, settings)
        out.rules.extend(_with_evidence(r, P, Y[:, k]) for r in rules)
    for e in vocab.expectation_names:
        out.sup.extend(_superiority(out.of(e)))
    return out


def _with_own_pours(T: np.ndarray, bodies: Sequence[tuple[str, ...]], held: np.ndarray,
                    n: np.ndarray, k: float) -> np.ndarray:
    """The likelihoods T of `bodies` with each body's own pours (the `n`
    in its support, of which `held` hold each expectation) counted beside
    the model's estimate, which counts as `k`
    pours: (kept + k T) / (n + k). The model smooths over a region a few
    pours hold (a leaf holds at least 10): 2 of 2 pours that fail are not
    answered `yes` 96%, but `maybe`; many pours of its own outweigh it.
    The empty body keeps the model's: its support holds every pour."""
    T = T.copy()
    for i, b in enumerate(bodies):
        if b and n[i]:
            T[i] = pooled(held[i], n[i], T[i], k)
    return T


def _with_evidence(r: GeneralRule, P: np.ndarray, y: np.ndarray) -> GeneralRule:
    """The rule with its evidence: the pours that could have been drawn for
    its body (in the support of P(.|B): the body as asked, everything else
    an ordinary pour), and how many of them keep its head."""
    m = in_support(P, r.body)
    return replace(r, support=int(m.sum()), kept=int((y[m] == r.holds).sum()))


class _Contrasts:
    """The greedy choice of one expectation's rules over the askable bodies
    (`bodies`, with their likelihoods `target`)."""

    def __init__(self, e: str, bodies: Sequence[tuple[str, ...]], target: np.ndarray,
                 s: Settings):
        self.e, self.bodies, self.target, self.s = e, list(bodies), target, s
        self.weight = np.array([s.default_weight if not b else 1.0 if len(b) == 1 else s.pair_weight
                                for b in bodies])
        self.band = s.verdict(target)
        index = {b: i for i, b in enumerate(self.bodies)}
        #: per body, the askable bodies that hold it (itself included)
        self.above: list[np.ndarray] = [np.array([], dtype=int)] * len(bodies)
        holders: dict[int, list[int]] = {i: [i] for i in range(len(bodies))}
        for j, b in enumerate(self.bodies):
            for size in range(1, len(b)):
                for sub in combinations(b, size):
                    if sub in index:
                        holders[index[sub]].append(j)
        self.above = [np.array(sorted(v), dtype=int) for _, v in sorted(holders.items())]
        self.root = index[()]

    def cost(self, answered: np.ndarray, at: np.ndarray) -> np.ndarray:
        """The weighted cost of answering the bodies `at` with likelihoods `answered`."""
        t = self.target[at]
        miss = self.s.verdict(answered) != self.band[at]
        return self.weight[at] * (np.abs(answered - t) + self.s.miss * miss)

    def rule(self, i: int, n: int) -> GeneralRule:
        t, b = float(self.target[i]), self.bodies[i]
        holds = t >= 0.5
        return GeneralRule(f"g{n}_{self.e}", b, self.e, holds, 0, 0, t if holds else 1 - t, 0)

    def learn(self) -> list[GeneralRule]:
        chosen = [self.rule(self.root, 0)]
        decider = np.zeros(len(self.bodies), dtype=int)     # index into chosen
        answered = np.full(len(self.bodies), float(self.target[self.root]))
        now = self.cost(answered, np.arange(len(self.bodies)))
        taken = {self.root}
        while len(chosen) < self.s.rules_per_expectation:
            best, best_gain = None, self.s.min_gain
            for i in range(len(self.bodies)):
                if i in taken:
                    continue
                cand = self.rule(i, len(chosen))
                at = self.above[i]
                wins = np.array([cand.rank > chosen[decider[j]].rank for j in at], dtype=bool)
                at = at[wins]
                if not len(at):
                    continue
                gain = float(now[at].sum() - self.cost(np.full(len(at), cand.likelihood), at).sum())
                if gain > best_gain + 1e-12:
                    best, best_gain = i, gain
            if best is None:
                break
            rule = self.rule(best, len(chosen))
            rule = replace(rule, level=level(rule.body, rule.holds, chosen))
            taken.add(best)
            chosen.append(rule)
            at = self.above[best]
            at = at[[rule.rank > chosen[decider[j]].rank for j in at]]
            decider[at] = len(chosen) - 1
            answered[at] = rule.likelihood
            now[at] = self.cost(answered[at], at)
        return chosen


def _superiority(rules: Sequence[GeneralRule]) -> list[Sup]:
    """Every pair of conflicting rules that can apply together, in rank
    order: by specificity where one body holds the other, else by an
    explicit sup/2."""
    out = []
    for r, q in combinations(rules, 2):
        if r.holds == q.holds or not together(r.body, q.body):
            continue
        hi, lo = (r, q) if r.rank > q.rank else (q, r)
        reason = "specificity" if set(lo.body) < set(hi.body) else "rank"
        out.append(Sup(hi.id, lo.id, reason))
    return out
