"""Novelty: how likely a candidate antecedent is to show a behaviour the
exploration has not yet got, before any of its pours is simulated.

The discovering curiosity ranks its candidates (A_new and the new ones of
each step) by this estimate and queues only those that reach a level.

For a candidate antecedent c, its pours are drawn from P(p|c) as its
simulations would be (the same sampler, with a seed of its own), and a
random forest of every pour so far (the nine verdicts against the
normalised parameters) predicts them: q_e, the predicted share of c's pours
in which expectation e holds. Taking q_e as the chance that c's verdict on
e holds, the chance that c's consequent is one an explored antecedent
already has is the sum over those consequents K of prod_e P(verdict_e =
K_e). This is optimistic where the pours are mixed (q_e near one half, the
verdict could go either way): it draws the exploration to where the
behaviour changes, which found more behaviours than taking the verdict of
the larger share as certain (python -m benchmarks discovery). The
estimate is 0.8 times the chance that it is none of them, plus 0.2 times
the share of c's predicted pours whose nine verdicts no two pours so far
have shown. So it is near 0 where the forest expects nothing new, and near
1 where it surely expects a new rule whose pours all show new behaviour.

The forest's guess is checked before a batch is spent on it: a probe, the
first pours of the candidate's batch, is simulated, and `probe_score` says
how likely a batch of the candidate is to give a consequent no explored
antecedent has and that another batch would give again (the candidate is
set aside below PASS; theory/curiosity/probe.pl, choose/6). A candidate is
queued when its estimate reaches the novelty level.
"""
from __future__ import annotations

import zlib
from collections import Counter
from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable, Sequence

import numpy as np
from scipy.stats import binom
from sklearn.ensemble import RandomForestClassifier

from pantarhei.bridge.exploration.significance import shuffle_seed
from pantarhei.bridge.exploration.trace import rounded
from pantarhei.bridge.verdicts import verdicts
from pantarhei.oracle.generative import normalise, sample
from pantarhei.theory import defaults

if TYPE_CHECKING:
    from pantarhei.bridge.exploration.session import Host

#: Trees of the forest; its leaves hold at least this many pours.
TREES, LEAF = 50, 3
#: The weight of a new consequent in the estimate; the rest is the share of
#: pours with unseen verdicts.
NEW_CONSEQUENT = 0.8
#: The seeded tie-break's share of the estimate (which so stays below 1).
TIE = 1e-6
#: A probe passes when the chance it gives of a new, reproducible consequent
#: is at least this (theory/defaults.pl's probe_pass).
PASS = float(defaults()["probe_pass"])


@dataclass(frozen=True)
class Known:
    """What the exploration knows when it ranks candidates."""
    forest: RandomForestClassifier | None
    columns: np.ndarray         # (9,) verdict of a constant column (-1: the forest predicts it)
    seen: frozenset             # nine-verdict vectors shown by at least two pours
    consequents: frozenset      # consequents (nine verdicts) of the explored antecedents
    samples: int                # pours per batch
    seed: int                   # the run's seed (of the candidates' predicted pours)


def shown(S: np.ndarray, at_least: int = 2) -> frozenset:
    """The behaviours seen: the distinct nine-verdict vectors (score above
    1/2) among the pours whose simulation did not fail, each shown by at
    least `at_least` pours."""
    S = np.asarray(S, dtype=float)
    S = S[np.all(np.isfinite(S), axis=1)]
    counts = Counter(tuple(bool(v) for v in row) for row in verdicts(S))
    return frozenset(k for k, c in counts.items() if c >= at_least)


def known(params: np.ndarray, scores: np.ndarray, consequents: Sequence[tuple[bool, ...]],
          samples: int, seed: int, forest_seed: int) -> Known:
    """Fit the forest (seeded by `forest_seed`) on the valid pours (params in
    theory units, scores (n, 9)) and gather the behaviours seen and the
    explored antecedents' consequents."""
    ok = np.all(np.isfinite(scores), axis=1)
    P, V = params[ok], verdicts(scores[ok])
    seen = shown(scores)
    columns = np.full(V.shape[1], -1)
    forest = None
    if len(P):
        constant = np.all(V == V[:1], axis=0)
        columns = np.where(constant, V[0].astype(int), -1)
        if not constant.all():
            forest = RandomForestClassifier(n_estimators=TREES, min_samples_leaf=LEAF, max_features=None,
                                            random_state=forest_seed % 2**32, n_jobs=1)
            forest.fit(normalise(P), V[:, ~constant])
    return Known(forest, columns, seen, frozenset(consequents), samples, seed)


def candidate_seed(seed: int, props: Sequence[str]) -> int:
    """The seed of a candidate's predicted pours: the run's seed and its
    propositions, so a candidate is always judged on the same pours."""
    key = zlib.crc32(",".join(sorted(props)).encode())
    return int(np.random.SeedSequence([int(seed), key]).generate_state(1)[0])


def predicted(k: Known, P: np.ndarray) -> np.ndarray:
    """(m, 9) predicted probability that each expectation holds for pours P."""
    out = np.tile(k.columns.astype(float), (len(P), 1))
    if k.forest is not None:
        proba = k.forest.predict_proba(normalise(P))
        classes = k.forest.classes_
        if not isinstance(proba, list):          # one free column: not multi-output
            proba, classes = [proba], [classes]
        for col, pr, cl in zip(np.flatnonzero(k.columns < 0), proba, classes):
            cl = list(cl)
            out[:, col] = pr[:, cl.index(True)] if True in cl else 0.0
    return out


