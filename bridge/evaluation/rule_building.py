"""Algorithm 1's rule building, applied to any pours: the consequent of
each antecedent from equation (1)'s weights, the theory of one rule per
antecedent and expectation, and what such a theory predicts in scenes (by
SWI-Prolog). The evaluation uses it for curiosity's antecedents and for the
random-exploration baseline alike."""
from __future__ import annotations

from typing import Sequence

import numpy as np

from pantarhei.bridge.engines.swipl import engine, text as prolog_text
from pantarhei.bridge.verdicts import FAILS, HOLDS, UNKNOWN
from pantarhei.bridge.exploration.qualify import consequent
from pantarhei.bridge.exploration.weights import log_densities, weights
from pantarhei.bridge.reasoning import logic
from pantarhei.bridge.theories.model import Rule, Theory
from pantarhei.theory.lexicon import load_vocabulary


def consequents(antecedents: Sequence[Sequence[str]], P: np.ndarray, S: np.ndarray,
                mode: str = "weighted") -> np.ndarray:
    """The consequent (verdict per expectation) of each antecedent, from
    all simulations (P, S) weighted by equation (1) over these antecedents,
    as Algorithm 1's last loop builds them."""
    ok = np.all(np.isfinite(S), axis=1)
    W = weights(log_densities(P[ok], [list(a) for a in antecedents]))
    return np.array([[o["holds"] for o in consequent(S[ok], W[i], mode)["outcomes"]]
                     for i in range(len(antecedents))], dtype=bool).reshape(len(antecedents), -1)


def rule_ids(count: int) -> list[list[str]]:
    """The ids of Algorithm 1's rules for the explored antecedents 1 to
    `count`, per antecedent one for each expectation in the vocabulary's
    order, as explore/1 names them (learned_rules:rule_id/3)."""
    if count < 1:
        return []
    e = engine()
    e.use_module("learned_rules")
    r = e.once("findall(Ids, (between(1, N, I), "
               "findall(Id, (member(E, Es), learned_rules:rule_id(I, E, Id)), Ids)), Rows)",
               N=int(count), Es=load_vocabulary().expectation_names)
    return [[prolog_text(x) for x in row] for row in r["Rows"]]


def theory_of(antecedents: Sequence[Sequence[str]], heads: np.ndarray, source: str) -> Theory:
    """A learned theory: for each antecedent, one defeasible rule per
    expectation, concluding it or its negation."""
    names = load_vocabulary().expectation_names
    t = Theory(source=source)
    ids = rule_ids(len(antecedents))
    for a, row, row_ids in zip(antecedents, heads, ids):
        for e, holds, rid in zip(names, row, row_ids):
            t.rules.append(Rule(rid, "defeasible", e if holds else f"neg({e})", tuple(sorted(a))))
            t.learned.add(rid)
    return t


def predict(theory: Theory, scenes: Sequence[Sequence[str]]) -> np.ndarray:
    """What SWI-Prolog concludes in each scene (scenes x 9): HOLDS, FAILS or
    UNKNOWN (neither, or uncertain), by `queries:what_happens/3`."""
    return answer_matrix(theory, scenes)[0]


def answer_matrix(theory: Theory, scenes: Sequence[Sequence[str]]
                  ) -> tuple[np.ndarray, np.ndarray]:
    """What SWI-Prolog answers in each scene (`queries:what_happens/3`):
    scenes x 9 verdicts (HOLDS, FAILS, or UNKNOWN for an uncertain or
    undecided one), and scenes x 9 likelihoods that the expectation holds
    (NaN where the deciding rule records none)."""
    names = load_vocabulary().expectation_names
    out = np.full((len(scenes), len(names)), UNKNOWN, dtype=int)
    lik = np.full((len(scenes), len(names)), np.nan)
    if not scenes:
        return out, lik
    e = logic.prolog_load(theory)
    e.use_module("queries")
    code = {"holds": HOLDS, "fails": FAILS}
    for i, scene in enumerate(scenes):
        r = e.once("queries:what_happens(Scene, [], Os), "
                   "findall(S, (member(outcome(E, V, P, _), Os), "
                   "format(atom(S), '~w=~w=~w', [E, V, P])), Ss)",
                   Scene=list(scene))
        for triple in r["Ss"]:
            name, value, p = prolog_text(triple).split("=", 2)
            out[i, names.index(name)] = code.get(value, UNKNOWN)
            lik[i, names.index(name)] = np.nan if p == "none" else float(p)
    return out, lik
