"""General defeasible rules from every pour, each with the likelihood of
its head: a default per expectation, and the contrasts that move it.

What a rule means. A rule `B => e` (or `B => neg(e)`) speaks of the pours
`pantarhei simulate --antecedent B` samples for B: B as asked, everything
it leaves unsaid as the ordinary pour (the priors). Its `confidence` is the
share of those pours that keep its head, so the likelihood that e holds
when B is asked is the confidence of a rule for e, one minus that of a
rule for neg(e). Its evidence is the pours learned from that could have
been drawn for B (in the support of P(.|B)): `support` of them, `kept` of
which keep the head.

How P(e | B) is known. A gradient-boosted classifier of each verdict from
the 30 parameters is trained on every pour (the model of the pours), and
averaged over `samples` parameterizations drawn from P(.|B) (`Meaning`).
Importance weights alone cannot do it: an explored antecedent moves the
parameters it names outside what a short question draws, so few explored
pours lie in the support of P(.|B) for most B.

How rules are found (per expectation, greedy). The bodies a person asks
about are the empty one, every valid proposition alone and every valid
pair (`max_body`). The theory answers a body with its deciding rule's
likelihood (the highest ranked rule whose body it holds), and each body
costs |answered - P(e | B)|, plus `miss` where the two fall in different
bands (holds, uncertain, fails: `band`), weighted by how often it is asked
(the empty body `default_weight`, one proposition 1, a pair
`pair_weight`). The default (the empty body, likelihood P(e | ())) comes
first; then, while the expectation has fewer than `max_rules` rules, the
rule for the body whose own likelihood removes the most cost joins, as
long as it removes at least `min_gain`. A rule for one proposition answers
every pair that holds it and has no rule of its own; a pair gets a rule
where the two propositions interact: where neither proposition's rule
gives the pair's likelihood.

How a question is decided. A scene (a set of propositions) is decided, for
each expectation, by the highest ranked rule whose body it holds. Rules rank
by body size (more specific first), then by the distance of their confidence
from one half, then by id. This is exactly standard defeasible logic
(theory/defeasible.pl in each of its eight variants) over the
rules and `sup/2` facts: more specific learned rules beat less specific ones
with the complementary head (specificity, which the engine derives), and
every other pair of conflicting rules that can apply together gets an
explicit `sup/2` fact in rank order. The order is a linear one, so the
superiority relation is acyclic, and no conflict stays undecided. The
default's empty body makes every scene decided.
"""
from __future__ import annotations

import zlib
from dataclasses import dataclass, field, replace
from functools import lru_cache
from itertools import combinations
from typing import Iterable, Sequence

import numpy as np

from pantarhei.oracle.generative import InvalidAntecedent, in_support, normalise, sample
from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.measures import FAILS, HOLDS, UNKNOWN, verdicts
from pantarhei.bridge.theories.model import Rule, Theory


@dataclass(frozen=True)
class Settings:
    max_rules: int = 12        # per expectation, the default included
    max_body: int = 2          # propositions in a body (0 to 2)
    samples: int = 64          # drawn per body to estimate its likelihood
    seed: int = 1
    #: an answer whose likelihood lies within this of one half is uncertain
    #: (theory/defaults.pl's uncertain_band, which the Prolog answers read)
    band: float = field(default_factory=lambda: float(defaults()["uncertain_band"]))
    #: the cost of an answer in another band than the body's likelihood,
    #: beside the difference of the likelihoods
    miss: float = 0.5
    #: how much each kind of body counts: the empty one, one proposition
    #: (1), a pair
    default_weight: float = 20.0
    pair_weight: float = 0.2
    #: the weighted cost a new rule must remove
    min_gain: float = 0.1

    def __post_init__(self) -> None:
        if self.max_rules < 1 or not 0 <= self.max_body <= 2:
            raise ValueError("max_rules must be at least 1 and max_body 0 to 2")
        if not 0 <= self.band < 0.5 or self.samples < 1:
            raise ValueError("band in [0, 1/2), samples at least 1")
        if min(self.miss, self.default_weight, self.pair_weight, self.min_gain) < 0:
            raise ValueError("miss, weights and min_gain at least 0")

    def verdict(self, likelihood):
        """HOLDS, FAILS or UNKNOWN (uncertain) for a likelihood that e holds
        (a number or an array of them)."""
        x = np.asarray(likelihood, dtype=float)
        out = np.where(x >= 0.5 + self.band - 1e-9, HOLDS,
                       np.where(x <= 0.5 - self.band + 1e-9, FAILS, UNKNOWN))
        return int(out) if out.ndim == 0 else out


def rank(body: Sequence[str], confidence: float, rule_id: str) -> tuple:
    """How a learned rule ranks against a conflicting one that can apply in
    the same scene; higher ranks win: more specific, then surer, then the id."""
    return (len(body), round(abs(confidence - 0.5), 9), rule_id)


