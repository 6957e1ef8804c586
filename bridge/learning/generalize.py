"""General defeasible rules from every pour: defaults, exceptions to them,
and exceptions to those.

What a rule means. A rule `B => e` (or `B => neg(e)`) says that the pours
`pantarhei simulate --antecedent B` samples for B mostly keep e (or mostly
break it): every parameter B leaves unsaid follows its prior. Its
`confidence` is that share, P(e | B) under the generative model of B, and
its evidence is the pours of the exploration that B describes
(`describe`): `support` of them, `kept` of which keep the rule's head.

Why not importance weights alone. Equation (1)'s densities would give
P(e | B) from every pour as sum w y / sum w with w = P(p|B) / q(p), q the
mixture of the distributions the pours were drawn from. But the priors are
narrow where a question is silent (the start and end poses of an ordinary
pour), and an explored antecedent of 15-20 propositions moves those
parameters outside them: no explored pour lies in the support of P(.|B)
for a short B (0 of the 775 pours of 25 random valid antecedents, for the
empty body as for each short question), so the weights are all zero. Instead P(e | B) is
estimated by the model of the pours: a gradient-boosted classifier of each
verdict from the 30 parameters, trained on every pour, averaged over
`samples` parameterizations drawn from P(.|B).

How rules are found (per expectation, greedy, as a decision list):

1. the default: the empty body, concluding the verdict most pours sampled
   from the priors would give. Where that is within `margin` of one half,
   the priors leave it open, and the pours are no guide either: curiosity
   draws them to where behaviour changes, so their majority is not that of
   scenes at large. Then a decision list is learned for each default, and
   the one kept is the list that the model of the pours finds right more
   often on `judges` uniformly random valid antecedents (drawn by Prolog,
   with a seed of their own), on ties the pours' majority. (One default
   can need many exceptions where the other needs few: liquid stays in the
   source unless the source tips far, so "stays" takes exceptions naming
   the pour's tilt, "leaves" a list of everything that keeps it upright.)
   The default's confidence is then the share of the pours of the judging
   antecedents it decides that the model expects to keep its head;
2. candidates: bodies of one or two propositions (and three, extending a
   chosen body of two) that are valid antecedents, that at least
   `min_support` pours satisfy, and whose pours mostly (at least `margin`
   from one half) give one verdict: the candidate's head;
3. repeatedly, the candidate that sets right the most pours, net of a cost
   of `penalty` times the number of pours per proposition of its body (each
   pour is the scene of its own description, decided by the rules so far;
   among equals the body describing the fewest pours, which aims at the
   errors) joins, while that net gain is at least `min_gain` and the
   expectation has fewer than `max_rules` rules. It joins only if its
   confidence (the pours sampled for it) is on its pours' side, at least
   `margin` from one half; otherwise it is dropped;
4. then each proposition asked alone: where the rules answer otherwise than
   its confidence, and the pours it describes agree with that confidence,
   its own rule joins, if it sets no more pours wrong than right (the
   budget `max_rules` still holds).

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

from pantarhei.oracle.generative import InvalidAntecedent, holds, normalise, sample
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.measures import FAILS, HOLDS, UNKNOWN, verdicts
from pantarhei.bridge.theories.model import Rule, Theory


@dataclass(frozen=True)
class Settings:
    max_rules: int = 12        # per expectation, the default included
    max_body: int = 3          # propositions in a body
    min_support: int = 10      # pours a body must describe
    margin: float = 0.1        # |confidence - 1/2| at least
    min_gain: int = 3          # pours a new rule must set right, net
    samples: int = 64          # drawn per body to estimate its confidence
    seed: int = 1
    #: "prior": a body's confidence is P(e | B) for the pours sampled for B
    #: (the model of the pours over P(.|B)); "pours": the share of the
    #: explored pours B describes (what those pours saw, unweighted).
    meaning: str = "prior"
    #: each proposition of a body costs this share of the pours in the
    #: gain: of two bodies setting nearly as many pours right, the shorter
    #: one, which more questions ask, joins
    penalty: float = 0.01
    #: uniformly random valid antecedents on which the model of the pours
    #: judges a default the priors leave open (`meaning` "prior" only)
    judges: int = 300

    def __post_init__(self) -> None:
        if self.max_rules < 1 or not 0 <= self.max_body <= 3:
            raise ValueError("max_rules must be at least 1 and max_body 0 to 3")
        if not 0 <= self.margin < 0.5 or self.min_support < 1 or self.samples < 1:
            raise ValueError("margin in [0, 1/2), min_support and samples at least 1")
        if self.judges < 0:
            raise ValueError("judges must be at least 0")
        if self.meaning not in ("prior", "pours"):
            raise ValueError(f"meaning is prior or pours, not {self.meaning!r}")


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

    def of(self, expectation: str) -> list[GeneralRule]:
        return [r for r in self.rules if r.expectation == expectation]

    def decide(self, scene: Iterable[str]) -> dict[str, tuple[int, str | None]]:
        """Per expectation: HOLDS, FAILS or UNKNOWN, and the deciding rule's id."""
        s = set(scene)
        out: dict[str, tuple[int, str | None]] = {}
        for e in load_vocabulary().expectation_names:
            rules = self.of(e)
            j = deciding(rules, s)
            out[e] = ((UNKNOWN, None) if j is None
                      else (HOLDS if rules[j].holds else FAILS, rules[j].id))
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
        """len(bodies) x 9: the estimated P(e | B); NaN where B cannot be sampled."""
        n = self.settings.samples
        out = np.full((len(bodies), len(self.models)), np.nan)
        rows, ok = [], []
        for i, b in enumerate(bodies):
            try:
                rows.append(sample(list(b), n, _seed(self.settings.seed, b)))
                ok.append(i)
            except InvalidAntecedent:
                continue
        if not rows:
            return out
        p = self.shares(normalise(np.vstack(rows)))
        for k in range(len(self.models)):
            out[ok, k] = p[:, k].reshape(len(ok), n).mean(axis=1)
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


