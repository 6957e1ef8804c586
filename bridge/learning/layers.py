"""One theory of two layers: Algorithm 1's rules and the general rules.

Algorithm 1 writes one rule per explored antecedent and expectation (its
body is the antecedent, `r<i>_<E>`); a learner (learners.py; the run's
`learner` setting, by default generalize.py) learns general rules from every pour of the exploration
(`g<i>_<E>`). Both are learned rules, and a
scene that both speak of is decided as within one layer: the most specific
applicable rule wins (a body that holds another's), and between rules whose
bodies do not hold each other, the higher ranked one: the larger body, then
the general layer's (estimated from every pour, where Algorithm 1's rule
rests on the weighted pours of its antecedent: the two layers' rules for
the empty body, when the priors were explored, say the same thing, and
the general one says it better), then the surer verdict (confidence
further from one half), then the id. The
engines derive specificity among learned rules themselves; every other pair
of conflicting rules that one scene can hold together gets an explicit
`sup/2` fact in rank order. The order is linear, so the superiority
relation is acyclic and no conflict is left undecided.

`general_layer` gives the general layer to explore/1, which writes it into
the theory file beside Algorithm 1's rules (theory/curiosity/writer.pl);
both engines read that file.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import AbstractSet, Sequence

import numpy as np

from pantarhei.bridge.learning.askable import together
from pantarhei.bridge.learning.general_rules import General, confidence, rank
from pantarhei.bridge.learning import learners
from pantarhei.bridge.theories.model import Theory, complement


@dataclass(frozen=True)
class Ranked:
    """A learned rule as the layers rank it."""
    id: str
    body: tuple[str, ...]
    head: str
    confidence: float
    general: bool = False

    @property
    def rank(self) -> tuple:
        return rank(len(self.body), self.general, self.confidence, self.id)


def ranked_rules(theory: Theory, general: General) -> list[Ranked]:
    """Algorithm 1's learned rules of `theory` (confidence from their
    provenance) and the general rules, as one list."""
    conf = {rid: confidence(c) for rid, c in theory.confidences().items()}
    return with_general([Ranked(r.id, tuple(sorted(r.body)), r.head, conf.get(r.id, 0.5))
                         for r in theory.rules if r.id in theory.learned], general)


def with_general(learned: Sequence[Ranked], general: General) -> list[Ranked]:
    """Algorithm 1's rules `learned` and the general rules, as one list."""
    return [*learned, *(Ranked(g.id, tuple(sorted(g.body)), g.head, g.confidence, True)
                        for g in general.rules)]


def superiority(rules: Sequence[Ranked]) -> list[tuple[str, str]]:
    """Explicit sup/2 pairs (higher, lower) for every pair of conflicting
    rules that one scene can hold, where neither body holds the other
    strictly (the engines derive those by specificity)."""
    by_head: dict[str, list[Ranked]] = {}
    for r in rules:
        by_head.setdefault(r.head, []).append(r)
    out = []
    for head in sorted(h for h in by_head if not h.startswith("neg(")):
        for r in by_head[head]:
            for q in by_head.get(complement(head), ()):
                rb, qb = set(r.body), set(q.body)
                if rb < qb or qb < rb or not together(r.body, q.body):
                    continue
                hi, lo = (r, q) if r.rank > q.rank else (q, r)
                out.append((hi.id, lo.id))
    return sorted(out)


