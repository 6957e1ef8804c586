"""The report's section on the general theory: the shipped theory, the
general rules alone, gradient boosting and the defaults-only theory on the
questions a person would ask; each question as the shipped theory answers
it; the general rules learned from curiosity's pours, in words."""
from __future__ import annotations

from pathlib import Path

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import antecedent_words, num, pct
from pantarhei.bridge.evaluation.measures import question_misses
from pantarhei.bridge.learning.general_rules import likelihood

_INTRODUCTION = (
    "General rules are learned from every pour of the exploration and from the learner's "
    "own pours for the ordinary pour and each proposition alone (`bridge/learning/`): a "
    "default per expectation and the contrasts that move it, each with the likelihood of "
    "its head. The shipped theory holds them beside Algorithm 1's rules. Each theory or "
    "model below is asked the questions of `bridge/evaluation/questions.json` "
    "({}: one-phrase questions, then real pours that vary one or two "
    "aspects of the ordinary pour), whose key is the majority of 20 pours sampled for the "
    "question. *clear*: keys where at least 75% of the pours agree. *contrast*: the clear "
    "keys where the defaults-only theory (one verdict per expectation, the majority of all "
    "pours learned from) is wrong. *calibration*: the mean absolute difference between "
    "the likelihood stated and the share of the question's pours, over every key. "
    "*coherent*: the questions whose decided verdicts, taken together, one of their own "
    "pours shows. *boosting*: gradient boosting of the same pours on the 30 parameters, "
    "averaged over each question's meaning: the ceiling of what the pours support. "
    "*uniform*: uniformly random held-out scenes, one pour each.")


def general_section(ev: Evaluation, out: Path) -> list[str]:
    """The report's section on the general theory."""
    g = ev.general
    if not g:
        return []
    return _models(g) + _questions(g) + _rules(g) + [""]


def _models(g: dict) -> list[str]:
    """Each theory or model on the questions and on uniform scenes."""
    L = ["## The general theory, asked what a person would ask", "",
         _INTRODUCTION.format(len(g["questions"])), "",
         "| theory or model | pours | clear: coverage | clear: accuracy | contrast: accuracy "
         "(coverage) | calibration | coherent | uniform: accuracy (coverage) |",
         "|---|---|---|---|---|---|---|---|"]

    def row(label: str, pours: str, e: dict) -> str:
        q, u = e["questions"], e.get("uniform")
        held = f"{pct(u['accuracy'])} ({pct(u['coverage'])})" if u else "-"
        return (f"| {label} | {pours} | {pct(q['coverage'])} | {pct(q['accuracy'])} | "
                f"{pct(q['contrast_accuracy'])} ({pct(q['contrast_coverage'])}) | "
                f"{num(q['calibration'])} | {pct(q['coherent'])} | {held} |")

    L.append(row(f"the shipped theory (both layers, {g['shipped']['general_rules']} general rules)",
                 "curiosity", g["shipped"]))
    for method in ("curiosity", "random"):
        e = g[method]
        L.append(row(f"general rules alone ({e['rules_per_expectation']:.1f} per expectation)",
                     f"{method} ({e['pours']})", e))
        L.append(row("gradient boosting", method, e["boosting"]))
        L.append(row("defaults only", method, e["defaults"]))
    return L


def _questions(g: dict) -> list[str]:
    """Each question as the shipped theory answers it: the clear keys it
    gets wrong or leaves open."""
    names = load_vocabulary().expectation_names
    q = g["shipped"]["questions"]
    L = ["", f"{q['contrast']} of the {q['clear']} clear keys are contrast keys.", "",
         "The questions, as the shipped theory answers them (the clear keys it gets wrong or "
         "leaves open are named; a contrast key is marked *):", "",
         "| question | clear | contrast | wrong | undecided |", "|---|---|---|---|---|"]
    ans, key, clear = g["shipped"]["answers"], g["key"], g["clear"]
    contrast = g.get("contrast", [[0] * len(names)] * len(clear))

    def named(ks: list[int], i: int) -> str:
        return ", ".join(names[k] + ("*" if contrast[i][k] else "") for k in ks) or "-"

    for i, (qq, (wrong, open_)) in enumerate(zip(g["questions"], question_misses(ans, key, clear))):
        L.append(f"| {qq['text']} | {sum(clear[i])} | {sum(contrast[i])} | {named(wrong, i)} | "
                 f"{named(open_, i)} |")
    return L


def _rules(g: dict) -> list[str]:
    """The general rules learned from curiosity's pours, in words."""
    L = ["", "The general rules learned from curiosity's pours (likelihood: the share of the "
         "body's pours, the rest an ordinary pour, in which the expectation holds; seen: of "
         "the pours learned from that could have been drawn for the body, how many kept the "
         "head):", "",
         "| rule | when | then | likelihood | seen |", "|---|---|---|---|---|"]
    for r in g["curiosity"]["rules"]:
        when = antecedent_words(r["body"]) if r["body"] else "(an ordinary pour)"
        holds = not r["head"].startswith("neg(")
        lik = likelihood(holds, r["confidence"])
        L.append(f"| `{r['id']}` | {when} | `{r['head']}` | {lik:.2f} | "
                 f"{r['kept']} of {r['support']} |")
    return L