def _generalize(P: np.ndarray, S: np.ndarray, settings: Settings) -> General:
    vocab = load_vocabulary()
    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    ok = np.all(np.isfinite(S), axis=1)
    P, S = P[ok], S[ok]
    if not len(P):
        raise ValueError("no pours to generalize from")
    Y = verdicts(S)
    names, D = holds(P)
    meaning = _Cache(Meaning(P, Y, settings) if settings.meaning == "prior"
                     else _Described(names, D, Y))
    bodies = _candidates(names, D, settings)
    A = _matrix(names, D, bodies)
    judge = _Judge(meaning, settings) if settings.meaning == "prior" and settings.judges else None
    out = General()
    for k, e in enumerate(vocab.expectation_names):
        def learn(default: bool, c0: float) -> list[GeneralRule]:
            return _learn(e, k, names, D, Y[:, k], bodies, A, meaning, settings, default, c0)

        c0, kept = float(meaning([()])[0, k]), float(Y[:, k].mean())
        if np.isfinite(c0) and abs(c0 - 0.5) >= settings.margin:
            rules = learn(c0 >= 0.5, c0)
        elif judge is None:
            # the priors leave it open: the default follows the pours
            rules = learn(kept >= 0.5, kept)
        else:
            rules = judge.better(k, learn(kept >= 0.5, kept), learn(kept < 0.5, kept))
        out.rules.extend(rules)
        out.sup.extend(_superiority(rules))
    return out


class _Judge:
    """Which of two decision lists (with opposite defaults) the model of the
    pours finds right more often, on uniformly random valid antecedents."""

    def __init__(self, meaning: "_Cache", s: Settings):
        from pantarhei.bridge.reasoning.scenes import random_antecedents

        # a seed of their own: not the held-out scenes of an evaluation
        self.scenes = [tuple(sorted(a)) for a in
                       random_antecedents(_seed(s.seed, ("judges",)), s.judges)]
        self.meaning = meaning

    def better(self, k: int, first: list[GeneralRule], second: list[GeneralRule]
               ) -> list[GeneralRule]:
        """The list expected to be right on more of the judging pours (the
        first on ties), its default's confidence the share it gets right of
        the pours it decides (one half where it decides none)."""
        p = self.meaning(self.scenes)[:, k]
        ok = np.isfinite(p)
        scored = []
        for rules in (first, second):
            holds, decider = _decide(rules, [s for s, o in zip(self.scenes, ok) if o])
            right = np.where(holds, p[ok], 1 - p[ok])
            scored.append((float(right.mean()) if len(right) else 0.0, right[decider == 0]))
        k_best = 0 if scored[0][0] >= scored[1][0] else 1
        rules, mine = (first, second)[k_best], scored[k_best][1]
        confidence = float(mine.mean()) if len(mine) else 0.5
        return [replace(rules[0], confidence=confidence), *rules[1:]]


def _decide(rules: Sequence[GeneralRule], scenes: Sequence[Sequence[str]]
            ) -> tuple[np.ndarray, np.ndarray]:
    """Per scene: whether one expectation's rules (a default among them)
    conclude it holds, and the index of the deciding rule (`deciding`)."""
    decider = np.array([deciding(rules, set(s)) for s in scenes], dtype=int)
    holds = np.array([rules[j].holds for j in decider], dtype=bool)
    return holds, decider


