"""Plan, verify, learn, plan again: search until a plan is verified.

A round asks the theory for plans (planning.py, clingo) it has not tried,
and verifies each in the simulation: its pours are sampled from its
antecedent (a seed of its own, from the run's seed and the antecedent, so
the same plan has the same pours in every run and the store simulates
them once), in steps, until its goals were met in `min_success` of
`verify` pours or can no longer be. A plan that passes is confirmed on
`confirm` fresh pours (a second seed of its own; as many as `verify`
unless told), drawn only after it was chosen: chosen among many for a
lucky first batch, it must meet its goals in `min_success` of all its
pours, pooled, or it is refuted like any other. When no plan of the round
is verified, the theory learns from the pours of the plans it refuted
(plan_evidence.py) and the next round plans with what it learned. Beside
the theory's plans (at most THEORY_PER_ROUND a round), and in their place
when it proposes nothing new (every plan it has was refuted, or it cannot
reach the goals at all), plans are searched in the simulation, one at a
time after the round's theory plans were verified: every manner
proposition alone with the given context, then the pairs of the best
singles, in plan_order.py's order (most promising first as the learned
theory predicts the goals; those it rates alike, as the pours seen so far
predict them). A plan is tried while the budget holds its first batch; one that
passes it when the budget cannot hold its confirming batch is not
verified, and the search ends there. The search ends with a verified plan, when the budget of pours is spent, or
when no candidate is left; it then says why no plan was found.
"""
from __future__ import annotations

import math
import zlib
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.plan_trials import Batch, Trial
from pantarhei.bridge.reasoning.planning import Plan, check_goals, goals_met, plan, pouring_goals
from pantarhei.bridge.theories.model import Theory

#: Plans verified per round: the theory's (at most THEORY_PER_ROUND), then
#: the search's.
PER_ROUND = 4
THEORY_PER_ROUND = 2


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
    #: the pours of a plan's confirming batch
    confirm: int = 0

    @property
    def verified(self) -> list[Trial]:
        return [t for t in self.tried if t.verified]


def pour_seed(seed: int, antecedent: Sequence[str], batch: int = 0) -> int:
    """The seed of a plan's verifying pours: the run's seed and the
    antecedent (and for the confirming batch, 1, a seed apart)."""
    key = [int(seed), zlib.crc32(" ".join(antecedent).encode())] + ([batch] if batch else [])
    return int(np.random.SeedSequence(key).generate_state(1)[0])


def passes(met: int, simulated: int, min_success: float) -> bool:
    """Does a plan whose goals were met in `met` of `simulated` pours meet
    the bar? The one criterion of a verified plan, for every batch."""
    return simulated > 0 and met >= min_success * simulated - 1e-9


