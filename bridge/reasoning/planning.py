"""Plan a pour: manners that make the theory conclude the goals (clingo).

theory/manners.lp chooses manner propositions (poses, tilts, speeds) that,
with the given context, form a valid antecedent from which the theory
defeasibly concludes every goal literal. Plans come cheapest first (fewest
chosen propositions) among those whose goals rest on the most confident
rules (the sum over the goals of the largest confidence of a rule for the
goal that applies); each further plan is the best one that does not
merely add propositions to a plan already found. Verifying plans in the
simulation, learning from those refuted and planning again is
plan_search.py.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from pantarhei.theory.lexicon import load_vocabulary
from pantarhei.theory import THEORY_DIR, VOCABULARY_FILES

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.theories.model import Theory, complement
from pantarhei.bridge.reasoning.literals import goal_literal, parse_goal
from pantarhei.bridge.reasoning.valid_scenes import require_valid

ENCODINGS = ("derivability.lp", "violations.lp", "valid.lp", "manners.lp")
MAX_STEPS = 64


@dataclass(frozen=True)
class Plan:
    chosen: tuple[str, ...]      # the manner propositions the plan adds
    antecedent: tuple[str, ...]  # given + chosen, sorted


def goals_met(scores, goals: list[str]):
    """Per row of oracle scores (n x 9): whether every goal literal was met
    (an expectation's verdict holds, bridge/verdicts.py's verdicts, or for neg(E) fails)."""
    import numpy as np

    from pantarhei.bridge.verdicts import verdicts

    names = load_vocabulary().expectation_names
    scores = np.atleast_2d(np.asarray(scores, dtype=float))
    met = np.all(np.isfinite(scores), axis=1)
    for g in goals:
        lit = parse_goal(g)
        negated = lit.startswith("neg(")
        col = names.index(complement(lit) if negated else lit)
        holds = verdicts(scores[:, col])
        met &= ~holds if negated else holds
    return met


def plan_defaults() -> tuple[int, float, int]:
    """The defaults of plans (theory/defaults.pl): the pours a plan is
    verified with (and confirmed with), the share of them that must meet
    every goal, and the pours a search may simulate."""
    from pantarhei.theory import defaults

    d = defaults()
    return int(d["plan_verify"]), float(d["plan_min_success"]), int(d["plan_pours"])


#: The goal a pour has unless a goal says otherwise: the liquid leaves the source.
POURS = "liquid_leaves_source"


def pouring_goals(goals: list[str]) -> tuple[list[str], list[str]]:
    """The goal literals of "how should I pour so that ...", with the
    liquid leaving the source added where no goal speaks of it (a goal of
    liquid_leaves_source or its negation says otherwise): a pour pours.
    Returns the goals and those added."""
    lits = [goal_literal(g) for g in goals]
    if POURS in lits or complement(POURS) in lits:
        return lits, []
    return lits + [POURS], [POURS]


def check_goals(goals: list[str], theory: Theory, reachable: bool = True) -> list[str]:
    """The goal literals; UserError for an unknown expectation, or for a
    goal literal that no rule of the theory can conclude."""
    out = []
    for g in goals:
        lit = goal_literal(g)
        if reachable and lit not in theory.facts and not any(r.head == lit and r.kind != "defeater"
                                               for r in theory.rules):
            raise UserError(f"unreachable goal: no rule of {theory.source} concludes {lit}")
        out.append(lit)
    return out


def plan(theory: Theory, goals: list[str], given: list[str] = (), alternatives: int = 5,
         exclude: Sequence[Sequence[str]] = ()) -> list[Plan]:
    """Plans for the goals, cheapest first (at most 1 + alternatives), none
    of whose chosen propositions are exactly a set of `exclude` (an empty
    list when only those reach the goals). UserError if no valid choice of
    manners reaches them, naming the goal."""
    goals = check_goals(list(goals), theory)
    given = require_valid(given) if given else []
    plans = _solve(theory, goals, given, 1 + alternatives, exclude=exclude)
    if plans or (exclude and _solve(theory, goals, given, 1)):
        return plans
    for g in goals:    # which goal cannot be reached even alone?
        if not _solve(theory, [g], given, 1):
            ctx = f" given {', '.join(given)}" if given else ""
            raise UserError(f"unreachable goal: no valid choice of manners makes the theory "
                            f"conclude {g}{ctx}")
    ctx = f" given {', '.join(given)}" if given else ""
    raise UserError(f"unreachable goals: each of {', '.join(goals)} can be reached, but no valid "
                    f"choice of manners reaches them together{ctx}")


def relevant(theory: Theory, goals: list[str]) -> Theory:
    """The part of the theory the goals depend on: the rules for each goal
    literal and its complement, and so on for their bodies. Conclusions
    about the goals are the same as in the whole theory."""
    wanted, todo = set(), list(goals)
    by_head: dict[str, list] = {}
    for r in theory.rules:
        by_head.setdefault(r.head, []).append(r)
    while todo:
        lit = todo.pop()
        if lit in wanted:
            continue
        wanted.update((lit, complement(lit)))
        for head in (lit, complement(lit)):
            for r in by_head.get(head, ()):
                todo.extend(b for b in r.body if b not in wanted)
    rules = [r for r in theory.rules if r.head in wanted]
    ids = {r.id for r in rules}
    return Theory(list(theory.facts), rules, [(a, b) for a, b in theory.sup if a in ids and b in ids],
                  theory.learned & ids, source=theory.source,
                  provenance=[p for p in theory.provenance
                              if p[0] in ids and p[1] == "confidence_permille"])


def _excluded(chosen: Sequence[str]) -> str:
    """An ASP constraint against choosing exactly the propositions `chosen`."""
    body = "".join(f"chosen({p}), " for p in chosen)
    return f":- {body}#count {{ P : chosen(P) }} = {len(chosen)}."


def _solve(theory: Theory, goals: list[str], given: list[str], count: int,
           steps: int = 4, exclude: Sequence[Sequence[str]] = ()) -> list[Plan]:
    """Up to `count` plans; the alternation steps double until the models
    found have converged (more steps only make more goals provable)."""
    import clingo

    theory = relevant(theory, goals)
    acyclic = theory.acyclic()
    if acyclic:
        steps = 0
    while True:
        ctl = clingo.Control(["--warn=none", f"-csteps={steps}", f"-cacyclic={str(acyclic).lower()}",
                              "--opt-mode=opt"])
        for f in VOCABULARY_FILES:
            ctl.load(str(f))
        for e in ENCODINGS:
            ctl.load(str(THEORY_DIR / e))
        facts = theory.encoded() + "".join(f"goal({g})." for g in goals) \
            + "".join(f"context({p})." for p in given) + "".join(_excluded(c) for c in exclude)
        ctl.add("base", [], facts)
        ctl.ground([("base", [])])
        plans: list[Plan] = []
        unconverged = False
        for i in range(count):
            best: list | None = None
            with ctl.solve(yield_=True) as handle:
                for model in handle:
                    best = list(model.symbols(shown=True))
            if best is None:
                break
            if any(s.name == "changed" for s in best):
                unconverged = True
                break
            chosen = tuple(sorted(str(s.arguments[0]) for s in best if s.name == "chosen"))
            antecedent = tuple(sorted(str(s.arguments[0]) for s in best if s.name == "in"))
            plans.append(Plan(chosen, antecedent))
            # next: no plan that only adds to this one
            name = f"forbid{i}"
            body = ", ".join(f"chosen({p})" for p in chosen)
            ctl.add(name, [], f":- {body}." if chosen else ":- #true.")
            ctl.ground([(name, [])])
        if not acyclic and (unconverged or not plans) and steps < MAX_STEPS:
            steps *= 2
            continue
        return plans