def learn_general(P: np.ndarray, S: np.ndarray, seed: int, simulate=None,
                  per_body: int | None = None,
                  bodies: Sequence[Sequence[str]] | None = None,
                  learner: str | None = None
                  ) -> tuple[General, np.ndarray, np.ndarray]:
    """The general rules of the pours (P, S) by the learner named
    `learner` (learners.py; None: the option table's default), after simulating (with `simulate`:
    parameterizations to scores) the pours the learner asks for where the
    exploration left it none (bridge/learning/gaps.py); the pours it
    learned from are returned beside the rules. The rules' bodies are
    among `bodies` (and the empty one) when given, else among the askable
    ones."""
    from pantarhei.bridge.learning.gaps import gap_pours
    from pantarhei.theory import defaults

    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    if simulate is not None:
        n = int(defaults()["pours_per_proposition"] if per_body is None else per_body)
        extra = gap_pours(P, n, seed)
        if len(extra):
            P = np.vstack([P, extra])
            S = np.vstack([S, np.asarray(simulate(extra), dtype=float)])
    return learners.learner(learner)(P, S, int(seed), bodies), P, S


def general_layer(learned: Sequence[Ranked], P: np.ndarray, S: np.ndarray, seed: int,
                  simulate=None, explored: Sequence[tuple[str, Sequence[str]]] | None = None,
                  learner: str | None = None, ruleless: AbstractSet[str] = frozenset()) -> dict:
    """The general layer of an exploration's pours (P, S) and the
    learner's own (simulated with `simulate`), as explore/1 writes it
    beside Algorithm 1's rules `learned`: the pours it learned from (those
    with finite scores; `own_pours`, the learner's), each rule with its
    provenance (confidence in permille: P(head | body)), and the sup/2
    pairs that make both layers one linear order. With `explored` (id,
    antecedent) pairs, the learning curiosity's: the rules' bodies are the
    explored antecedents (and the empty one), each rule names the
    antecedent whose body it has, and no pour is the learner's own; the
    explored antecedents whose ids are in `ruleless` are no rule's body
    (their pours teach the others, and are cited as explored). The
    rules are learned by the learner named `learner` (the run's setting;
    None: the option table's default)."""
    n0 = len(np.atleast_2d(P))
    among = None if explored is None else [tuple(sorted(b)) for a, b in explored
                                           if str(a) not in ruleless]
    general, P, S = learn_general(P, S, seed, simulate if explored is None else None,
                                  bodies=among, learner=learner)
    ids = {tuple(sorted(b)): str(a) for a, b in reversed(list(explored or []))
           if str(a) not in ruleless}
    rules = []
    for g in general.rules:
        rule = {"id": g.id, "expectation": g.expectation, "holds": g.holds,
                "body": list(g.body), "level": g.level, "support": g.support,
                "kept": g.kept, "confidence_permille": int(round(1000 * g.confidence))}
        if tuple(sorted(g.body)) in ids:
            rule["antecedent"] = ids[tuple(sorted(g.body))]
        if g.doubt:
            rule["doubt"] = g.doubt
        if g.beside:
            rule["beside"] = sorted(g.beside)
        rules.append(rule)
    return {"pours": int(np.all(np.isfinite(np.atleast_2d(S)), axis=1).sum()),
            "own_pours": len(P) - n0,
            "rules": rules,
            "sup": [[a, b] for a, b in superiority(with_general(learned, general))],
            "explored": explored_pours(explored or [], P, S)}


def explored_pours(explored: Sequence[tuple[str, Sequence[str]]], P: np.ndarray,
                   S: np.ndarray) -> list[dict]:
    """For each explored antecedent (id, propositions), its propositions
    and, per expectation, the pours (P, S) that could have been drawn for
    it (as a rule's support counts them: the antecedent as asked,
    everything else an ordinary pour) and how many of them hold the
    expectation: what an answer cites for an antecedent explored that has
    no rule of its own. Pours with a failed simulation are left out."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.learning.meaning import held_in_support
    from pantarhei.theory.lexicon import load_vocabulary

    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    ok = np.all(np.isfinite(S), axis=1)
    P, Y = P[ok], verdicts(S[ok])
    names = load_vocabulary().expectation_names
    out = []
    for a, body in explored:
        held, n = held_in_support(P, Y, body)
        out.append({"id": str(a), "body": sorted(str(b) for b in body),
                    "held": [[e, int(h), n] for e, h in zip(names, held)]})
    return out