@dataclass(frozen=True)
class GeneralRule:
    """`body => expectation` (holds) or `body => neg(expectation)`."""
    id: str
    body: tuple[str, ...]
    expectation: str
    holds: bool
    support: int          # explored pours whose description holds the body
    kept: int             # of those, how many keep the head
    confidence: float     # P(head | body): the share of the body's pours that keep the head
    level: int            # 0 default, 1 exception, 2 exception to an exception, ...

    @property
    def head(self) -> str:
        return self.expectation if self.holds else f"neg({self.expectation})"

    @property
    def rank(self) -> tuple:
        return rank(self.body, self.confidence, self.id)

    @property
    def likelihood(self) -> float:
        """The share of the body's pours in which the expectation holds."""
        return self.confidence if self.holds else 1 - self.confidence

    def rule(self) -> Rule:
        return Rule(self.id, "defeasible", self.head, self.body)


def deciding(rules: Sequence[GeneralRule], scene: set[str]) -> int | None:
    """The index of the rule that decides a scene: the highest ranked of
    those whose body it holds (None when none does)."""
    live = [j for j, r in enumerate(rules) if set(r.body) <= scene]
    return max(live, key=lambda j: rules[j].rank) if live else None


@dataclass(frozen=True)
class Sup:
    """`superior` beats `inferior`: by specificity (the engine derives it
    among learned rules) or by rank (an explicit sup/2 fact)."""
    superior: str
    inferior: str
    reason: str           # "specificity" or "rank"


@dataclass
class General:
    """The general rules of every expectation and their superiority."""
    rules: list[GeneralRule] = field(default_factory=list)
    sup: list[Sup] = field(default_factory=list)
    #: answers whose likelihood lies within this of one half are uncertain
    band: float = 0.0

    def of(self, expectation: str) -> list[GeneralRule]:
        return [r for r in self.rules if r.expectation == expectation]

    def decide(self, scene: Iterable[str]) -> dict[str, tuple[int, str | None]]:
        """Per expectation: HOLDS, FAILS or UNKNOWN (undecided, or uncertain:
        the likelihood within `band` of one half), and the deciding rule's id."""
        return {e: (v, rid) for e, (v, _, rid) in self.answer(scene).items()}

    def answer(self, scene: Iterable[str]) -> dict[str, tuple[int, float, str | None]]:
        """Per expectation: the verdict (as `decide`), the likelihood that it
        holds (NaN where no rule decides), and the deciding rule's id."""
        s = set(scene)
        out: dict[str, tuple[int, float, str | None]] = {}
        for e in load_vocabulary().expectation_names:
            rules = self.of(e)
            j = deciding(rules, s)
            if j is None:
                out[e] = (UNKNOWN, float("nan"), None)
                continue
            p = rules[j].likelihood
            v = UNKNOWN if abs(p - 0.5) < self.band - 1e-9 else HOLDS if rules[j].holds else FAILS
            out[e] = (v, p, rules[j].id)
        return out

    def predict(self, scenes: Sequence[Iterable[str]]) -> np.ndarray:
        """scenes x 9: HOLDS, FAILS or UNKNOWN, as `decide`."""
        names = load_vocabulary().expectation_names
        out = np.full((len(scenes), len(names)), UNKNOWN, dtype=int)
        for i, s in enumerate(scenes):
            d = self.decide(s)
            out[i] = [d[e][0] for e in names]
        return out

    def theory(self, source: str = "<general>") -> Theory:
        """The rules as learned defeasible rules, with the explicit sup/2
        facts (specificity is left to the engines, which derive it)."""
        t = Theory(source=source)
        for r in self.rules:
            t.rules.append(r.rule())
            t.learned.add(r.id)
        t.sup = [(s.superior, s.inferior) for s in self.sup if s.reason == "rank"]
        return t


# -- the propositions a pour holds, and which bodies can be asked --------------

@lru_cache(maxsize=1)
def _conflicts() -> frozenset[frozenset[str]]:
    from pantarhei.theory import VOCABULARY_FILES, read_facts

    return frozenset(frozenset(c[1:]) for c in read_facts(VOCABULARY_FILES).get("conflict", []))


def _askable(body: Sequence[str]) -> bool:
    """Whether a body is a valid antecedent: one value per dimension, one
    proposition per parameter, no listed conflict."""
    v = load_vocabulary()
    props = [v.proposition(p) for p in body]
    if len({p.dimension for p in props}) < len(props) or len({p.model.param for p in props}) < len(props):
        return False
    return not any(frozenset(pair) in _conflicts() for pair in combinations(body, 2))


def _seed(seed: int, body: Sequence[str]) -> int:
    return int(np.random.SeedSequence([int(seed), zlib.crc32(" ".join(body).encode())])
               .generate_state(1)[0])


