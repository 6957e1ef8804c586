"""Answers to questions about pouring: what happens in a scene (one answer
per expectation, with the deciding rule), why or why not, and the deciding
rule in words with its evidence.

A question means what `pantarhei simulate --antecedent Q` samples for it:
whatever it leaves unsaid follows the priors (the ordinary pour). Nothing
is added to it: the general rules (bridge/learning/) answer questions of
any length in that meaning, each with the likelihood that the expectation
holds in such pours."""
from __future__ import annotations

from dataclasses import dataclass

from pantarhei.bridge.engines.swipl import text as prolog_text
from pantarhei.bridge.reasoning.logic import Semantics, prolog_load
from pantarhei.bridge.theories.model import Theory


@dataclass(frozen=True)
class Answer:
    """What the theory says about one expectation in a scene."""
    expectation: str
    value: str          # "holds", "fails", "uncertain" or "unknown"
    likelihood: float | None    # the share of such pours in which it holds
    rule: str           # the deciding rule, "fact", or "none"
    reason: str         # in words


def what_happens(theory: Theory, props: list[str],
                 semantics: Semantics = Semantics()) -> list[Answer]:
    """The prediction for a scene: one Answer per expectation, with reasons
    (for an undecided one, the brief why-not of queries:explain_brief/4)."""
    e = prolog_load(theory)
    e.use_module("queries")
    goal = (f"Sem = {semantics.options()}, queries:what_happens(Scene, Sem, Os), "
            "findall(S, (member(outcome(E, V, P, R), Os), "
            "(V == unknown -> queries:explain_brief(Scene, E, Sem, T) ; T = \"\"), "
            "format(string(S), '~w\\t~w\\t~w\\t~w\\t~s', [E, V, P, R, T])), Ss)")
    r = e.once(goal, Scene=list(props))
    general = {rid for rid, k, v in theory.provenance if k == "layer" and v == "general"}
    out = []
    for line in r["Ss"]:
        exp, value, p, rule, reason = prolog_text(line).split("\t", 4)
        likelihood = None if p == "none" else float(p)
        out.append(Answer(exp, value, likelihood, _general_twin(theory, general, rule), reason))
    return out


def _general_twin(theory: Theory, general: set[str], rule_id: str) -> str:
    """The rule to name for a conclusion: where the deciding rule is one of
    Algorithm 1's and the general layer has a rule with the same body and
    head (the empty body, when the priors were explored), the general one,
    which ranks above it (bridge/learning/layers.py) and whose evidence is
    every pour. `general`: the ids of the general layer's rules."""
    if rule_id in general:
        return rule_id
    try:
        r = theory.rule(rule_id)
    except KeyError:
        return rule_id
    twins = [g.id for g in theory.rules
             if g.id in general and g.head == r.head and set(g.body) == set(r.body)]
    return twins[0] if twins else rule_id


def explain(theory: Theory, props: list[str], literal: str,
            semantics: Semantics = Semantics(), brief: bool = False) -> str:
    """Why (or why not) the theory concludes `literal` in the scene, in
    words, sentences separated by "; ". A why-not names every rule for the
    literal (queries:explain/4), or with `brief` at most three
    (queries:explain_brief/4)."""
    e = prolog_load(theory)
    e.use_module("queries")
    pred = "explain_brief" if brief else "explain"
    r = e.once(f"term_to_atom(L, LText), queries:{pred}(Scene, L, {semantics.options()}, T)",
               Scene=list(props), LText=literal)
    return prolog_text(r["T"])


def rule_words(theory: Theory, rule_id: str) -> str:
    """The deciding rule in words: its body's glosses (or "an ordinary
    pour" for the empty body), the share of such pours in which its
    expectation holds, and its evidence, e.g. "pour from the side: holds
    in 45% of such pours (seen in 27 of 60 such pours; rule g3_no_spill)"."""
    from pantarhei.theory.lexicon import load_vocabulary

    vocab = load_vocabulary()
    try:
        rule = theory.rule(rule_id)
    except KeyError:
        return rule_id
    props = [vocab.propositions[b].gloss if b in vocab.propositions else b for b in rule.body]
    where = ", ".join(props) if props else "an ordinary pour"
    share = likelihood(theory, rule_id)
    said = f": holds in {round(100 * share)}% of such pours" if share is not None else ""
    ev = evidence(theory, rule_id)
    return f"{where}{said} ({ev + '; ' if ev else ''}rule {rule_id})"


def likelihood(theory: Theory, rule_id: str) -> float | None:
    """The share of a learned rule's pours in which its expectation holds
    (from its confidence in its head), None where it records none."""
    conf = [v for rid, k, v in theory.provenance if rid == rule_id and k == "confidence_permille"]
    if not conf:
        return None
    c = int(conf[0]) / 1000
    return 1 - c if theory.rule(rule_id).head.startswith("neg(") else c


def evidence(theory: Theory, rule_id: str) -> str:
    """The pours behind a learned rule, from its provenance facts: "seen in
    41 of 52 such pours" for a general rule (of the pours learned from that
    could have been drawn for its body, how many kept its head), "the weighted pours of a4" for a rule of Algorithm 1; ""
    when the theory records none."""
    facts = {k: v for rid, k, v in theory.provenance if rid == rule_id}
    if "support" in facts and "kept" in facts:
        if not int(facts["support"]):
            return "no such pour simulated: estimated from the pours nearby"
        return f"seen in {facts['kept']} of {facts['support']} such pours"
    if "antecedent" in facts:
        return f"the weighted pours of {facts['antecedent']}"
    return ""
