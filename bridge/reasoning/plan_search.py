"""Plan, verify, learn, plan again: search until a plan is verified.

A round asks the theory for plans (planning.py, clingo) it has not tried,
and verifies each in the simulation: its pours are sampled from its
antecedent (a seed of its own, from the run's seed and the antecedent, so
the same plan has the same pours in every run and the store simulates
them once), in steps, until its goals were met in `min_success` of
`verify` pours or can no longer be. When no plan of the round is
verified, the theory learns from the pours of the plans it refuted
(plan_evidence.py) and the next round plans with what it learned. Beside
the theory's plans (at most THEORY_PER_ROUND a round), and in their place
when it proposes nothing new (every plan it has was refuted, or it cannot
reach the goals at all), plans are searched in the simulation: every
manner proposition alone with the given context, then the pairs of the
most promising, most promising first (as the learned theory predicts the
goals). The search ends with a verified plan, when the budget of pours is
spent, or when no candidate is left; it then says why no plan was found.
"""
from __future__ import annotations

import math
import zlib
from dataclasses import dataclass, field
from itertools import combinations
from typing import Callable, Sequence

import numpy as np

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.planning import Plan, check_goals, goals_met, plan, pouring_goals
from pantarhei.bridge.theories.model import Theory, complement

#: Plans verified per round: the theory's (at most THEORY_PER_ROUND), then
#: the search's.
PER_ROUND = 4
THEORY_PER_ROUND = 2
#: The singles whose pairs the search tries.
PAIRED = 8


@dataclass
class Trial:
    """A plan verified in the simulation: where it came from (the theory
    or the search), the round, its pours and how many met every goal, and
    each goal's count."""
    plan: Plan
    origin: str
    round: int
    simulated: int = 0
    failed: int = 0
    met: int = 0
    per_goal: dict[str, int] = field(default_factory=dict)
    verified: bool = False
    #: what the theory of its round said of each goal in its scene (plan_numbers.Support)
    said: list = field(default_factory=list)

    @property
    def rate(self) -> float:
        return self.met / self.simulated if self.simulated else 0.0

    def as_dict(self) -> dict:
        return {"chosen": list(self.plan.chosen), "antecedent": list(self.plan.antecedent),
                "origin": self.origin, "round": self.round, "simulated": self.simulated,
                "failed": self.failed, "met": self.met, "rate": round(self.rate, 3),
                "per_goal": dict(self.per_goal), "verified": self.verified,
                "rests_on": [x.as_dict() for x in self.said]}


@dataclass
class Search:
    """What a search found: the goals (with those added, a pour pours), the
    given context, every plan tried in order, the verified ones, the pours
    simulated of the budget, the rounds, the theory it leaves (the one
    given with the rules learned from the pours), why the theory could not
    reach the goals (None: it could), and why no plan was found (None: one
    was)."""
    goals: list[str]
    added: list[str]
    given: list[str]
    tried: list[Trial] = field(default_factory=list)
    pours: int = 0
    budget: int = 0
    rounds: int = 0
    theory: Theory | None = None
    learned: int = 0
    unreachable: str | None = None
    reason: str | None = None

    @property
    def verified(self) -> list[Trial]:
        return [t for t in self.tried if t.verified]


def pour_seed(seed: int, antecedent: Sequence[str]) -> int:
    """The seed of a plan's verifying pours: the run's seed and the
    antecedent."""
    return int(np.random.SeedSequence([int(seed), zlib.crc32(" ".join(antecedent).encode())])
               .generate_state(1)[0])


def verify(p: Plan, goals: list[str], simulate: Callable, n: int, seed: int,
           min_success: float, trial: Trial) -> tuple[np.ndarray, np.ndarray]:
    """Simulate the plan's pours in steps until its goals were met in
    `min_success` of `n` or can no longer be; fill in `trial`; the pours
    simulated and their scores. The pours are the first of one seeded
    sample, so that a plan verified to the end has the same pours however
    it was stepped."""
    from pantarhei.oracle.generative import sample

    P = sample(list(p.antecedent), n, pour_seed(seed, p.antecedent))
    allowed = n - math.ceil(min_success * n - 1e-9)      # misses that still verify
    step = max(2, math.ceil(n / 3))
    Ps, Ss = [], []
    done = misses = 0
    while done < n:
        rows = P[done:done + step]
        S = np.atleast_2d(np.asarray(simulate(rows), dtype=float))
        Ps.append(rows)
        Ss.append(S)
        done += len(rows)
        ok = np.all(np.isfinite(S), axis=1)
        misses += int((ok & ~goals_met(S, goals)).sum())
        if misses > allowed:
            break
    P, S = np.vstack(Ps), np.vstack(Ss)
    ok = np.all(np.isfinite(S), axis=1)
    trial.simulated, trial.failed = int(ok.sum()), int((~ok).sum())
    trial.met = int(goals_met(S[ok], goals).sum()) if ok.any() else 0
    trial.per_goal = {g: int(goals_met(S[ok], [g]).sum()) if ok.any() else 0 for g in goals}
    trial.verified = done >= n and trial.simulated > 0 and trial.rate >= min_success - 1e-9
    return P, S