class _Described:
    """P(e | B) as the share of the explored pours B describes."""

    def __init__(self, names, D, Y):
        self.names, self.D, self.Y = names, D, Y

    def __call__(self, bodies: Sequence[tuple[str, ...]]) -> np.ndarray:
        out = np.full((len(bodies), self.Y.shape[1]), np.nan)
        for i, b in enumerate(bodies):
            m = _described(self.names, self.D, b)
            if m.any():
                out[i] = self.Y[m].mean(axis=0)
        return out


class _Cache:
    """The meaning of bodies, each estimated once (in batches)."""

    def __init__(self, meaning: Meaning):
        self.meaning = meaning
        self.known: dict[tuple[str, ...], np.ndarray] = {}

    def __call__(self, bodies: Sequence[tuple[str, ...]]) -> np.ndarray:
        new = [b for b in dict.fromkeys(bodies) if b not in self.known]
        if new:
            self.known.update(zip(new, self.meaning(new)))
        return np.array([self.known[b] for b in bodies]).reshape(len(bodies), -1)


def _described(names: Sequence[str], D: np.ndarray, body: Sequence[str]) -> np.ndarray:
    col = {n: i for i, n in enumerate(names)}
    return D[:, [col[p] for p in body]].all(axis=1) if body else np.ones(len(D), dtype=bool)


def _candidates(names: Sequence[str], D: np.ndarray, s: Settings) -> list[tuple[str, ...]]:
    """The bodies of one and two propositions that are askable and that at
    least min_support pours satisfy, in canonical order."""
    out: list[tuple[str, ...]] = []
    if s.max_body >= 1:
        count = D.sum(axis=0)
        single = [i for i in range(len(names)) if count[i] >= s.min_support]
        out += [(names[i],) for i in sorted(single, key=lambda i: names[i])]
        if s.max_body >= 2:
            Di = D.astype(np.int32)
            pairs = Di.T @ Di
            for a, b in combinations(single, 2):
                if pairs[a, b] >= s.min_support:
                    body = tuple(sorted((names[a], names[b])))
                    if _askable(body):
                        out.append(body)
    return out


def _matrix(names, D, bodies) -> "sparse.csc_matrix":
    """Which pours (rows) each body (column) describes, as a sparse 0/1 matrix."""
    from scipy import sparse

    indices = [np.flatnonzero(_described(names, D, b)) for b in bodies]
    indptr = np.concatenate([[0], np.cumsum([len(i) for i in indices])])
    data = np.ones(int(indptr[-1]), dtype=np.float32)
    flat = np.concatenate(indices) if indices else np.empty(0, dtype=int)
    return sparse.csc_matrix((data, flat, indptr), shape=(len(D), len(bodies)))


class _Pool:
    """Candidate bodies with the pours each describes (a sparse matrix) and
    the verdict most of those pours give."""

    def __init__(self, bodies, A, y, s: Settings):
        n_b = np.asarray(A.sum(axis=0)).ravel()
        k_b = A.T @ y.astype(np.float32)
        rate = np.where(n_b > 0, k_b / np.maximum(n_b, 1), 0.5)
        keep = np.flatnonzero((n_b >= s.min_support) & (np.abs(rate - 0.5) >= s.margin))
        self.bodies = [bodies[i] for i in keep]
        self.A = A[:, keep]
        self.holds = rate[keep] >= 0.5
        self.size = np.array([len(b) for b in self.bodies], dtype=float)
        self.support = n_b[keep]
        self.alive = np.ones(len(self.bodies), dtype=bool)

    def add(self, names, D, y, bodies, s: Settings) -> None:
        from scipy import sparse

        have = set(self.bodies)
        bodies = [b for b in bodies if b not in have]
        more = _Pool(bodies, _matrix(names, D, bodies), y, s)
        self.bodies += more.bodies
        self.A = sparse.hstack([self.A, more.A]).tocsc()
        self.holds = np.concatenate([self.holds, more.holds])
        self.size = np.concatenate([self.size, more.size])
        self.support = np.concatenate([self.support, more.support])
        self.alive = np.concatenate([self.alive, more.alive])

    def gains(self, y, pred, decider, levels) -> np.ndarray:
        """Per candidate: pours set right minus pours set wrong if it joined
        (ranked by its size: it beats the rules of smaller bodies)."""
        right_now = (pred == y).astype(np.float32)
        g = np.zeros(len(self.bodies))
        AT = self.A.T.tocsr()
        for j, lv in enumerate(levels):
            on = decider == j
            if not on.any():
                continue
            beats = self.size > lv
            for h in (True, False):
                v = np.where(on, (y == h).astype(np.float32) - right_now, 0.0)
                sel = beats & (self.holds == h)
                if sel.any():
                    g[sel] += (AT @ v)[sel]
        return np.where(self.alive, g, -np.inf)


