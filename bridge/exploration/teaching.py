"""What a batch of pours would teach the theory: the learning curiosity's
choice of the next antecedent (option curiosity(learn),
theory/curiosity/learn.pl).

The learning curiosity explores what questions say: the ordinary pour
first (the empty antecedent), then antecedents of one proposition more
than one explored, up to `body` propositions, each meaning what a question
with the same words means (what it says; the rest the ordinary pour). The
theory it writes has a rule for an explored antecedent where that
antecedent's likelihoods depart from what the rest of the theory answers
(bridge/learning/generalize.py over the explored bodies), so the pours to
simulate next are those that would change the theory most.

For each candidate B, with every pour so far pooled in a model of the
pours (`Meaning`: a gradient-boosted classifier per expectation, averaged
over parameterizations drawn for B), M_e(B) is the model's likelihood of
e for B. B's value is

    asked(B) * (departure(B) + uncertainty * sum_e sd_e(B) * drop(n_B))

departure(B) = sum_e min_A |M_e(B) - M_e(A)| over the antecedents A that B
holds with one proposition less: for a proposition alone, how far its
answers move from the ordinary pour's; for a pair, how far they move from
both of its propositions' (an interaction, which one proposition at a
time cannot show; what one proposition does is learned from it alone).
For an explored antecedent it is 0: its rule gives its answers.

The second term is how much a batch of b more pours would narrow the
standard error of B's likelihoods: with n_B pours in B's support,
sd_e(B) = sqrt(q (1 - q)) for q = (n_B M_e(B) + 1) / (n_B + 2) (the
model's likelihood, drawn to one half where B has few pours of its own:
the model's guess for an antecedent it never saw is no knowledge), and
drop(n) = 1/sqrt(n + 1) - 1/sqrt(n + b + 1), large for an antecedent
without pours and small once it has many. A pair never explored gets
none unless its propositions set parameters of one group (one pose, the
liquid, a bowl, the motion; `suspect`), where physics makes them
interact (height and position together decide where the stream lands, as
neither alone does): the model has no pours of such a pair's region and
cannot see the interaction it may hide, so its guess is no knowledge.
Other pairs are explored for an interaction the model shows or not at
all (their pours would sweep the pairs at random). An explored
antecedent is a candidate for another batch by this term alone.

asked(B) is how often B is asked, as the learner weighs the bodies it
answers (generalize.Settings: the empty antecedent most, a proposition
alone 1, a pair less).

Beside what the theory would learn about B itself, a batch of B is worth
what its very pours would teach the model of every pour, and what they may
show that no pour has shown. The batch B would get if explored next is
known (the pours `batch_pours` samples for B with the next iteration's
seed), so for its pours x the model gives Q_e(x), and

    doubt(B) = mean_x sum_e h(Q_e(x)) * drop(n_B) / drop(0)

where h is the binary entropy in bits: where the model of the pours cannot
tell what happens (as uncertainty sampling chooses pours), less as B's own
pours pile up (what stays uncertain after many pours is noise, not
something to learn: the curiosity leaves it), and

    newness(B) = mean_x (1 - sum_{v seen} prod_e P(verdict_e(x) = v_e))

the chance that a pour of the batch shows a nine-verdict behaviour no two
pours so far have shown (the paper's criterion: behaviours not seen
before), as learning progress (Oudeyer and Kaplan): the model's chance
counts as `model_pours` pours beside B's own, each of which counts 1 if
it showed a behaviour new when it was simulated (`shown_new`), so that a
region whose pours stay unpredictable without showing anything new is
left. For an antecedent of two propositions or more, each counts only
what exceeds the most that one of its parts (B with one proposition less)
gets: the doubt and the new behaviours its interaction brings, not those
of a part whose own pours already show them (a proposition whose pours no
number of them makes predictable would otherwise pass its doubt to every
pair it is in, one after the other: what the curiosity cannot learn, it
leaves). The value adds `doubt` times the first and `newness` times the
second, neither weighed by how often B is asked: what they teach the model
serves every question.

A whole (a uniformly random valid antecedent that learn.pl explores
every `whole_every` steps, named as such in the request) is
said by no question, so no answer a question asks moves with it. Its
value is `newness` times the chance that its consequent is new:

    fresh(W) = 1 - sum_{c had} prod_e P(verdict_e = c_e)

with P(verdict_e = 1) the model's mean of Q_e(x) over the pours of W's
next batch, and c over the consequents the explored antecedents have (the
majority verdicts of the pours in each one's support): a behaviour the
theory does not have yet, as random exploration finds them.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from pantarhei.theory import defaults
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.learning.askable import suspect
from pantarhei.bridge.exploration.pour_support import Support

if TYPE_CHECKING:
    from pantarhei.bridge.exploration.session import Host

#: Parameterizations drawn per candidate pair to average the model over
#: (4 times as many for one proposition, 16 for the empty antecedent), the
#: rounds of boosting of the model of the pours, and the factor by which
#: the pours grow before the model is fitted again (on the first
#: `fitted_on(n)` of n pours, so that a resumed run fits the model an
#: uninterrupted one had): theory/defaults.pl's learn_draws, learn_rounds
#: and learn_refit_growth.
DRAWS, ROUNDS, GROWTH = (int(defaults()["learn_draws"]), int(defaults()["learn_rounds"]),
                         float(defaults()["learn_refit_growth"]))


def fitted_on(n: int) -> int:
    """How many of the first n pours the model is fitted on: the largest of
    8, 8 x GROWTH, 8 x GROWTH^2, ... (rounded up) that is at most n; n
    below 8."""
    m, k = 8, 8.0
    if n < m:
        return n
    while True:
        k *= GROWTH
        nxt = int(np.ceil(k))
        if nxt > n:
            return m
        m = nxt


@dataclass(frozen=True)
class Teaching:
    """The value of each candidate, and its parts."""
    value: list[float]
    departure: list[float]
    uncertainty: list[float]
    doubt: list[float]
    newness: list[float]


@dataclass(frozen=True)
class Weights:
    """The weights of a value's parts beside how far B's answer would move:
    its uncertain likelihoods, the model's doubt on its next batch, and the
    new behaviours that batch may show (the options `uncertainty`, `doubt`
    and `newness` of theory/defaults.pl)."""
    uncertainty: float = 1.0
    doubt: float = 0.0
    newness: float = 0.0


def thread_pools():
    """A threadpoolctl ThreadpoolController of the libraries' thread pools,
    the boosting's OpenMP among them (it finds the libraries loaded when
    it is made, so scikit-learn's boosting is loaded first); a caller that
    keeps one saves that search on every call."""
    import sklearn.ensemble  # noqa: F401  (loads the OpenMP runtime the controller must see)
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


def one_thread(threads=None):
    """A context in which the libraries' thread pools use one thread,
    through `threads` (thread_pools()) or a new controller."""
    return (threads or thread_pools()).limit(limits=1)


def model(P: np.ndarray, S: np.ndarray, seed: int, threads=None):
    """The model of the pours the value is estimated with: a Meaning of the
    first `fitted_on(n)` of the n pours (P, S) whose simulation did not
    fail; None when there are none. `threads` as for one_thread."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.bridge.learning.meaning import Meaning

    P, S = _valid(P, S)
    n = fitted_on(len(P))
    if not n:
        return None
    with one_thread(threads):
        return Meaning(P[:n], verdicts(S[:n]), Settings(seed=int(seed), draws=DRAWS), ROUNDS)