def search(theory: Theory, goals: Sequence[str], given: Sequence[str], simulate: Callable, *,
           verify_pours: int, min_success: float, seed: int, budget: int, want: int = 1,
           pour: bool = True, learn: bool = True, explore: bool = True,
           use_theory: bool = True) -> Search:
    """Search for `want` plans reaching `goals` given `given` (see the
    module's text) within `budget` pours; `pour`: add the goal that the
    liquid leaves the source unless a goal speaks of it; `learn`: learn
    from refuted plans; `explore`: search manners in the simulation when
    the theory proposes none; `use_theory` False: search the simulation
    alone (the manners alone and in pairs, ordered as the theory predicts).
    UserError for an unknown goal or invalid context."""
    from pantarhei.bridge.reasoning.plan_evidence import planned_rules, with_rules
    from pantarhei.bridge.reasoning.plan_numbers import rests_on
    from pantarhei.bridge.reasoning.scenes import require_valid

    lits, added = pouring_goals(list(goals)) if pour else ([*map(_literal, goals)], [])
    given = require_valid(given) if given else []
    out = Search(lits, added, given, budget=budget, theory=theory)
    # the theory plans for the goals it has rules for among those added
    asked = [g for g in lits if g not in added or _concludes(theory, g)]
    current, planned = theory, []
    pool: list[Plan] | None = None
    while True:
        tried = {t.plan.chosen for t in out.tried}
        proposed: list[tuple[str, Plan]] = []
        try:
            if use_theory:
                proposed = [("theory", p) for p in _proposals(current, asked, given, tried)]
        except UserError as e:
            if out.rounds == 0:
                out.unreachable = str(e)
        proposed = proposed[:THEORY_PER_ROUND]
        if explore and len(proposed) < PER_ROUND:
            if pool is None or learn:
                pool = _candidates(current, lits, given)
            theirs = {p.chosen for _, p in proposed}
            proposed += [("search", p) for p in pool if p.chosen not in tried
                         and p.chosen not in theirs][:PER_ROUND - len(proposed)]
        if not proposed:
            break
        out.rounds += 1
        spent = False
        for origin, p in proposed:
            if out.pours + verify_pours > budget:
                spent = True
                break
            trial = Trial(p, origin, out.rounds, said=rests_on(current, p.antecedent, lits))
            P, S = verify(p, lits, simulate, verify_pours, seed, min_success, trial)
            out.tried.append(trial)
            out.pours += len(P)
            if learn:
                planned.append(planned_rules(len(out.tried) - 1, p.antecedent, P, S, seed))
            if len(out.verified) >= want:
                break
        if len(out.verified) >= want or spent:
            break
        if learn:
            current = with_rules(theory, planned)
    if learn and out.tried:
        out.theory = with_rules(theory, planned)
        out.learned = len(out.theory.rules) - len(theory.rules)
    if not out.verified:
        out.reason = _why_none(out, min_success, verify_pours)
    return out


def _literal(g: str) -> str:
    from pantarhei.bridge.reasoning.literals import goal_literal

    return goal_literal(g)


def _concludes(theory: Theory, lit: str) -> bool:
    return lit in theory.facts or any(r.head == lit and r.kind != "defeater" for r in theory.rules)


def _proposals(theory: Theory, goals: list[str], given: list[str], tried: set) -> list[Plan]:
    """Up to PER_ROUND plans of the theory not tried yet (UserError when the
    theory cannot reach the goals)."""
    check_goals(goals, theory)
    return plan(theory, goals, given, PER_ROUND - 1, exclude=sorted(tried))


def _candidates(theory: Theory, goals: list[str], given: list[str]) -> list[Plan]:
    """Every manner proposition alone with the given context, then the pairs
    of the PAIRED most promising, each valid; most promising first (the
    theory's likelihoods of the goals multiplied; an undecided goal one
    half), then in the vocabulary's order."""
    from pantarhei.bridge.reasoning.answers import what_happens
    from pantarhei.bridge.reasoning.scenes import violations

    vocab = load_vocabulary()
    taken = {vocab.propositions[p].dimension for p in given}
    manners = [p for p, x in vocab.propositions.items()
               if vocab.dimensions[x.dimension].role == "manner" and x.dimension not in taken]

    def score(chosen: tuple[str, ...]) -> float:
        said = {a.expectation: a.likelihood for a in what_happens(theory, [*given, *chosen])}
        s = 1.0
        for g in goals:
            negated = g.startswith("neg(")
            like = said.get(complement(g) if negated else g)
            s *= 0.5 if like is None else (1 - like if negated else like)
        return s

    singles = [(p,) for p in manners if not violations([*given, p])]
    scored = sorted(((-score(c), i, c) for i, c in enumerate(singles)))
    top = [c[0] for _, _, c in scored[:PAIRED]]
    pairs = [tuple(sorted(pair)) for pair in combinations(top, 2) if not violations([*given, *pair])]
    scored_pairs = sorted(((-score(c), i, c) for i, c in enumerate(pairs)))
    return [Plan(c, tuple(sorted([*given, *c]))) for _, _, c in [*scored, *scored_pairs]]


def _why_none(out: Search, min_success: float, n: int) -> str:
    """Why no plan was found, in one line."""
    best = max(out.tried, key=lambda t: (t.rate, -len(t.plan.chosen)), default=None)
    seen = "" if best is None else (
        f"; the best, {', '.join(best.plan.chosen) or 'the context alone'}, met them in "
        f"{best.met} of {best.simulated}")
    spent = out.pours + n > out.budget
    why = (f"the budget of {out.budget} pours is spent" if spent else "no candidate is left")
    if out.unreachable and not any(t.origin == "theory" for t in out.tried):
        head = f"unreachable in the theory ({out.unreachable})"
        if not out.tried:
            return head
        return (f"{head}, and none of the {len(out.tried)} plans searched in the simulation met "
                f"the goals in {min_success:.0%} of {n} pours ({why}){seen}")
    return (f"every candidate refuted: none of the {len(out.tried)} plans tried met the goals in "
            f"{min_success:.0%} of {n} pours ({why}){seen}")
