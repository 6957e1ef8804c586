"""Answers to questions about pouring: what happens in a scene (one answer
per expectation, with the deciding rule), why or why not, and the deciding
rule in words with its evidence.

The answers and the deciding rule's words are SWI-Prolog's
(theory/ask.pl); this module asks them of a theory held in Python.

A question means what `pantarhei simulate --antecedent Q` samples for it:
whatever it leaves unsaid follows the priors (the ordinary pour). Nothing
is added to it: the general rules (bridge/learning/) answer questions of
any length in that meaning, each with the likelihood that the expectation
holds in such pours."""
from __future__ import annotations

from pantarhei.bridge.engines.swipl import text as prolog_text
from pantarhei.bridge.reasoning.asking import Answer, answer_of
from pantarhei.bridge.reasoning.logic import Semantics, prolog_load
from pantarhei.bridge.theories.model import Theory


def what_happens(theory: Theory, props: list[str],
                 semantics: Semantics = Semantics()) -> list[Answer]:
    """The prediction for a scene: one Answer per expectation, with the
    rule to name, why in one line, and for an undecided one the brief
    why-not (theory/ask.pl's answers/3, in this process's SWI-Prolog)."""
    e = prolog_load(theory)
    e.use_module("ask")
    goal = (f"ask:answers(Scene, {semantics.options()}, As), "
            "findall(S, (member(answer(E, V, P, R, B, T, Ev), As), "
            "ask:evidence_fields(Ev, H, O, Bd, U, X, C), "
            "format(string(S), '~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w\\t~w', "
            "[E, V, P, R, B, T, H, O, Bd, U, X, C])), Ss)")
    r = e.once(goal, Scene=list(props))
    return [answer_of(prolog_text(line).split("\t")) for line in r["Ss"]]


class InProcess:
    """A theory asked in this process (what `pantarhei ask` asks through
    its door, bridge/reasoning/asking.py): for a theory built in Python."""

    def __init__(self, theory: Theory) -> None:
        self.theory = theory
        self.source = theory.source

    def answers(self, scene: list[str]) -> list[Answer]:
        return what_happens(self.theory, scene)

    def why(self, scene: list[str], literal: str) -> str:
        return explain(self.theory, scene, literal)


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