def _valid(P: np.ndarray, S: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    ok = np.all(np.isfinite(S), axis=1)
    return P[ok], S[ok]


def teaching(P: np.ndarray, S: np.ndarray, explored: Sequence[Sequence[str]],
             candidates: Sequence[Sequence[str]], weights: Weights, batch: int,
             seed: int, iteration: int = 1, meaning=None,
             wholes: Sequence[Sequence[str]] = (), support: Support | None = None,
             threads=None) -> Teaching:
    """The value of exploring each candidate next, at `iteration`, with a
    batch of `batch` pours, given the pours so far (P, S; failed ones are
    left out) and the explored antecedents; `meaning` is model(P, S,
    seed), and `support` a Support of fewer of these pours, when the
    caller keeps them; `threads` as for one_thread. A candidate among
    `wholes` (of a whole step of learn.pl) is said by no question, so it is
    valued by its newness alone, counted whole."""
    from pantarhei.bridge.learning.generalize import Settings

    if meaning is None:
        meaning = model(P, S, seed, threads)
    P, S = _valid(P, S)
    cands = [tuple(sorted(str(p) for p in c)) for c in candidates]
    done = {tuple(sorted(str(p) for p in e)) for e in explored}
    if not cands:
        return Teaching([], [], [], [], [])
    whole = {tuple(sorted(str(p) for p in w)) for w in wholes} & set(cands)
    plain = [c for c in cands if c not in whole]
    parents = {c: [tuple(q for q in c if q != p) for p in c] for c in plain}
    bodies = list(dict.fromkeys(plain + [a for c in plain for a in parents[c]]))
    index = {b: i for i, b in enumerate(bodies)}
    learner = Settings()
    asked = {0: learner.default_weight, 1: 1.0}
    suspects = {c for c in cands if suspect(c)}
    support = Support(P) if support is None else support.grown(P)
    doubts = news = np.zeros(len(plain))
    with one_thread(threads):
        if meaning is not None:
            M = np.nan_to_num(meaning(bodies), nan=0.5)
        else:                       # every pour failed: nothing is known
            M = np.full((len(bodies), len(load_vocabulary().expectations)), 0.5)
        if (weights.doubt or weights.newness) and plain:
            doubts, news = beyond_parts(meaning, P, S, plain, parents, batch, seed, iteration,
                                        learner.model_pours, support)
        parts = dict(zip(plain, zip(doubts, news)))
        if whole and weights.newness:
            order = sorted(whole)
            fresh = consequent_newness(meaning, P, S, sorted(done), order, batch, seed, iteration,
                                       support)
            parts.update((c, (0.0, x)) for c, x in zip(order, fresh))
    value, dep, unc, doubt_of = [], [], [], []
    for c in cands:
        h, new = parts.get(c, (0.0, 0.0))
        if c in whole:
            for part in (dep, unc, doubt_of):
                part.append(0.0)
            value.append(round(weights.newness * float(new), 6))
            continue
        m = M[index[c]]
        explored = c in done
        if explored or not c:
            departure = 0.0
        else:
            away = np.min(np.abs(m - M[[index[a] for a in parents[c]]]), axis=0)
            departure = float(away.sum())
        n = int(support(c).sum())
        q = (n * m + 1) / (n + 2)
        drop = 1 / np.sqrt(n + 1) - 1 / np.sqrt(n + batch + 1)
        uncertainty = (float(np.sqrt(q * (1 - q)).sum() * drop)
                       if explored or len(c) <= 1 or c in suspects else 0.0)
        doubt = float(h) * drop / (1 - 1 / np.sqrt(batch + 1))
        dep.append(round(departure, 6))
        unc.append(round(uncertainty, 6))
        doubt_of.append(round(doubt, 6))
        value.append(round(asked.get(len(c), learner.pair_weight)
                           * (departure + weights.uncertainty * uncertainty)
                           + weights.doubt * doubt + weights.newness * float(new), 6))
    return Teaching(value, dep, unc, doubt_of, [round(float(parts.get(c, (0.0, 0.0))[1]), 6)
                                                for c in cands])


def beyond_parts(meaning, P: np.ndarray, S: np.ndarray, cands: Sequence[tuple[str, ...]],
                 parents: dict[tuple[str, ...], list[tuple[str, ...]]], batch: int, seed: int,
                 iteration: int, model_pours: float,
                 support: Support | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Per candidate, its batch's doubt (batch_doubt) and newness (as
    realized: shown_new) less the most that one of its parts (`parents`:
    the candidate with one proposition less) gets, at least 0; the empty
    body is no part. `support` is Support(P), when the caller keeps it."""
    parts = {c: [a for a in parents[c] if a] for c in cands}
    bodies = list(dict.fromkeys([*cands, *(a for c in cands for a in parts[c])]))
    index = {b: i for i, b in enumerate(bodies)}
    h, new = batch_doubt(meaning, S, bodies, batch, seed, iteration)
    new = shown_new(new, P, S, bodies, model_pours, support)
    return tuple(np.array([max(0.0, x[index[c]] - max((x[index[a]] for a in parts[c]), default=0.0))
                           for c in cands]) for x in (h, new))


def shown_new(new: np.ndarray, P: np.ndarray, S: np.ndarray,
              bodies: Sequence[tuple[str, ...]], model_pours: float,
              support: Support | None = None) -> np.ndarray:
    """Newness as learning progress: the model's chance that a pour of B's
    next batch shows a new behaviour (`new`), counted as `model_pours`
    pours beside the n_B pours in B's support, of which k_B showed a
    behaviour new when simulated (fewer than two earlier pours had shown
    its nine verdicts): (model_pours * new + k_B) / (model_pours + n_B).
    What B's pours keep failing to show, B is no longer credited with: a
    region whose pours stay unpredictable keeps a high modelled newness
    although its pours show behaviours seen already. `support` is
    Support(P), when the caller keeps it."""
    from pantarhei.bridge.verdicts import verdicts

    if not len(P):
        return new
    _, inverse = np.unique(verdicts(S), axis=0, return_inverse=True)
    inverse = np.asarray(inverse).ravel()
    earlier = np.zeros(inverse.max() + 1, dtype=int)
    fresh = np.zeros((len(P), 1), dtype=int)
    for i, v in enumerate(inverse):
        fresh[i] = earlier[v] < 2
        earlier[v] += 1
    support = Support(P) if support is None else support
    out = np.array(new, dtype=float)
    for j, b in enumerate(bodies):
        m = support(b)
        out[j] = (model_pours * out[j] + fresh[m, 0].sum()) / (model_pours + int(m.sum()))
    return out


def consequent_newness(meaning, P: np.ndarray, S: np.ndarray,
                       explored: Sequence[tuple[str, ...]], wholes: Sequence[tuple[str, ...]],
                       batch: int, seed: int, iteration: int, support: Support) -> np.ndarray:
    """Per whole, the chance that the consequent of the batch it would get
    at `iteration` (each expectation's verdict, as likely as the model's
    mean over the batch's pours) is none of the explored antecedents' (the
    majority verdicts of the pours in each one's support)."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.exploration.simulation import batch_pours
    from pantarhei.oracle.generative import normalise

    if meaning is None or not wholes:
        return np.zeros(len(wholes))
    Y = verdicts(S)
    had = sorted({tuple(2 * Y[m].sum(axis=0) > m.sum()) for m in map(support, explored) if m.any()})
    X = normalise(np.vstack([batch_pours(c, batch, seed, iteration) for c in wholes]))
    Q = np.clip(meaning.shares(X), 1e-9, 1 - 1e-9).reshape(len(wholes), batch, -1).mean(axis=1)
    if not had:
        return np.ones(len(wholes))
    C = np.array(had, dtype=bool)
    logs = np.log(Q) @ C.T.astype(float) + np.log(1 - Q) @ (~C).T.astype(float)
    return np.clip(1 - np.exp(logs).sum(axis=1), 0.0, 1.0)


def batch_doubt(meaning, S: np.ndarray, cands: Sequence[tuple[str, ...]], batch: int,
                seed: int, iteration: int) -> tuple[np.ndarray, np.ndarray]:
    """Per candidate, over the pours of the batch it would get at
    `iteration`: the model's mean entropy in bits, summed over the
    expectations, and the mean chance that a pour shows a behaviour that no
    two pours of S have shown (nine verdicts); both 0 without a model."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.exploration.simulation import batch_pours
    from pantarhei.oracle.generative import normalise

    if meaning is None or not cands:
        return np.zeros(len(cands)), np.zeros(len(cands))
    X = normalise(np.vstack([batch_pours(c, batch, seed, iteration) for c in cands]))
    Q = np.clip(meaning.shares(X), 1e-9, 1 - 1e-9)
    H = -(Q * np.log2(Q) + (1 - Q) * np.log2(1 - Q)).sum(axis=1)
    rows, counts = np.unique(verdicts(S), axis=0, return_counts=True) if len(S) else ([], [])
    seen = np.asarray([r for r, k in zip(rows, counts) if k >= 2], dtype=bool)
    if len(seen):
        # P(pour shows v) for every seen v: prod_e of Q_e or 1 - Q_e
        logs = np.log(Q) @ seen.T.astype(float) + np.log(1 - Q) @ (~seen).T.astype(float)
        new = 1 - np.exp(logs).sum(axis=1)
    else:
        new = np.ones(len(Q))
    per = np.repeat(np.arange(len(cands)), batch)
    return (np.bincount(per, H, len(cands)) / batch,
            np.clip(np.bincount(per, new, len(cands)) / batch, 0.0, 1.0))


def handlers() -> dict:
    """The learning curiosity's foreign predicate
    (bridge/exploration/curiosity_sides.py): by name, the timing it counts
    towards and the handler."""
    return {"exploration_teach": ("planes", teach)}


def teach(host: Host, request: dict) -> dict:
    """The value of each candidate (`teaching`), given every pour so far
    and the explored antecedents: the weights, `batch`, `seed` and the
    `iteration` to explore at as the request says."""
    s = host.need_session()
    seed = int(request["seed"])
    threads = s.kept("threads", None, thread_pools)
    # the model of the pours, kept while the pours it is fitted on and the seed are the same
    meaning = s.kept("teacher", (fitted_on(int(s.valid.sum())), seed),
                     lambda: model(s.params, s.scores, seed, threads))
    weights = Weights(float(request["uncertainty"]), float(request["doubt"]),
                      float(request["newness"]))
    found = teaching(s.params, s.scores, [e["antecedent"] for e in request["antecedents"]],
                     request["candidates"], weights, int(request["batch"]), seed,
                     int(request["iteration"]), meaning, request["wholes"],
                     s.kept("support", None, lambda: Support(s.params[:0])), threads)
    return {"value": found.value}