class Meaning:
    """P(e | B) for every expectation e: the model of the pours (one
    gradient-boosted classifier per expectation, on the 30 parameters),
    averaged over parameterizations drawn from P(.|B)."""

    def __init__(self, P: np.ndarray, Y: np.ndarray, settings: Settings):
        from sklearn.ensemble import HistGradientBoostingClassifier

        self.settings = settings
        X = normalise(P)
        self.models: list = []
        for k in range(Y.shape[1]):
            y = Y[:, k]
            if y.all() or not y.any():
                self.models.append(float(y[0]) if len(y) else 0.5)
                continue
            m = HistGradientBoostingClassifier(max_depth=3, max_iter=150, learning_rate=0.1,
                                               min_samples_leaf=10, early_stopping=False,
                                               random_state=settings.seed)
            self.models.append(m.fit(X, y))

    def __call__(self, bodies: Sequence[tuple[str, ...]]) -> np.ndarray:
        """len(bodies) x 9: the estimated P(e | B); NaN where B cannot be
        sampled. Shorter bodies, which more questions fall back on, get
        more draws: `samples` for a pair, 4 times as many for one
        proposition, 16 times for the empty body."""
        out = np.full((len(bodies), len(self.models)), np.nan)
        rows, ok, sizes = [], [], []
        for i, b in enumerate(bodies):
            n = self.settings.samples * {0: 16, 1: 4}.get(len(b), 1)
            try:
                rows.append(sample(list(b), n, _seed(self.settings.seed, b)))
            except InvalidAntecedent:
                continue
            ok.append(i)
            sizes.append(n)
        if not rows:
            return out
        p = self.shares(normalise(np.vstack(rows)))
        ends = np.cumsum(sizes)
        for i, start, end in zip(ok, ends - sizes, ends):
            out[i] = p[start:end].mean(axis=0)
        return out

    def shares(self, X: np.ndarray) -> np.ndarray:
        """len(X) x 9: the chance that each expectation holds, per pour
        (rows of normalised parameters)."""
        return np.column_stack([np.full(len(X), m) if isinstance(m, float) else m.predict_proba(X)[:, 1]
                                for m in self.models])


# -- the learner -----------------------------------------------------------------

def generalize(P: np.ndarray, S: np.ndarray, settings: Settings = Settings()) -> General:
    """The general rules of pours P (n x 30) with scores S (n x 9); pours
    with a failed simulation (a NaN score) are left out."""
    from threadpoolctl import threadpool_limits

    # one thread: the models are small, and spinning threads on a shared
    # machine cost more than they give
    with threadpool_limits(1):
        return _generalize(P, S, settings)


def askable_bodies(max_body: int) -> list[tuple[str, ...]]:
    """The empty body, every proposition alone and every valid pair (up to
    `max_body` propositions), in canonical order."""
    names = sorted(load_vocabulary().propositions)
    out: list[tuple[str, ...]] = [()]
    if max_body >= 1:
        out += [(n,) for n in names]
    if max_body >= 2:
        out += [b for b in combinations(names, 2) if _askable(b)]
    return out


def _generalize(P: np.ndarray, S: np.ndarray, settings: Settings) -> General:
    vocab = load_vocabulary()
    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    ok = np.all(np.isfinite(S), axis=1)
    P, S = P[ok], S[ok]
    if not len(P):
        raise ValueError("no pours to generalize from")
    Y = verdicts(S)
    bodies = askable_bodies(settings.max_body)
    T = Meaning(P, Y, settings)(bodies)
    known = np.isfinite(T[:, 0])
    bodies, T = [b for b, k in zip(bodies, known) if k], T[known]
    out = General(band=settings.band)
    for k, e in enumerate(vocab.expectation_names):
        rules = _Contrasts(e, bodies, T[:, k], settings).learn()
        out.rules.extend(_with_evidence(r, P, Y[:, k]) for r in rules)
    for e in vocab.expectation_names:
        out.sup.extend(_superiority(out.of(e)))
    return out


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
        while len(chosen) < self.s.max_rules:
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
            rule = replace(rule, level=_level(rule.body, rule.holds, chosen))
            taken.add(best)
            chosen.append(rule)
            at = self.above[best]
            at = at[[rule.rank > chosen[decider[j]].rank for j in at]]
            decider[at] = len(chosen) - 1
            answered[at] = rule.likelihood
            now[at] = self.cost(answered[at], at)
        return chosen


def _level(body, r_holds: bool, chosen: Sequence[GeneralRule]) -> int:
    under = [r.level for r in chosen if r.holds != r_holds and set(r.body) < set(body)]
    return 1 + max(under) if under else 1


def together(a: Sequence[str], b: Sequence[str]) -> bool:
    """Whether one scene can hold both bodies."""
    return _askable(tuple(sorted(set(a) | set(b))))


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
