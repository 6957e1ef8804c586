"""What a plan's verifying pours teach the theory.

A plan the simulation refutes is evidence: its pours say what happens in
its scene. The theory learns from them with the learner the exploration
recorded in the theory (setting(learner, Name); bridge/learning/learners.py's
default for a theory that records none, through its interface): for
each plan tried (its antecedent: the given context and the manners
chosen) the learner models every pour drawn for it (likelihoods pooled
over them), and its answer for the antecedent becomes, per expectation, a
rule with that antecedent as its body, and its provenance: the layer
(plans), the support and kept pours, the confidence in permille. A planned rule
beats a conflicting rule of the theory whose body its own holds (the
same body included: it rests on pours of that very scene), and loses to
one whose body holds a proposition its own does not (that rule speaks of
what the plan's pours left to the ordinary pour); between planned rules,
the larger body wins, then the later id. Every such pair is an explicit
sup/2 fact (planned rules are not marked learned, so the engines derive
no specificity for them), and a pair that would close a cycle with the
theory's own superiority is left out.
Each plan's rules are learned once; the theory of each round is the
original one with the rules of every plan tried so far, so rules are not
stacked on rules.
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.reasoning.written_theory import AsWritten
from pantarhei.bridge.theories.model import Rule, Theory, complement

#: The layer the planned rules' provenance names.
LAYER = "plans"


def rule_id(k: int, expectation: str) -> str:
    """The id of the planned rule for the k-th antecedent tried."""
    return f"p{k}_{expectation}"


def with_evidence(theory: Theory, pours: Mapping[tuple[str, ...], tuple[np.ndarray, np.ndarray]],
                  seed: int) -> Theory:
    """`theory` with a planned rule per expectation for each antecedent
    tried (`pours`: antecedent to the parameterizations and scores drawn
    for it, in the order tried; failed pours left out)."""
    name = theory_learner(theory)
    return with_rules(theory, [planned_rules(k, body, P, S, seed, name)
                               for k, (body, (P, S)) in enumerate(pours.items())])


def theory_learner(theory: Theory) -> str:
    """The name of the learner `theory` records, the default where it
    records none; UserError for a learner unknown here."""
    from pantarhei.bridge.learning.learners import known_recorded_learner
    from pantarhei.bridge.theories.loading import settings

    return known_recorded_learner(settings(theory), theory.source)


Planned = tuple[list[Rule], list[tuple[str, str, "str | int"]]]


def planned_rules(k: int, body: Sequence[str], P: np.ndarray, S: np.ndarray,
                  seed: int, learner: str | None = None) -> Planned:
    """The planned rules of the k-th antecedent tried, `body`, learned from
    the pours drawn for it (P, S) by the learner named `learner` (None:
    the default), and their provenance; none when no pour finished."""
    from pantarhei.bridge.verdicts import verdicts
    from pantarhei.bridge.learning import learners

    names = load_vocabulary().expectation_names
    P = np.atleast_2d(np.asarray(P, dtype=float))
    S = np.atleast_2d(np.asarray(S, dtype=float))
    done = np.all(np.isfinite(S), axis=1)
    P, S = P[done], S[done]
    rules: list[Rule] = []
    provenance: list[tuple[str, str, str | int]] = []
    if not len(P):
        return rules, provenance
    body = tuple(sorted(body))
    Y = verdicts(S)
    general = learners.learner(learner)(P, S, int(seed), [body])
    for e, (_, like, _) in general.answer(body).items():
        if not np.isfinite(like):
            continue
        holds = like >= 0.5
        rid = rule_id(k, e)
        rules.append(Rule(rid, "defeasible", e if holds else complement(e), body))
        provenance += [(rid, "layer", LAYER), (rid, "support", len(P)),
                       (rid, "kept", int((Y[:, names.index(e)] == holds).sum())),
                       (rid, "confidence_permille",
                        int(round(1000 * (like if holds else 1 - like))))]
    return rules, provenance


def with_rules(theory: Theory, planned: Sequence[Planned]) -> Theory:
    """`theory` with the planned rules and their provenance, and the
    sup/2 pairs that order them (the theory itself for none)."""
    new = [r for rules, _ in planned for r in rules]
    if not new:
        return theory
    provenance = [x for _, prov in planned for x in prov]
    out = Theory(list(theory.facts), list(theory.rules) + new, list(theory.sup),
                 set(theory.learned), list(theory.extra), theory.source,
                 {k: list(v) for k, v in theory.settings.items()},
                 list(theory.provenance) + provenance)
    out.sup += _acyclic(out, _sup(theory, new), {r.id for r in new})
    if isinstance(theory, AsWritten):   # SWI-Prolog reads its files, then what was added
        return theory.extended(out)
    return out


def _acyclic(theory: Theory, pairs: list[tuple[str, str]], planned: set[str]
             ) -> list[tuple[str, str]]:
    """`pairs` without those that would close a superiority cycle with the
    theory's own (sup/2 and specificity): on each cycle found, the pair in
    which a planned rule loses is dropped first, else one it wins (the
    conflict is then left undecided, and no goal rests on it)."""
    from pantarhei.bridge.theories.model import superiority_cycle

    pairs = list(pairs)
    while True:
        trial = Theory(theory.facts, theory.rules, theory.sup + pairs, theory.learned)
        cycle = superiority_cycle(trial.sup, trial._specific_successors())
        if not cycle:
            return pairs
        steps = [p for p in zip(cycle, cycle[1:]) if p in pairs]
        losing = [p for p in steps if p[1] in planned]
        pairs.remove((losing or steps)[0])


def _sup(theory: Theory, new: Sequence[Rule]) -> list[tuple[str, str]]:
    """sup/2 pairs for the planned rules `new` against every conflicting
    rule of the theory and against each other (see the module's text)."""
    from pantarhei.bridge.learning.askable import together

    out = []
    for r in new:
        for q in theory.rules:
            if q.head != complement(r.head):
                continue
            rb, qb = set(r.body), set(q.body)
            if qb <= rb:
                out.append((r.id, q.id))
            elif together(r.body, q.body):
                out.append((q.id, r.id))
    for i, r in enumerate(new):
        for q in new[i + 1:]:
            rb, qb = set(r.body), set(q.body)
            if q.head != complement(r.head) or not together(r.body, q.body):
                continue
            hi, lo = (r, q) if (len(rb), r.id) > (len(qb), q.id) else (q, r)
            out.append((hi.id, lo.id))
    return out