def novelties(k: Known, candidates: Sequence[Sequence[str]]) -> list[dict]:
    """The estimate for each candidate antecedent, with its parts (the chance
    that its consequent is new, the share of predicted pours with unseen
    verdicts). A seeded tie-break of a millionth orders equal
    estimates without favouring the vocabulary's order; the estimate stays
    below 1, so the level 1 queues nothing."""
    if not candidates:
        return []
    seeds = [candidate_seed(k.seed, props) for props in candidates]
    P = np.vstack([sample(list(props), k.samples, seed)
                   for props, seed in zip(candidates, seeds)])
    p = predicted(k, P).reshape(len(candidates), k.samples, -1)
    known_c = verdict_rows(k.consequents, p.shape[2])
    out = []
    for i in range(len(candidates)):
        q = p[i].mean(axis=0)                    # predicted share of pours that hold
        same = float(np.prod(np.where(known_c, q, 1.0 - q), axis=1).sum())
        new = max(0.0, 1.0 - same)
        unseen = float(np.mean([tuple(bool(v) for v in row) not in k.seen
                                for row in p[i] > 0.5]))
        tie = np.random.default_rng(seeds[i]).random() * TIE
        estimate = NEW_CONSEQUENT * new + (1.0 - NEW_CONSEQUENT) * unseen
        out.append({"novelty": estimate * (1.0 - TIE) + tie, "new_consequent": new,
                    "unseen": unseen})
    return out


def verdict_rows(consequents: Iterable[tuple[bool, ...]], width: int) -> np.ndarray:
    """Consequents as a (k, width) boolean array, sorted (none: 0 rows)."""
    return np.array(sorted(consequents), dtype=bool).reshape(-1, width)


def majority(q: np.ndarray, n: int) -> np.ndarray:
    """The chance that the larger share of n pours holds, when each holds
    with chance q (a tie, for even n, counts half)."""
    q = np.clip(np.asarray(q, dtype=float), 0.0, 1.0)
    return binom.sf(n // 2, n, q) + (0.0 if n % 2 else 0.5 * binom.pmf(n // 2, n, q))


def new_reproduced(q: np.ndarray, n: int, consequents: np.ndarray) -> float:
    """The chance that two batches of n pours, in which the expectations
    hold with the chances q, give the same consequent and that it is none of
    `consequents` (rows of nine verdicts): a behaviour found, not a toss."""
    r = majority(q, n)
    agree = float(np.prod(r * r + (1.0 - r) * (1.0 - r)))
    same = float(np.prod(np.where(consequents, r * r, (1.0 - r) * (1.0 - r)), axis=1).sum())
    return max(0.0, agree - same)


def probe_score(S: np.ndarray, n: int, consequents: Sequence[tuple[bool, ...]]) -> float:
    """What a probe says of its candidate: the chance (new_reproduced) that
    a batch of n of its pours gives a consequent none of `consequents` has,
    and that another batch would give it again, with each expectation's
    chance taken from the probe's pours that did not fail ((holds + 1) /
    (pours + 2): a probe of a few pours is not read as certain). A split
    probe scores at most about one half, a probe that shows an explored
    antecedent's consequent about 0."""
    S = np.asarray(S, dtype=float)
    V = verdicts(S[np.all(np.isfinite(S), axis=1)])
    q = (V.sum(axis=0) + 1.0) / (len(V) + 2.0)
    return new_reproduced(q, n, verdict_rows(consequents, S.shape[1]))


def handlers() -> dict:
    """The discovering curiosity's foreign predicates
    (bridge/exploration/curiosity_sides.py): by name, the timing they count
    towards and the handler."""
    return {"exploration_predict": ("planes", predict),
            "exploration_probe": ("probe", probe)}


def probe(host: Host, request: dict) -> dict:
    """Simulate the first `probe` pours of a candidate's batch and say
    whether they show a new, reproducible consequent (probe_score against
    the explored antecedents' consequents, qualified by `qualify`, at
    least PASS)."""
    s = host.need_session()
    samples = int(request["batch"])
    _, S = host.batch(request, min(int(request["probe"]), samples))
    # rounded as the trace keeps it, so that a resumed run and another
    # machine read the same score from it
    score = rounded(probe_score(S, samples, s.verdicts(request["antecedents"],
                                                       str(request["qualify"]))))
    passed = score >= PASS
    return {"score": score, "pass": passed, "simulations": len(s.params)}


def predict(host: Host, request: dict) -> dict:
    """The novelty of each candidate antecedent given every pour so far and
    the consequents of the explored antecedents (qualified by `qualify`),
    and whether it reaches the level `novelty` to be queued; the forest is
    seeded from `seed` and predicts `batch` pours per candidate."""
    s = host.need_session()
    entries = request["antecedents"]
    seed, batch, mode = int(request["seed"]), int(request["batch"]), str(request["qualify"])
    key = (len(s.params), len(entries), seed, batch, mode)
    # what the last estimate knew, kept while what it was computed from is the same
    k = s.kept("known", key, lambda: known(s.params, s.scores, s.verdicts(entries, mode), batch,
                                          seed, shuffle_seed(seed, 0, len(s.params))))
    level = float(request["novelty"])
    found = novelties(k, [[str(p) for p in props] for props in request["candidates"]])
    return {"novelty": [f["novelty"] for f in found],
            "queued": [f["novelty"] >= level for f in found]}