def verify(p: Plan, goals: list[str], simulate: Callable, n: int, seed: int,
           min_success: float, trial: Trial, confirm: int | None = None,
           room: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Simulate the plan's pours in steps until its goals were met in
    `min_success` of `n` or can no longer be; if they were, confirm it on
    `confirm` fresh pours (n when None; 0: not confirmed) in steps, until
    its goals were met in `min_success` of all its pours, pooled, or can
    no longer be; with fewer than the two batches' pours left in `room`
    (None: no bound), a plan that passes its first batch is left
    unconfirmed, and not verified. Fill in `trial` (pooled over both batches); the pours
    simulated and their scores. Each batch's pours are the first of one
    seeded sample, so that a plan verified to the end has the same pours
    however it was stepped."""
    confirm = n if confirm is None else confirm
    batches = [("first", n, 0)] + ([("confirming", confirm, 1)] if confirm else [])
    Ps, Ss, tally = [], [], []
    total = misses = 0
    for kind, size, batch in batches:
        if room is not None and total + size > room:
            trial.short = True
            break
        P, S, missed = _batch(p.antecedent, goals, simulate, size, pour_seed(seed, p.antecedent, batch),
                              total + size, misses, min_success)
        Ps.append(P)
        Ss.append(S)
        ok = np.all(np.isfinite(S), axis=1)
        tally.append(Batch(kind, int(ok.sum()), int(goals_met(S[ok], goals).sum()) if ok.any() else 0))
        total, misses = total + size, missed
        if len(P) < size or not passes(sum(b.met for b in tally), sum(b.simulated for b in tally),
                                       min_success):
            break
    P, S = np.vstack(Ps), np.vstack(Ss)
    ok = np.all(np.isfinite(S), axis=1)
    trial.batches = tally
    trial.simulated, trial.failed = int(ok.sum()), int((~ok).sum())
    trial.met = int(goals_met(S[ok], goals).sum()) if ok.any() else 0
    trial.per_goal = {g: int(goals_met(S[ok], [g]).sum()) if ok.any() else 0 for g in goals}
    trial.verified = len(tally) == len(batches) and len(P) == total \
        and passes(trial.met, trial.simulated, min_success)
    return P, S


def _batch(antecedent: Sequence[str], goals: list[str], simulate: Callable, size: int, seed: int,
           total: int, misses: int, min_success: float) -> tuple[np.ndarray, np.ndarray, int]:
    """One batch of `size` pours, in steps, stopped once the misses so far
    (`misses` before it) are more than `total` pours may have and still
    meet the bar; its pours, scores and the misses after it. Each step is
    the fewest pours that could refute the plan (two at the least), so a
    plan that misses from the start costs few pours."""
    from pantarhei.oracle.generative import sample

    P = sample(list(antecedent), size, seed)
    allowed = total - math.ceil(min_success * total - 1e-9)      # misses that still verify
    Ps, Ss = [], []
    done = 0
    while done < size:
        rows = P[done:done + max(2, allowed - misses + 1)]
        S = np.atleast_2d(np.asarray(simulate(rows), dtype=float))
        Ps.append(rows)
        Ss.append(S)
        done += len(rows)
        ok = np.all(np.isfinite(S), axis=1)
        misses += int((ok & ~goals_met(S, goals)).sum())
        if misses > allowed:
            break
    return np.vstack(Ps), np.vstack(Ss), misses


def search(theory: Theory, goals: Sequence[str], given: Sequence[str], simulate: Callable, *,
           verify_pours: int, min_success: float, seed: int, budget: int, want: int = 1,
           pour: bool = True, learn: bool = True, explore: bool = True,
           use_theory: bool = True, confirm: int | None = None) -> Search:
    """Search for `want` plans reaching `goals` given `given` (see the
    module's text) within `budget` pours, each verified with `verify_pours`
    and confirmed with `confirm` more (None: as many); `pour`: add the goal that the
    liquid leaves the source unless a goal speaks of it; `learn`: learn
    from refuted plans; `explore`: search manners in the simulation when
    the theory proposes none; `use_theory` False: search the simulation
    alone (the manners alone and in pairs, ordered as the theory predicts).
    UserError for an unknown goal or invalid context."""
    from pantarhei.bridge.reasoning.plan_evidence import planned_rules, theory_learner, with_rules
    from pantarhei.bridge.reasoning.plan_numbers import rests_on
    from pantarhei.bridge.reasoning.plan_order import next_plan, ranked_singles
    from pantarhei.bridge.reasoning.valid_scenes import require_valid

    lits, added = pouring_goals(list(goals)) if pour else ([*map(_literal, goals)], [])
    given = require_valid(given) if given else []
    confirm = verify_pours if confirm is None else confirm
    out = Search(lits, added, given, budget=budget, theory=theory, confirm=confirm)
    # the theory plans for the goals it has rules for among those added
    asked = [g for g in lits if g not in added or _concludes(theory, g)]
    current, planned = theory, []
    learner = theory_learner(theory)
    singles: list[tuple[float, tuple[str, ...]]] | None = None
    seen: list[tuple[np.ndarray, np.ndarray]] = []       # every pour verified, for plan_order
    while True:
        tried = {t.plan.chosen for t in out.tried}
        theirs: list[Plan] = []
        try:
            if use_theory:
                theirs = _proposals(current, asked, given, tried)[:THEORY_PER_ROUND]
        except UserError as e:
            if out.rounds == 0:
                out.unreachable = str(e)
        searching = explore and len(theirs) < PER_ROUND
        if searching and (singles is None or learn):
            singles = ranked_singles(current, lits, given)

        def following(k: int) -> tuple[str, Plan] | None:
            """The round's k-th plan: the theory's, then the search's most
            promising untried one, ranked with every pour seen so far."""
            if k < len(theirs):
                return "theory", theirs[k]
            if not searching or k >= PER_ROUND:
                return None
            p = next_plan(given, singles, lits, seen, out.tried, {q.chosen for q in theirs})
            return None if p is None else ("search", p)

        step = following(0)
        if step is None:
            break
        out.rounds += 1
        spent = False
        k = 0
        while step is not None:
            origin, p = step
            if out.pours + verify_pours > budget:
                spent = True
                break
            trial = Trial(p, origin, out.rounds, said=rests_on(current, p.antecedent, lits))
            P, S = verify(p, lits, simulate, verify_pours, seed, min_success, trial, confirm,
                          room=budget - out.pours)
            out.tried.append(trial)
            out.pours += len(P)
            seen.append((P, S))
            if learn:
                planned.append(planned_rules(len(out.tried) - 1, p.antecedent, P, S, seed,
                                             learner))
            if len(out.verified) >= want:
                break
            if trial.short:          # no plan could be confirmed now
                spent = True
                break
            k += 1
            step = following(k)
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


def _why_none(out: Search, min_success: float, n: int) -> str:
    """Why no plan was found, in one line."""
    short = next((t for t in out.tried if t.short), None)
    if short is not None:       # passed its first pours, with no pours left to confirm it
        return (f"the budget of {out.budget} pours is spent: "
                f"{', '.join(short.plan.chosen) or 'the context alone'} met the goals in "
                f"{short.met} of {short.simulated} pours, too few pours were left to confirm it on "
                f"{out.confirm} fresh ones (more --pours would), and none of the "
                f"{len(out.tried) - 1} other plans tried met them in "
                f"{_bar(min_success, n, out.confirm)}")
    best = max(out.tried, key=lambda t: (t.rate, -len(t.plan.chosen)), default=None)
    seen = "" if best is None else (
        f"; the best, {', '.join(best.plan.chosen) or 'the context alone'}, met them in "
        + (f"{best.batches[0].met} of {best.batches[0].simulated}, then in {best.batches[1].met} "
           f"of {best.batches[1].simulated} fresh pours confirming it"
           if best.unconfirmed else f"{best.met} of {best.simulated}"))
    spent = out.pours + n > out.budget
    why = (f"the budget of {out.budget} pours is spent" if spent else "no candidate is left")
    if out.unreachable and not any(t.origin == "theory" for t in out.tried):
        head = f"unreachable in the theory ({out.unreachable})"
        if not out.tried:
            return head
        return (f"{head}, and none of the {len(out.tried)} plans searched in the simulation met "
                f"the goals in {_bar(min_success, n, out.confirm)} ({why}){seen}")
    return (f"every candidate refuted: none of the {len(out.tried)} plans tried met the goals in "
            f"{_bar(min_success, n, out.confirm)} ({why}){seen}")


def _bar(min_success: float, n: int, confirm: int) -> str:
    """The bar a verified plan meets, in words."""
    if not confirm:
        return f"{min_success:.0%} of {n} pours"
    return f"{min_success:.0%} of {n} pours and of {n + confirm} with {confirm} fresh ones"
