"""What `pantarhei plan` prints: each plan in propositions and in numbers
(the parameter ranges it fixes, those left to the ordinary pour), the rule
and likelihood each goal rests on, the verification per goal, and the
search that found it; or the same as JSON."""
from __future__ import annotations

from pantarhei.theory.lexicon import load_vocabulary

ADDED = "added: a pour pours, unless a goal says otherwise"


def _goals_line(goals: list[str], added: list[str], given: list[str]) -> list[str]:
    out = [f"goals: {', '.join(goals)}" + (f"  given: {', '.join(given)}" if given else "")]
    if added:
        out.append(f"  ({', '.join(added)} {ADDED})")
    return out


def _pct(x: float) -> str:
    return f"{round(100 * x)}%"


def plan_lines(p, given: list[str], said, trial=None) -> list[str]:
    """One plan: its propositions, its numbers, what each goal rests on and
    its verification per goal (`trial`, None unverified)."""
    from pantarhei.bridge.reasoning.plan_numbers import fixed_ranges, ordinary_ranges

    vocab = load_vocabulary()
    L = []
    if not p.chosen:
        L.append("  nothing to choose: an ordinary pour with the given context")
    for c in p.chosen:
        L.append(f"  {c:26} {vocab.propositions[c].gloss}")
    if trial is not None:
        L.append(f"  verified: goals met in {trial.met} of {trial.simulated} simulations "
                 f"({trial.rate:.0%})" + (f", {trial.failed} failed" if trial.failed else "")
                 + _batches(trial))
        L.extend(_wrapped("  per goal, of every verifying pour: ",
                          [f"{g} {n} of {trial.simulated} ({trial.shares[g]:.0%})"
                           for g, n in trial.per_goal.items()], "    "))
    L.append("  the goals rest on:")
    for s in said:
        rule = f"rule {s.rule}" if s.rule else "no rule"
        like = "no likelihood recorded" if s.likelihood is None else f"likelihood {_pct(s.likelihood)}"
        L.append(f"    {s.goal:30} {rule}, {like} ({s.verdict})")
    L.append("  numbers, fixed by the plan:")
    for r in fixed_ranges(p.antecedent):
        L.append(f"    {r.words():42} {r.by}" + (" (given)" if r.by in given else ""))
    L.extend(_wrapped("  left to the ordinary pour: ",
                      [r.words() for r in ordinary_ranges(p.antecedent)], "    "))
    return L


def _batches(trial) -> str:
    """How a trial's pours came: the first batch, then the fresh ones
    confirming it."""
    if len(trial.batches) < 2:
        return ""
    first, confirming = trial.batches[:2]
    return (f": {first.met} of the first {first.simulated}, then {confirming.met} of "
            f"{confirming.simulated} fresh ones confirming it")


def _wrapped(first: str, items: list[str], indent: str, width: int = 100) -> list[str]:
    """`items` joined by commas after `first`, in lines of at most `width`
    characters, never breaking an item."""
    lines, line = [], first
    for i, item in enumerate(items):
        part = item + ("," if i < len(items) - 1 else "")
        if len(line) + len(part) > width and line.strip():
            lines.append(line.rstrip())
            line = indent
        line += part + " "
    lines.append(line.rstrip())
    return lines


def print_unverified(theory, goals, added, given, plans) -> None:
    from pantarhei.bridge.reasoning.plan_numbers import rests_on

    for line in _goals_line(goals, added, given):
        print(line)
    for i, p in enumerate(plans):
        n = len(p.chosen)
        print(f"{'best plan' if i == 0 else f'alternative {i}'} ({n} proposition"
              f"{'s' if n != 1 else ''}), not verified:")
        for line in plan_lines(p, given, rests_on(theory, p.antecedent, goals)):
            print(line)


def print_search(found, oracle: str, learned_out: str | None) -> None:
    for line in _goals_line(found.goals, found.added, found.given):
        print(line)
    kept = (f"written to {learned_out}" if learned_out else "not written: --learned-out FILE keeps them")
    from pantarhei.oracle.base import REAL_ORACLES

    where = oracle if oracle in REAL_ORACLES else f"{oracle}: analytic test scores, not a simulation"
    print(f"searched: {len(found.tried)} plan{'s' if len(found.tried) != 1 else ''} in "
          f"{found.rounds} round{'s' if found.rounds != 1 else ''}, {found.pours} of "
          f"{found.budget} pours ({where}); {found.learned} rules learned from them ({kept})")
    for t in found.tried:
        if not t.verified:
            print(f"  refuted: {', '.join(t.plan.chosen) or 'the context alone'} ({t.origin}, "
                  f"round {t.round}): every goal met in {t.met} of {t.simulated} pours"
                  + (_batches(t) + " (not confirmed)" if t.unconfirmed else "")
                  + (" (too few pours left to confirm it)" if t.short else "") + "; "
                  + ", ".join(f"{g} {n}" for g, n in t.per_goal.items()))
    for i, t in enumerate(found.verified):
        n = len(t.plan.chosen)
        where = "proposed by the theory" if t.origin == "theory" else "found searching the simulation"
        print(f"{'best plan' if i == 0 else f'alternative {i}'} ({n} proposition"
              f"{'s' if n != 1 else ''}), {where}:")
        for line in plan_lines(t.plan, found.given, t.said, t):
            print(line)


def plan_json(theory, goals, added, given, plans, found=None, oracle=None,
              learned_out=None) -> dict:
    """The plans as JSON: per plan its propositions, numbers, what each goal
    rests on and (verified) its pours per goal; with `found`, the search."""
    from pantarhei.bridge.reasoning.plan_numbers import fixed_ranges, ordinary_ranges, rests_on

    out = {"goals": goals, "added_goals": added, "given": given, "plans": []}
    for p, trial in plans:
        said = trial.said if trial is not None else rests_on(theory, p.antecedent, goals)
        entry = {"chosen": list(p.chosen), "antecedent": list(p.antecedent),
                 "fixes": [r.as_dict() for r in fixed_ranges(p.antecedent)],
                 "ordinary": [r.as_dict() for r in ordinary_ranges(p.antecedent)],
                 "rests_on": [s.as_dict() for s in said]}
        if trial is not None:
            entry["origin"] = trial.origin
            entry["verified"] = {"simulated": trial.simulated, "met": trial.met,
                                 "failed": trial.failed, "rate": round(trial.rate, 3),
                                 "per_goal": dict(trial.per_goal),
                                 "per_goal_share": {g: round(x, 3) for g, x in trial.shares.items()},
                                 "batches": [b.as_dict() for b in trial.batches]}
        out["plans"].append(entry)
    if found is not None:
        out["search"] = {"oracle": oracle, "pours": found.pours, "budget": found.budget,
                         "confirm": found.confirm,
                         "rounds": found.rounds, "learned_rules": found.learned,
                         "learned_out": learned_out, "unreachable": found.unreachable,
                         "tried": [t.as_dict() for t in found.tried]}
    return out