def _learn(e: str, k: int, names, D, y, bodies, A, meaning: _Cache, s: Settings,
           default_holds: bool, c0: float) -> list[GeneralRule]:
    """The decision list of one expectation under the default given (c0:
    the estimated share of pours that keep the expectation)."""
    n = len(y)
    chosen: list[GeneralRule] = [GeneralRule(
        f"g0_{e}", (), e, default_holds, n, int((y == default_holds).sum()),
        float(c0 if default_holds else 1 - c0), 0)]
    pred = np.full(n, default_holds)
    decider = np.zeros(n, dtype=int)
    pool = _Pool(bodies, A, y, s)
    while len(chosen) < s.max_rules and pool.alive.any():
        g = pool.gains(y, pred, decider, [len(r.body) + abs(r.confidence - 0.5) for r in chosen])
        g = g - s.penalty * n * pool.size
        # the most pours set right; among equals the narrowest body, which
        # aims at the errors rather than at pours already right
        order = [i for i in np.lexsort((pool.support, -g))[:16] if g[i] >= s.min_gain]
        if not order:
            break
        conf = meaning([pool.bodies[i] for i in order])[:, k]
        taken = None
        for i, c in zip(order, conf):
            # the pours the body describes and the pours sampled for it must agree
            if np.isfinite(c) and (c >= 0.5) == pool.holds[i] and abs(c - 0.5) >= s.margin:
                taken = (i, float(c))
                break
            pool.alive[i] = False
        if taken is None:
            continue
        i, c = taken
        pool.alive[i] = False
        body, r_holds = pool.bodies[i], bool(pool.holds[i])
        m = _described(names, D, body)
        rule = GeneralRule(f"g{len(chosen)}_{e}", body, e, r_holds, int(m.sum()),
                           int((y[m] == r_holds).sum()), c if r_holds else 1 - c,
                           _level(body, r_holds, chosen))
        chosen.append(rule)
        for p in np.flatnonzero(m):
            if rule.rank > chosen[decider[p]].rank:
                decider[p], pred[p] = len(chosen) - 1, r_holds
        if len(body) == 2 and s.max_body >= 3:
            pool.add(names, D, y, _extensions(body, names, D, s), s)
    _ask_alone(e, k, names, D, y, pool, chosen, pred, decider, meaning, s)
    return chosen


def _ask_alone(e, k, names, D, y, pool: _Pool, chosen: list[GeneralRule], pred, decider,
               meaning: _Cache, s: Settings) -> None:
    """One proposition asked alone must get the answer of the pours sampled
    for it: where the rules so far answer otherwise, and the pours it
    describes agree with its confidence, its own rule joins (if it sets no
    more pours wrong than right)."""
    singles = [i for i, b in enumerate(pool.bodies) if len(b) == 1 and pool.alive[i]]
    if not singles or len(chosen) >= s.max_rules:
        return
    conf = meaning([pool.bodies[i] for i in singles])[:, k]
    order = sorted(range(len(singles)), key=lambda j: (-abs(conf[j] - 0.5), pool.bodies[singles[j]]))
    for j in order:
        i, c = singles[j], float(conf[j])
        if len(chosen) >= s.max_rules:
            break
        if not np.isfinite(c) or abs(c - 0.5) < s.margin or (c >= 0.5) != pool.holds[i]:
            continue
        body, r_holds = pool.bodies[i], bool(pool.holds[i])
        said = max((r for r in chosen if set(r.body) <= set(body)), key=lambda r: r.rank)
        if said.holds == r_holds:
            continue
        rule = GeneralRule(f"g{len(chosen)}_{e}", body, e, r_holds, int(pool.support[i]), 0,
                           c if r_holds else 1 - c, _level(body, r_holds, chosen))
        m = _described(names, D, body)
        wins = np.array([rule.rank > chosen[d].rank for d in decider[m]], dtype=bool)
        idx = np.flatnonzero(m)[wins]
        if (y[idx] == r_holds).sum() < (y[idx] == pred[idx]).sum():
            continue
        rule = GeneralRule(rule.id, body, e, r_holds, rule.support, int((y[m] == r_holds).sum()),
                           rule.confidence, rule.level)
        chosen.append(rule)
        pred[idx], decider[idx] = r_holds, len(chosen) - 1


def _extensions(body, names, D, s: Settings) -> list[tuple[str, ...]]:
    """The askable bodies of three propositions that extend `body`
    (candidates for exceptions to an exception)."""
    m = _described(names, D, body)
    count = D[m].sum(axis=0)
    have = set(body)
    out = []
    for i in np.flatnonzero(count >= s.min_support):
        b = tuple(sorted(have | {names[i]}))
        if len(b) == 3 and _askable(b):
            out.append(b)
    return out


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
